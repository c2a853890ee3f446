#pragma once
// The points a per-point pass visits, copied once per frame into separate x, y, z arrays so
// that the arithmetic of the pass vectorises: an organized cloud's pixels at a fixed step
// (missing readings stay NaN, so the grid is still an image), or every point of an
// unorganized cloud.
#include <opencv2/core/types.hpp>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

struct PointGrid {
    int step = 1;         ///< pixel step of an organized cloud (1 for unorganized clouds)
    int cols = 0;         ///< grid columns (the point count of an unorganized cloud)
    int rows = 0;         ///< grid rows (1 for unorganized clouds)
    int cloud_width = 0;  ///< pixels per row of the organized cloud it came from
    bool organized = false;
    std::vector<float> x, y, z;  ///< row-major; non-finite points are NaN in all three

    /// Index into the cloud of grid element (row, col).
    int cloudIndex(int row, int col) const { return organized ? row * step * cloud_width + col * step : col; }
    /// The grid elements whose pixels lie in `pixels` (organized clouds; the whole grid when
    /// `pixels` is empty or the cloud is unorganized).
    cv::Rect gridBox(const cv::Rect &pixels) const;
};

/// Fills `grid` (reusing its storage) with `cloud` at pixel step `step` (organized) or with
/// all its points (unorganized).
void fillPointGrid(const Cloud &cloud, int step, PointGrid &grid);

}  // namespace projsurf
