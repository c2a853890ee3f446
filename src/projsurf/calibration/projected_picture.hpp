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

/// The white test card verify looks for: white, a grey disc in the centre (orientation-free).
cv::Mat verificationCard(int width, int height);

}  // namespace projsurf
