#pragma once
// One number printed by a printf format, as a string (report tables, reason sentences).
#include <cmath>
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

/// As comparedPair, `limit` a number a user gave: with at least the decimals it was given with
/// (up to 6), so that 0.6225 is not shown as 0.623.
inline std::pair<std::string, std::string> limitPair(double value, double limit, int digits = 3) {
    while (digits < 6 && std::abs(std::round(limit * std::pow(10.0, digits)) - limit * std::pow(10.0, digits)) > 1e-6)
        ++digits;
    return comparedPair(value, limit, digits);
}

}  // namespace projsurf
