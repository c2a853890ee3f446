#pragma once
// The biggest free axis-aligned rectangle of a fixed aspect ratio in a raster
// (paper 3.2.2, last step; the paper uses Vandevorde's maximal-rectangle search).
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>

#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// Cells [col, col + cols) x [row, row + rows) of a raster.
struct GridRect {
    int col = 0;
    int row = 0;
    int cols = 0;
    int rows = 0;
};

/// The tallest rectangle whose `rows` x ceil(aspect * rows) cells are all free (non-zero in
/// `free_mask`, CV_8U), aspect = width / height. Among the placements of that size, the one
/// whose centre is nearest `prefer` (in cell coordinates: x = col, y = row) is returned.
/// nullopt when not even one row fits. O(R C log R) with an integral image.
std::optional<GridRect> largestAspectRect(const cv::Mat &free_mask, double aspect, const Eigen::Vector2d &prefer);

/// Cells wide for a rectangle `rows` tall at the given aspect ratio.
int widthForRows(int rows, double aspect);

/// The same on a raster of a plane: the rectangle in plane coordinates, centred in the cells it
/// occupies, the placement nearest `prefer` (plane coordinates); nullopt when none fits.
std::optional<Rectangle> largestFreeRectangle(const cv::Mat &free_mask, const RasterFrame &raster,
                                              const PlaneFrame &frame, double aspect, const Eigen::Vector2d &prefer);

}  // namespace projsurf
