#pragma once
// The projector calibration as every command reads it: its warnings (unknown keys under
// `projector:`, a typo whose value would be lost) on stderr, one line each.
#include <string>

#include "projsurf/types/projector.hpp"

namespace projsurf::cli {

/// readCalibration(path) with its warnings printed as "projsurf: warning: ...".
Projector readCalibrationWarned(const std::string &path);

}  // namespace projsurf::cli
