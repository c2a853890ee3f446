#pragma once
// Floating-point -> int conversions defined for every input (C++ leaves the cast undefined
// for NaN, infinities and values out of range): clamp into [lo, hi] first, then convert.
#include <cstdint>

namespace projsurf {

/// `v` clamped into [lo, hi] and truncated toward zero like static_cast; NaN gives `lo`.
inline int clampToInt(double v, int lo, int hi) {
    if (!(v >= lo)) return lo;  // NaN lands here too
    if (v >= hi) return hi;
    return static_cast<int>(v);
}

/// The same for 64-bit results.
inline std::int64_t clampToInt64(double v, std::int64_t lo, std::int64_t hi) {
    if (!(v >= static_cast<double>(lo))) return lo;
    if (v >= static_cast<double>(hi)) return hi;
    return static_cast<std::int64_t>(v);
}

}  // namespace projsurf
