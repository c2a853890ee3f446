#pragma once
// Camera and projector calibrated together from chessboard poses (no depth): the board's
// corners in the camera image and, carried through the decoded structured light, in the
// framebuffer. Each device alone by Zhang's method (cv::calibrateCamera; radial k1 k2 k3,
// tangential p1 p2 held at zero), then the pair by
// cv::stereoCalibrate with those intrinsics held, which gives the projector's pose relative to
// the camera. OpenCV's convention throughout: P_proj = R P_cam + t, in the board's units.
// Every fit runs to convergence (converged_fit.hpp), and the projector is fitted again with
// each pose left out once (pose_spread.hpp): what one pose moves it by.
#include <array>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/calibration/converged_fit.hpp"
#include "projsurf/calibration/pose_spread.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

/// One chessboard pose: object points (z = 0) and where each was seen, same order.
struct StereoView {
    std::vector<cv::Point3f> board;
    std::vector<cv::Point2f> camera;     ///< camera px
    std::vector<cv::Point2f> projector;  ///< framebuffer px
};

struct DeviceIntrinsics {
    double fx = 0, fy = 0, cx = 0, cy = 0;  ///< px, pixel centres at integers
    std::array<double, 5> distortion{{0, 0, 0, 0, 0}};  ///< OpenCV k1 k2 p1 p2 k3
    double rms_px = 0;  ///< its own calibration's reprojection RMS
    /// Standard deviations of fx, fy, cx, cy (px) from its own calibration's covariance
    /// (cv::calibrateCamera): how well the poses constrain them.
    std::array<double, 4> sigma{{0, 0, 0, 0}};
};

struct StereoFit {
    bool ok = false;
    std::string problem;
    DeviceIntrinsics camera, projector;
    cv::Matx33d rotation = cv::Matx33d::eye();  ///< projector from camera
    cv::Vec3d translation{0, 0, 0};             ///< board units
    double rms_px = 0;                          ///< stereo reprojection RMS over both devices
    std::size_t views = 0, points = 0;
    std::vector<FitConvergence> convergence;    ///< camera, projector, stereo
    PoseSpread spread;                          ///< leave-one-pose-out (3 or more views)
};

struct StereoFitConfig {
    /// Tangential distortion held at zero: over a few board poses seen through narrow lenses it
    /// trades against the principal point and the pose instead of measuring the lens.
    int flags = 1 << 3;  // cv::CALIB_ZERO_TANGENT_DIST (calib3d is not in this header)
    LmCriteria criteria;
    bool jackknife = true;  ///< leave each pose out once (3 or more views)
};

/// The contract's projector from the fit: intrinsics, distortion, rotation (columns: the
/// projector's axes in the camera frame, R^T) and origin (-R^T t, in the board's units: metres
/// when the board was given in metres).
Projector stereoProjector(const StereoFit &fit, int width, int height);

/// `views`: 2 or more (3 or more recommended). Sizes in px.
StereoFit fitStereo(const std::vector<StereoView> &views, cv::Size camera_size, cv::Size projector_size,
                    const StereoFitConfig &config = {});

/// The iteration-cap warnings of the fit and its leave-one-out fits, then the spread's (one line each).
std::vector<std::string> stereoWarnings(const StereoFit &fit, const SpreadLimits &limits = {});

}  // namespace projsurf
