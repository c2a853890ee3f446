#pragma once
// The contract's YAML files: projector calibration and camera intrinsics.
#include <string>
#include <vector>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/projector.hpp"

namespace YAML {
class Node;
}

namespace projsurf {

/// Reads the projector calibration (required keys, and the contract's optional full model).
/// Throws InputError naming the file and the key on any problem, including a degenerate axis.
/// Unknown keys are ignored; with `warnings`, those inside `projector:` (a typo such as
/// `distorsion`, whose value would be lost) are added there as one line (at most three named,
/// escaped). The file is one YAML document with no alias cycle and no key twice (yaml_tree.hpp).
Projector readCalibration(const std::string &path, std::vector<std::string> *warnings = nullptr);
/// The `calibration.fit.verdict` that `projsurf calibrate` wrote (good, acceptable, redo);
/// "" when the file has none (a calibration written by hand). Throws InputError like readCalibration.
std::string readCalibrationVerdict(const std::string &path);
/// The `projector:` node of the contract (resolution, fov_deg, axis) for a writer to extend.
YAML::Node calibrationNode(const Projector &projector);
/// The text of the calibration `root` (a `projector:` node and its report) for `path`, checked
/// before anything is written: read back as readCalibration reads it, every number finite.
/// InputError naming `path` and the reader's reason otherwise (the fit is refused, nothing written).
std::string calibrationYamlText(const std::string &path, const YAML::Node &root);
/// The same check on a calibration's text as it will be written.
void checkCalibrationText(const std::string &path, const std::string &text);
/// Writes a calibration file with only the required keys (atomically; checked as above).
void writeCalibration(const std::string &path, const Projector &projector);

/// Reads camera intrinsics: projsurf's `camera:` block (width, height, fx, fy, cx, cy,
/// depth_scale), or a ROS camera_info YAML (image_width, image_height, camera_matrix; its
/// depth_scale is 1000, 16UC1 millimetres by REP 118; non-zero distortion_coefficients are
/// refused: projsurf reads rectified, pinhole depth). Throws InputError on any problem. With
/// `warnings`, keys it does not know (a typo such as `depth_scal`) are added there as one line.
CameraIntrinsics readCamera(const std::string &path, std::vector<std::string> *warnings = nullptr);
void writeCamera(const std::string &path, const CameraIntrinsics &camera);

}  // namespace projsurf
