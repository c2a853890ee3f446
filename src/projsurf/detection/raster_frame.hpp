#pragma once
// The raster on a plane (paper 3.2.2): cells of a fixed side over the plane's coordinates, and
// polygons filled on it. Every stage that searches a plane for free space works on one.
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <vector>

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

/// Cells whose centre lies inside a convex or simple polygon given in plane coordinates
/// are set to `value` (exact, scanline even-odd).
void fillPolygon(cv::Mat &grid, const RasterFrame &frame, const std::vector<Eigen::Vector2d> &polygon, uchar value);

/// A convex polygon moved inwards by `distance` on every edge (counter-clockwise or
/// clockwise input); used so that whole cells, not only their centres, lie inside.
std::vector<Eigen::Vector2d> insetConvexPolygon(const std::vector<Eigen::Vector2d> &polygon, double distance);

/// Cells of `raster` wholly inside the convex footprint (plane coordinates): 255, else 0.
cv::Mat footprintCells(const RasterFrame &raster, const std::array<Eigen::Vector2d, 4> &footprint_uv);

}  // namespace projsurf
