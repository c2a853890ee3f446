#pragma once
// The keystone warp of a distorted projector: straight lines on the wall are not straight in
// the framebuffer, so the picture -> framebuffer map is the homography to ideal (undistorted)
// pixels followed by the lens distortion; the warp samples per framebuffer pixel (a remap).
#include <opencv2/core.hpp>

#include "projsurf/keystone/keystone.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

/// Per framebuffer pixel (CV_32FC2, the keystone's framebuffer size): the position in the warp
/// source (warpSourceFor(keystone, keystone.picture): the picture or its area-reduced copy)
/// that the pixel shows: the inverse homography of the pixel's ideal position. Pixels whose
/// position falls outside the source get -10 (black).
cv::Mat keystoneRemap(const Projector &projector, const Keystone &keystone);

/// The framebuffer for `picture` (8-bit or not, of the keystone's picture size, else
/// std::invalid_argument): the same area-averaging prepass as warpToFramebuffer (reducedSource),
/// then a bilinear cv::remap through keystone.remap, black outside the picture.
cv::Mat remapToFramebuffer(const cv::Mat &picture, const Keystone &keystone);

}  // namespace projsurf
