#pragma once
// One number printed by a printf format, as a string (report tables, reason sentences).
#include <cstdio>
#include <string>

namespace projsurf {

/// `format` holds one double conversion (e.g. "%.2f m").
inline std::string formatted(const char *format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace projsurf
