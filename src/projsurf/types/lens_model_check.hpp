#pragma once
// One plausibility check of a lens model (the projector's and the depth camera's), shared by
// every reader of a calibration or camera file and by the Python constructors, so a model is
// held to the same rules wherever it comes from. The core of it is geometry, not files: the
// problem comes back as text naming the contract's keys, the caller adds where it came from.
#include <string>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

/// Angles of view a lens model may give, degrees: 1 (a long telephoto) to 170 (a fisheye's
/// edge); a projector's is 15-120, a depth camera's 40-120.
constexpr double kMinLensFovDeg = 1.0;
constexpr double kMaxLensFovDeg = 170.0;
/// The longest focal length a camera model may have, px: a crop of a frame keeps the frame's
/// focal length and may see under 1 degree, so the camera's bound is this, not an angle; 10^6 px
/// is a 1 m lens on 1 um pixels (depth cameras have 200-2000 px).
constexpr double kMaxCameraFocalPx = 1e6;
/// How far the full model's angles of view may lie from the file's fov_deg: 10 degrees
/// (calibrate writes them equal; a hand-rounded file stays well inside).
constexpr double kMaxFovDisagreementDeg = 10.0;
/// How far from the camera the projector's lens may sit: 3 m (a larger number is millimetres).
constexpr double kMaxProjectorOffsetM = 3.0;

/// Empty when `projector` is a plausible lens model; otherwise what is wrong, naming the
/// contract's key (projector.fov_deg, projector.intrinsics.fx, projector.axis.origin, ...).
std::string lensModelProblem(const Projector &projector);

/// The same for a depth camera (camera.fx .. camera.depth_scale).
std::string cameraModelProblem(const CameraIntrinsics &camera);

}  // namespace projsurf
