#pragma once
// Per-stage timing of a detection (timing_ms: one key per stage, and "total").
#include <chrono>
#include <string>

#include "projsurf/detection/detection.hpp"

namespace projsurf {

class StageTimer {
public:
    explicit StageTimer(Detection &detection) : detection_(detection) {}
    /// Adds the time since the last lap (or the start) to `stage`.
    void lap(const char *stage) {
        const auto now = Clock::now();
        detection_.timing_ms[stage] += ms(lap_, now);
        lap_ = now;
    }
    /// Sets "total"; the detection is returned as it is.
    Detection &finish() {
        detection_.timing_ms["total"] = ms(start_, Clock::now());
        return detection_;
    }
    /// Not found, for `reason`.
    Detection &fail(const std::string &reason) {
        detection_.found = false;
        detection_.reason = reason;
        return finish();
    }

private:
    using Clock = std::chrono::steady_clock;
    static double ms(Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    }
    Detection &detection_;
    Clock::time_point start_ = Clock::now(), lap_ = start_;
};

}  // namespace projsurf
