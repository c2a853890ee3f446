#pragma once
// The calibration YAML that `projsurf calibrate` writes: the contract's required keys
// (projector.resolution, fov_deg, axis) plus what a user needs to judge the fit (corner rays,
// per-capture centroids and residuals, what was used). readCalibration reads it back.
#include <string>
#include <vector>

#include "projsurf/calibration/calibration.hpp"

namespace projsurf {

struct CalibrationProvenance {
    std::string captures_dir;                ///< as given on the command line
    std::vector<std::string> capture_names;  ///< colour image file names, in capture order
    int threshold = 50;                      ///< binarisation threshold used
    std::string created_utc;                 ///< ISO 8601 timestamp
};

/// How good the axis fit is, from its largest residual: "good" (<= 5 mm), "acceptable"
/// (<= 15 mm) or "redo" (the captures disagree; take them again).
std::string calibrationVerdict(const AxisFit &axis);

/// The YAML text (required keys + extras).
std::string calibrationReportYaml(const Calibration &calibration, const CalibrationProvenance &provenance);

/// Writes calibrationReportYaml atomically; throws InputError naming the path on failure.
void writeCalibrationReport(const std::string &path, const Calibration &calibration,
                            const CalibrationProvenance &provenance);

}  // namespace projsurf
