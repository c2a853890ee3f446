#pragma once
// From a rectangle found on a raster to the largest one about it that still fits: grown
// continuously while its corners stay inside the exact projector footprint and every cell it
// touches is free surface (recovers the grid search's quantisation; the footprint is exact).
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>

#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

struct GrowthOptions {
    double search_cells = 2.0;  ///< cells, the height is searched in [h, h + this]
    int bisections = 10;        ///< steps of the search (2 cells / 2^10: 0.02 mm at 1 cm cells)
    double slide_cells = 0.5;   ///< cells moved per slide away from what limits the rectangle
    int max_slides = 8;         ///< slide rounds at most
};

/// `surface`: CV_8U on `raster`, non-zero = free surface (the footprint not applied);
/// `footprint_uv`: the projector footprint in plane coordinates; aspect = width / height.
Rectangle growRectangle(const Rectangle &start, const PlaneFrame &frame, const RasterFrame &raster,
                        const cv::Mat &surface, const std::array<Eigen::Vector2d, 4> &footprint_uv, double aspect,
                        const GrowthOptions &options = {});

/// The rectangle moved in by `margin` on every side (by at most a quarter of its smaller side).
Rectangle shrinkRectangle(const PlaneFrame &frame, const Rectangle &rect, double margin);

}  // namespace projsurf
