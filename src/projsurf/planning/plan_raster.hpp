#pragma once
// Every raster the planner lays (a wall's free surface, the floor's occupancy) is laid here:
// one place for its size and for turning metres into cells.
#include <Eigen/Core>

#include "projsurf/detection/raster_frame.hpp"

namespace projsurf {

/// A raster on a plane covering [lo, hi] (plane coordinates, m) in cells of `cell` m.
RasterFrame planRaster(const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double cell);

/// The square floor grid of `cell` m about the camera's foot that reaches `reach` m each way:
/// its half side in cells (the grid is 2 * half + 1 cells a side).
int floorGridHalf(double reach, double cell);

/// The cell index of a coordinate `v` (m) on a grid of `cell` m whose cell 0 is centred on 0.
int cellIndex(double v, double cell);

}  // namespace projsurf
