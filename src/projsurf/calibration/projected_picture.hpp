#pragma once
// Closed-loop check (contract "Closed-loop check"): where a projected picture really
// landed. The picture is found in the colour camera's image as the largest bright
// quadrilateral (the test card is white), its edges fitted as lines with sub-pixel care, the
// corners intersected, and lifted to 3-D through the plane fitted to the registered depth
// inside it. Also: where the framebuffer's lit picture was meant to land, by the calibration.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "projsurf/types/camera.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct FoundPicture {
    bool found = false;
    std::string reason;   ///< why not found
    Corners2 image_px{};  ///< TL, TR, BR, BL in the colour image, px
    Corners3 corners{};   ///< the same lifted to 3-D, camera frame, m
    Plane plane;          ///< fitted to the depth inside the picture
};

/// `colour`: 8-bit (grey or BGR); `depth`: CV_16UC1 of the same size, registered. The
/// picture must cover at least `min_area_px` camera pixels and be the test card
/// (verificationCard): a bright quadrilateral without its darker centre disc is not found.
FoundPicture findProjectedPicture(const cv::Mat &colour, const cv::Mat &depth, const CameraIntrinsics &camera,
                                  double min_area_px = 400.0);

/// The outer corners (TL, TR, BR, BL, framebuffer px) of the non-black region of a framebuffer
/// that `correct` wrote; nullopt when it is all black.
std::optional<Corners2> litFramebufferCorners(const cv::Mat &framebuffer);

/// What a found picture says about the calibration, apart from what the detection carries.
/// `expected`: the framebuffer's lit corners cast through the calibration onto the surface the
/// colour camera sees (the plane fitted to the depth inside the picture); `calibration_error_m`:
/// the found corners' distances from them. Both lie on that one plane, so a depth error of that
/// plane moves them alike (by its offset times the camera-projector baseline over the distance)
/// and what is left is the calibration's. `detection_error_m`: the found corners' distances from
/// `meant` (the detection's corners, letterboxed to the picture), which add the detection's own
/// depth noise; `detection_off_m`: how far `meant` lies off the surface seen, the largest of
/// the four (that noise, about 2 cm at 2 m for a Kinect v1).
struct LandingCheck {
    Corners3 expected{};
    std::array<double, 4> calibration_error_m{};
    std::array<double, 4> detection_error_m{};
    double max_calibration_error_m = 0, max_detection_error_m = 0, detection_off_m = 0;
};

/// verify's default tolerance for `LandingCheck::calibration_error_m`: 5 mm, or 0.3 deg seen
/// from the projector at the mean distance of `expected` from its lens where that is more
/// (10.5 mm at 2 m). What a perfect calibration still shows grows with the distance (the
/// camera's and the projector's pixels cover more of the wall): up to 0.15 deg in the closed
/// loop through every simulated sensor at 1-3 m, frontal and at 30 deg; a calibration 1 deg
/// off in yaw shows 1 deg or more (tests/calibration/test_verify.cpp).
constexpr double kCalibrationToleranceM = 0.005, kCalibrationToleranceDeg = 0.3;
double calibrationTolerance(const Projector &projector, const Corners3 &expected);

/// nullopt when a lit corner's ray misses the surface seen (the calibration casts the picture
/// elsewhere: behind the projector, or parallel to the surface).
std::optional<LandingCheck> checkLanding(const Projector &projector, const Corners2 &lit_px, const FoundPicture &found,
                                         const Corners3 &meant);

/// The white test card verify looks for: white, a grey disc in the centre (orientation-free).
cv::Mat verificationCard(int width, int height);

}  // namespace projsurf
