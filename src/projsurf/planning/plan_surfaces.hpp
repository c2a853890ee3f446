#pragma once
// The vertical surfaces a plan can put the picture on: every plane detection considers and
// does not refuse (a face standing free in the room, a view through an opening), with
// where the camera saw it free (no shadows: those depend on where the robot will stand), the
// wall assumed to go on a little where it runs out of the camera's view, and the points in
// front of it that may shadow it from a stance.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/planning/floor_occupancy.hpp"

namespace projsurf {

struct PlanSurfaceOptions {
    /// m the free wall is assumed to go on beyond the edge of the camera's view (our choice:
    /// a wall seen to the image border rarely ends just there; this much lets the plan step
    /// back for a wider picture without trusting much unseen wall: docs/planning.md)
    double beyond_view = 0.75;
    /// m, wall seen this near the edge of the camera's view is taken as seen up to it, and only
    /// such wall is assumed to go on beyond the view (our choice: depth images often have no
    /// reading in their outermost pixels, ~8 px = 5 cm at 3 m on a Kinect v1).
    double view_edge = 0.1;
    double voxel = 0.04;  ///< m, the points in front are kept one per voxel (shadows are cast per voxel)
    double obstacle_height = 0.08;  ///< m above the floor: lower points in front of the wall are floor
};

struct PlanSurface {
    Plane plane;
    PlaneFrame frame;
    RasterFrame raster;
    cv::Mat free;      ///< CV_8U, 255 = free (seen free, or assumed beyond the view)
    cv::Mat assumed;   ///< CV_8U, 255 = assumed free beyond the view
    cv::Mat integral;  ///< CV_32S (rows + 1) x (cols + 1), the free cells' integral image
    cv::Mat assumed_integral;  ///< CV_32S, the assumed cells' integral image
    /// The points in front of it, one per voxel: the voxel centre's plane coordinates and its
    /// height above the plane (m, towards the camera).
    struct InFront {
        Eigen::Vector2d uv;
        double h;
    };
    std::vector<InFront> in_front;
    double voxel = 0.04;  ///< m, their voxels' side
};

/// The plan's surfaces from the seen ones (their rasters extended by beyond_view); `camera`:
/// the pinhole they were seen through (no extension without one).
std::vector<PlanSurface> planSurfaces(const Cloud &cloud, const SeenSurfaces &seen, const FloorOccupancy &floor,
                                      const PlanSurfaceOptions &options);

/// Free cells of `surface` in the cell box [c0, c1) x [r0, r1) (clipped), from its integral image.
int freeCells(const PlanSurface &surface, int c0, int r0, int c1, int r1);

/// The share of the cells under `picture` (an upright rectangle on `surface`, camera frame;
/// the cells whose centre it covers) that are assumed, not seen: 0 = all seen, 1 = all assumed.
double assumedShare(const PlanSurface &surface, const Rectangle &picture);

}  // namespace projsurf
