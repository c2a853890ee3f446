#pragma once
// The paper's outline raster (3.2.2, Figs. 8-9): the hull's edges drawn with Bresenham and
// everything outside them filled row by row.
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/detection/paper/hull.hpp"
#include "projsurf/detection/raster_frame.hpp"

namespace projsurf {

/// Sets the cells of the segment a-b (cell coordinates) to `value` (Bresenham's algorithm).
void drawLine(cv::Mat &grid, const Eigen::Vector2i &a, const Eigen::Vector2i &b, uchar value);

/// Paper's fill: scanning each row from both ends, every cell before the first border cell
/// (non-zero) is outside and set to `value`. Rows with no border are entirely outside.
void fillOutsideRows(cv::Mat &grid, uchar value);

/// The paper's M matrix: edges drawn with Bresenham, outside filled; 1 = not projectable.
cv::Mat outlineMask(const RasterFrame &frame, const std::vector<Segment2> &edges);

}  // namespace projsurf
