#pragma once
// The pixels of an organized cloud where a volume is seen: per-point passes look only there.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// Pixels where the camera sees all of `points`, grown by `margin` and clipped to the image;
/// empty (meaning: all pixels) when one of them is not finite or not in front of the camera.
cv::Rect pixelBox(const CameraIntrinsics &camera, const std::vector<Eigen::Vector3d> &points, int margin);

/// Pixels where everything that matters to a raster on a plane is seen: the raster itself
/// (wall points, and points seen through holes in it) and the beam from `lens` towards it from
/// depth `near` on (whatever shadows it), grown by `margin`.
cv::Rect beamImageBox(const CameraIntrinsics &camera, const PlaneFrame &frame, const RasterFrame &raster,
                      const Eigen::Vector3d &lens, double near, int margin);

/// Pixels of an organized cloud where the points `indices` lie, grown by `margin`; empty for
/// an unorganized cloud or no indices.
cv::Rect indexImageBox(const Cloud &cloud, const std::vector<int> &indices, int margin);

}  // namespace projsurf
