#pragma once
// What the camera saw of one plane, cell by cell of a raster on it (the default method's
// free space, paper 3.2.2, and its surface check, 3.2.3, read off one pass over the points).
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "projsurf/detection/default/wall_shape.hpp"
#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/detection/surface_check.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/point_grid.hpp"

namespace projsurf {

/// Counts per raster cell (row-major, raster.rows x raster.cols). The matrices are views into
/// `counts`, which only grows, so that a stream of frames allocates nothing once warm (hence
/// no copies: they would share the views); spare rows after each block absorb the points
/// that count nowhere, so that the counting loop has no branches.
struct PlaneObservation {
    PlaneObservation() = default;
    PlaneObservation(const PlaneObservation &) = delete;
    PlaneObservation &operator=(const PlaneObservation &) = delete;
    PlaneObservation(PlaneObservation &&) = default;  // the vector's buffer moves with it
    PlaneObservation &operator=(PlaneObservation &&) = default;

    cv::Mat support;  ///< CV_32S: points on the plane (within the inlier band), at their foot on it
    cv::Mat behind;   ///< CV_32S: points beyond the plane (a hole, a door), where their camera ray crosses it
    cv::Mat shadow;   ///< CV_32S: points between the projector and the plane, where their shadow falls
    cv::Mat seen;     ///< CV_32S: points whose camera ray crosses the plane in the cell (all of them)
    cv::Mat off;      ///< CV_32S: of `seen`, the points off the plane by more than the tolerance margin
    cv::Mat near;     ///< CV_32S: points within the margin of the wall's shape (on it or just proud), at their foot
    cv::Mat offset;   ///< CV_32F: the sum of those points' offsets from the shape (m, towards the camera)
    int support_points = 0;
    /// support, behind, shadow, spare row; seen, spare row, off, spare row; near, spare row
    std::vector<std::int32_t> counts;
    std::vector<float> offsets;  ///< offset, spare row
};

/// One pass over the grid elements in `box` (grid coordinates): each finite point is on the
/// wall (|r| <= band), beyond it (r < -margin), between the projector and the wall
/// (margin < r, h < projector height), or in between (counted in `seen` only); those within the
/// margin also add their r to `near` and `offset` at their foot; h is its signed
/// distance to the plane, positive towards the camera, and r = h - shape's height at its foot.
/// Grid elements with a non-zero `exclude` (grid-sized; points of another surface) are never
/// support. Reuses `out`'s storage.
void observePlane(const PointGrid &grid, const cv::Rect &box, const Plane &plane, const PlaneFrame &frame,
                  const RasterFrame &raster, const Eigen::Vector3d &projector_origin, const DepthTolerance &tolerance,
                  PlaneObservation &out, const WallShape &shape = {},
                  const std::vector<std::uint8_t> *exclude = nullptr);

/// The default surface check (checkSurface's rule) read off an observation: the points whose
/// camera ray crosses the plane in the cells whose centres lie in [lo, hi] (plane
/// coordinates); rejected when more than `max_fraction` of them are off the plane. The counts
/// only: outlier_indices stays empty (offPlanePoints lists them, for the rectangle kept).
SurfaceCheckResult checkObservedSurface(const PlaneObservation &observation, const RasterFrame &raster,
                                        const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double max_fraction);

/// Cloud indices of the points that checkObservedSurface counts as off the plane for [lo, hi],
/// looked for among the grid elements in `box` (which must hold all of them: the pixels where
/// the rectangle is seen).
std::vector<int> offPlanePoints(const PointGrid &grid, const cv::Rect &box, const Plane &plane, const PlaneFrame &frame,
                                const RasterFrame &raster, const DepthTolerance &tolerance, const Eigen::Vector2d &lo,
                                const Eigen::Vector2d &hi, const WallShape &shape = {});

}  // namespace projsurf
