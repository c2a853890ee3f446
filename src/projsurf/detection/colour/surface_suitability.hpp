#pragma once
// Whether the wall under each raster cell is fit to project on, from the registered colour of
// the wall points seen there (issue 15): too dark (low albedo: the picture is dim), too
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

#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/detection/outline_raster.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/point_grid.hpp"
#include "projsurf/detection/default/wall_shape.hpp"

namespace projsurf {

/// Why a cell is unfit for the picture (its colour), worst first when several apply.
enum class Unfit : uchar { None = 0, Glare = 1, Dark = 2, Textured = 3, Saturated = 4 };

struct SuitabilityOptions {
    double context = 0.05;  ///< m, the wall judged beyond the raster on each side, so that a thing reaching into it is
                            ///< judged with the rest of it (a calendar the projector's reach cuts 7 cm into)
    double weak_contrast = 0.12;  ///< window contrast above which cells near wide texture are textured too (hysteresis;
                                  ///< a calendar's grid of thin lines holds 0.12-0.2; colour suite) ...
    double weak_over_wall =
        8.0;  ///< ... and above this many times the wall's median contrast (5 shrank the fabric
              ///< wardrobe of real frame nyu_o3d_basement_closet, 8 leaves every labelled frame as it was)
    double texture_growth = 0.05;  ///< m, how far from wide texture the weak cells may join it (0.03 leaves the
                                   ///< calendar 2.2 % on the rectangle; colour suite)
    double window = 0.05;  ///< m, side of the square on the wall texture and glare are judged over (5 cells at 1 cm)
    double tone_window =
        0.03;  ///< m, the square darkness and saturation are judged over (3 cells: a dark panel's edge to a cell)
    double dark_relative =
        0.45;  ///< darker than this share of the wall's median luminance: too dark (measured, docs/suitability.md)
    double dark_min = 0.06;  ///< luminance share below which a surface is too dark whatever the wall (near black)
    double max_chroma =
        0.40;  ///< mean (max - min channel) / 255 above this: too saturated (measured, docs/suitability.md)
    double max_contrast =
        0.20;  ///< luminance std / mean over the window above this: textured (measured, docs/suitability.md)
    double glare_level = 0.98;  ///< a sample whose brightest channel reaches this share of 255 is blown out
    double max_glare_share =
        0.1;  ///< more blown-out samples than this share of the window: glare (specular, emissive; one column of 5)
    double glare_wall_share = 0.85;  ///< no glare on a wall whose median luminance reaches this share of glare_level
                                     ///< (the camera clipped the wall itself; real frame sun3d_nvblox_studyroom_000116)
    int row_step = 1;  ///< every this many rows of the point grid are sampled (2 halves the pass but lets a window pane
                       ///< reach 2.1 % of the rectangle; colour suite)
    int min_tone_samples = 8;  ///< fewer in the tone window: tone is judged over the window (a terracotta wall's
                               ///< chroma, 0.37, crossed 0.40 on the noise of 3-7 samples; test_suitability)
    int min_samples = 3;       ///< fewer wall samples in the window: colour decides nothing there
    int trim_cells =
        2;  ///< textured and glare cells given back on an unfit area's rim (the window reaches 2 cells beyond an edge)
    double max_hole =
        0.25;  ///< m^2, fit areas enclosed by unfit cells up to this size are unfit too (a picture's plain mat)
    double min_unfit_area = 0.01;     ///< m^2, smaller unfit areas are fit (a light switch plate, 8 x 8 cm, clipped
                                      ///< to white: real frame bundlefusion_copyroom_000000)
    double min_texture_width = 0.05;  ///< m, textured areas narrower than this are fit (a door seam, a cable; real
                                      ///< frame nyu_o3d_basement_closet)
};

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
