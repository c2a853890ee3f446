#pragma once
// The contract's YAML files: projector calibration and camera intrinsics.
#include <string>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/projector.hpp"

namespace YAML {
class Node;
}

namespace projsurf {

/// Reads the projector calibration (required keys only; unknown keys are ignored).
/// Throws InputError naming the file and the key on any problem, including a degenerate axis.
Projector readCalibration(const std::string &path);
/// The `calibration.fit.verdict` that `projsurf calibrate` wrote (good, acceptable, redo);
/// "" when the file has none (a calibration written by hand). Throws InputError like readCalibration.
std::string readCalibrationVerdict(const std::string &path);
/// The `projector:` node of the contract (resolution, fov_deg, axis) for a writer to extend.
YAML::Node calibrationNode(const Projector &projector);
/// Writes a calibration file with only the required keys (atomically).
void writeCalibration(const std::string &path, const Projector &projector);

/// Reads camera intrinsics (`camera:` block); throws InputError on any problem.
CameraIntrinsics readCamera(const std::string &path);
void writeCamera(const std::string &path, const CameraIntrinsics &camera);

}  // namespace projsurf
