#pragma once
// Rasterising outlines on the plane (paper 3.2.2, Figs. 8-9): Bresenham edges and the
// row-by-row fill of everything outside them.
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/detection/hull.hpp"

namespace projsurf {

/// Maps plane coordinates (u right, v up, metres) to raster cells (col right, row down).
struct RasterFrame {
    Eigen::Vector2d top_left = Eigen::Vector2d::Zero();  ///< plane coords of the raster's top-left corner
    double cell = 0.02;                                  ///< m
    int cols = 0, rows = 0;

    Eigen::Vector2d toCell(const Eigen::Vector2d &uv) const {
        return {(uv.x() - top_left.x()) / cell, (top_left.y() - uv.y()) / cell};
    }
    Eigen::Vector2d toPlane(const Eigen::Vector2d &cr) const {
        return {top_left.x() + cr.x() * cell, top_left.y() - cr.y() * cell};
    }
};

/// Raster covering the bounding box [lo, hi] of plane coordinates, capped at max_cells per side.
RasterFrame makeRasterFrame(const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double cell, int max_cells = 4000);

/// Sets the cells of the segment a-b (cell coordinates) to `value` (Bresenham's algorithm).
void drawLine(cv::Mat &grid, const Eigen::Vector2i &a, const Eigen::Vector2i &b, uchar value);

/// Paper's fill: scanning each row from both ends, every cell before the first border cell
/// (non-zero) is outside and set to `value`. Rows with no border are entirely outside.
void fillOutsideRows(cv::Mat &grid, uchar value);

/// Cells whose centre lies inside a convex or simple polygon given in plane coordinates
/// are set to `value` (exact, scanline even-odd).
void fillPolygon(cv::Mat &grid, const RasterFrame &frame, const std::vector<Eigen::Vector2d> &polygon, uchar value);

/// A convex polygon moved inwards by `distance` on every edge (counter-clockwise or
/// clockwise input); used so that whole cells, not only their centres, lie inside.
std::vector<Eigen::Vector2d> insetConvexPolygon(const std::vector<Eigen::Vector2d> &polygon, double distance);

/// The paper's M matrix: edges drawn with Bresenham, outside filled; 1 = not projectable.
cv::Mat outlineMask(const RasterFrame &frame, const std::vector<Segment2> &edges);

/// Cells of `raster` wholly inside the convex footprint (plane coordinates): 255, else 0.
cv::Mat footprintCells(const RasterFrame &raster, const std::array<Eigen::Vector2d, 4> &footprint_uv);

}  // namespace projsurf
