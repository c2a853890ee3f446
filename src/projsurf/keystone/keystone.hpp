#pragma once
// Keystone correction (paper section 3.3): where the detected rectangle's corners fall in the
// projector framebuffer, the homography from the picture to those pixels, and the warp.
// Also the paper's quality measure (eq. 8) for checking the result on the wall.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

using Corners3 = std::array<Eigen::Vector3d, 4>;  ///< top-left, top-right, bottom-right, bottom-left
using Corners2 = std::array<Eigen::Vector2d, 4>;  ///< same order, framebuffer pixels

/// Framebuffer position of one camera-frame point by the paper's eq. (7) construction: the plane
/// perpendicular to the projector axis through the point, the projector workspace on it (where
/// the corner rays `rays` from the lens meet it), and linear interpolation between that
/// workspace's extremes along the projector's right and down axes. Pixel centres are at
/// integers, so the workspace edges map to -0.5 and W-0.5. With the pinhole corner rays the
/// workspace is a true rectangle and this equals Projector::toPixel. nullopt behind the lens.
std::optional<Eigen::Vector2d> pixelFromWorkspace(const Projector &projector, const Eigen::Vector3d &point,
                                                  const Corners3 &rays);
/// Same, with the projector's pinhole corner rays.
std::optional<Eigen::Vector2d> pixelFromWorkspace(const Projector &projector, const Eigen::Vector3d &point);

/// The part of `rect` that shows a picture of aspect ratio `picture_aspect` (width/height) whole
/// and undistorted: full width or full height, centred (letterbox / pillarbox).
Rectangle letterbox(const Rectangle &rect, double picture_aspect);

/// How a picture is put into the framebuffer.
struct Keystone {
    cv::Size picture;        ///< picture size the homography was computed for, px
    cv::Size framebuffer;    ///< calibration resolution, px
    Rectangle shown;         ///< the letterboxed part of the rectangle that shows the picture, 3-D
    Corners2 rectangle_px;   ///< framebuffer positions of the detected rectangle's corners
    Corners2 picture_px;     ///< framebuffer positions of the picture's outer corners
    cv::Matx33d homography;  ///< picture pixel -> ideal (undistorted) framebuffer pixel (centres at integers)
    /// With a distorted projector: per framebuffer pixel, the position it samples in the warp
    /// source (the picture, or its area-reduced copy, see warpSourceFor), CV_32FC2; the warp is
    /// then this remap instead of the homography. Empty without distortion.
    cv::Mat remap;
};

struct KeystoneResult {
    std::optional<Keystone> keystone;
    std::string problem;  ///< why there is none (empty when there is)
};

/// px: how far a rectangle may leave the framebuffer and still be shown (its edge clipped) by
/// default: half a pixel, the rounding of a corner that lies on the edge.
constexpr double kKeystoneTolerancePx = 0.5;

/// Eq. (7) pixels of the letterboxed rectangle and the picture -> framebuffer homography
/// (the paper's model; with the full model of the contract, Projector::toPixel for the pixels
/// and the homography to the corners' ideal pixels, plus `remap` when distorted)
/// (OpenCV, four exact correspondences: the picture's outer corners (-0.5,-0.5), (w-0.5,-0.5),
/// (w-0.5,h-0.5), (-0.5,h-0.5) to those pixels). Refuses (problem set) when a corner is behind
/// the projector or the rectangle leaves the framebuffer by more than `tolerance_px`.
KeystoneResult computeKeystone(const Projector &projector, const Rectangle &rect, cv::Size picture,
                               double tolerance_px = kKeystoneTolerancePx);

/// The framebuffer: black, of the keystone's framebuffer size, with `picture` (same size as the
/// keystone's picture, any 8-bit type) warped in (bilinear; pictures shrunk below half size
/// are first reduced with area averaging to avoid aliasing). A picture of another size throws
/// std::invalid_argument. For many pictures with one keystone, KeystoneWarper
/// (keystone_warper.hpp) does the per-keystone work once.
cv::Mat warpToFramebuffer(const cv::Mat &picture, const Keystone &keystone);

/// For evaluation: framebuffer pixels of a picture's outer corners when shown in `rect`
/// (letterboxed); nullopt when the rectangle cannot be shown (see computeKeystone).
std::optional<Corners2> framebufferCornersFor(const Projector &projector, const Rectangle &rect, cv::Size picture);

/// Where framebuffer pixel `pixel` lands on `wall` (ray from the lens); nullopt when it misses.
std::optional<Eigen::Vector3d> castToWall(const Projector &projector, const Eigen::Vector2d &pixel, const Plane &wall);

/// The paper's eq. (8): relative differences (percent) of opposite sides and diagonals of a
/// projected quadrilateral. Sides relative to the smaller one, diagonals to the larger.
struct ShapeErrors {
    double top = 0, bottom = 0, left = 0, right = 0, diagonal1 = 0, diagonal2 = 0;  ///< m
    double horizontal_pct = 0, vertical_pct = 0, diagonal_pct = 0;
    double worst_pct() const;
};
ShapeErrors shapeErrors(const Corners3 &corners);

}  // namespace projsurf
