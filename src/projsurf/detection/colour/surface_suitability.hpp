#pragma once
// Whether the wall under each raster cell is fit to project on, from the registered colour of
// the wall points seen there: too dark (low albedo: the picture is dim), too
// saturated (its colours shift), textured (a framed picture, a calendar, a busy pattern: it is
// unreadable), or blown out (specular or emissive: glass, a lamp, a screen). Statistics are
// taken over sliding windows on the wall around each cell (texture and glare over `window`,
// darkness and saturation over the smaller `tone_window`).
// Luminance is the camera's 8-bit luma (0.114 B + 0.587 G + 0.299 R), as a share of 255: an
// uncalibrated stand-in for albedo, hence judged relative to the wall's median.
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/detection/wall_height.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/point_grid.hpp"

namespace projsurf {

/// Why a cell is unfit for the picture (its colour), worst first when several apply.
enum class Unfit : uchar { None = 0, Glare = 1, Dark = 2, Textured = 3, Saturated = 4 };

/// The colour sums of one cell's wall samples (Y and chroma in 8-bit levels).
struct ColourSums {
    float samples = 0, luminance = 0, luminance_sq = 0, chroma = 0,
          glare = 0;  ///< count, sum Y, sum Y^2, sum chroma, blown-out count
};

/// Per-cell colour sums over the wall samples (over the wall judged: the raster and its
/// margin) and the verdicts of the raster's cells (rows x cols).
struct CellSuitability {
    int rows = 0, cols = 0;
    int margin = 0, stride = 0;    ///< cells judged beyond the raster on each side; cells in a row of `sums`
    std::vector<ColourSums> sums;  ///< row-major over the wall judged (the raster and its margin)
    std::vector<float> window_rows, tone_rows;  ///< working storage: running sums of each window
    cv::Mat contrast;  ///< CV_32F, luminance std / mean over the window about each cell (0 without samples)
    cv::Mat unfit;     ///< CV_8U, Unfit per cell
    cv::Mat judged_contrast, judged_unfit;  ///< the same over the wall judged (contrast and unfit are views of them)
    double median_luminance = 0.0;          ///< share of 255, of the wall samples seen
    bool empty() const { return rows == 0; }
    /// The sums of raster cell (row r, column c).
    const ColourSums &sumsAt(int r, int c) const {
        return sums[static_cast<std::size_t>(r + margin) * stride + static_cast<std::size_t>(c + margin)];
    }
};

/// The colour statistics of the wall samples in `box` (grid coordinates): those within the
/// tolerance band of the wall's shape, at their foot on the plane. `colours` are the cloud's
/// (one per point); `out` is left empty when there are none. Reuses `out`'s storage (a
/// stream of frames allocates nothing once warm).
void cellSuitability(const PointGrid &grid, const cv::Rect &box,
                     const std::vector<std::array<std::uint8_t, 3>> &colours, const Plane &plane,
                     const PlaneFrame &frame, const RasterFrame &raster, const DepthTolerance &tolerance,
                     const WallShape &shape, const SuitabilityOptions &options, CellSuitability &out);

/// What the picture would lie on: over the cells whose centres are in [lo, hi] (plane coords).
struct RegionSuitability {
    double mean_luminance = 0.0;  ///< share of 255 ("mean_albedo" in the JSON)
    double contrast = 0.0;        ///< mean over its cells of the window contrast ("texture")
    double unfit_share = 0.0;     ///< share of its cells that are unfit
    int cells = 0;
};
RegionSuitability regionSuitability(const CellSuitability &cells, const RasterFrame &raster, const Eigen::Vector2d &lo,
                                    const Eigen::Vector2d &hi);

}  // namespace projsurf
