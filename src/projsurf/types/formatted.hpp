#pragma once
// One number printed by a printf format, as a string (report tables, reason sentences).
#include <cstdio>
#include <string>
#include <utility>

namespace projsurf {

/// `format` holds one double conversion (e.g. "%.2f m").
inline std::string formatted(const char *format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

/// Two numbers a sentence compares, with `digits` decimals or as many more (up to 9) as it
/// takes for different values to print differently: never "0.150 narrower than 0.150".
inline std::pair<std::string, std::string> comparedPair(double a, double b, int digits = 3) {
    char x[64], y[64];
    for (int d = digits;; ++d) {
        std::snprintf(x, sizeof x, "%.*f", d, a);
        std::snprintf(y, sizeof y, "%.*f", d, b);
        if (a == b || std::string(x) != y || d >= 9) return {x, y};
    }
}

}  // namespace projsurf
