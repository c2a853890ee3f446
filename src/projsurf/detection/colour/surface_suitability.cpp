#include "projsurf/detection/colour/surface_suitability.hpp"

#include "projsurf/detection/raster_shape.hpp"
#include "projsurf/types/target_clones.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace projsurf {
namespace {

/// Fills fit areas wholly enclosed by unfit cells, up to `max_cells` cells, with the reason of
/// a cell on their border.
void fillEnclosed(cv::Mat &unfit, double max_cells) {
    const cv::Mat bad = unfit != 0;
    std::vector<std::vector<cv::Point>> contours;
    std::vector<cv::Vec4i> hierarchy;
    cv::findContours(bad, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
    cv::Mat hole;
    for (std::size_t i = 0; i < contours.size(); ++i) {
        if (hierarchy[i][3] < 0) continue;  // an outer boundary, not a hole
        if (cv::contourArea(contours[i]) > max_cells) continue;
        const cv::Rect box = cv::boundingRect(contours[i]);
        const cv::Point p = contours[i].front();
        const uchar reason =
            unfit.at<uchar>(p.y, p.x) ? unfit.at<uchar>(p.y, p.x) : static_cast<uchar>(Unfit::Textured);
        hole = cv::Mat::zeros(box.size(), CV_8U);
        cv::drawContours(hole, contours, static_cast<int>(i), cv::Scalar(255), cv::FILLED, cv::LINE_8, cv::noArray(), 0,
                         -box.tl());
        cv::Mat roi = unfit(box);
        roi.setTo(reason, hole & (roi == 0));
    }
}

/// The floats of a row of ColourSums, read as one array (the struct is five floats, no padding).
constexpr int kChannels = 5;
static_assert(sizeof(ColourSums) == kChannels * sizeof(float), "ColourSums is read as plain floats");

/// The k x k window sums about the cells of one raster row at a time (zero outside the
/// raster), kept in `store`: the sums down each column over the k rows about the row (with
/// k / 2 empty cells either side), then the row's window sums. Flat float arrays, the five
/// sums of a cell side by side, so that every pass vectorises; nothing raster-sized is written.
struct RunningWindow {
    const float *in = nullptr;  ///< the cell sums, row-major
    int rows = 0, k = 1;
    std::ptrdiff_t width = 0;                  ///< floats in a raster row
    float *column = nullptr, *sums = nullptr;  ///< column sums (padded), the row's window sums
};

RunningWindow startWindow(const std::vector<ColourSums> &in, int rows, int cols, int k, std::vector<float> &store) {
    RunningWindow w;
    w.in = reinterpret_cast<const float *>(in.data());
    w.rows = rows;
    w.k = k;
    w.width = static_cast<std::ptrdiff_t>(cols) * kChannels;
    const std::ptrdiff_t pad = (k / 2) * kChannels;
    store.assign(static_cast<std::size_t>(2 * w.width + 2 * pad), 0.0f);
    w.column = store.data();
    w.sums = store.data() + w.width + 2 * pad;
    float *sum = w.column + pad;
    for (int r = 0; r < std::min(k / 2, rows); ++r)
        for (std::ptrdiff_t i = 0; i < w.width; ++i) sum[i] += w.in[r * w.width + i];
    return w;
}

/// Moves the window to row r (rows are taken in order 0, 1, ...) and returns its sums there.
PROJSURF_CLONES
const ColourSums *windowRow(RunningWindow &w, int r) {
    const int half = w.k / 2;
    float *sum = w.column + half * kChannels;
    if (r + half < w.rows) {
        const float *add = w.in + (r + half) * w.width;
        for (std::ptrdiff_t i = 0; i < w.width; ++i) sum[i] += add[i];
    }
    if (r - half - 1 >= 0) {
        const float *sub = w.in + (r - half - 1) * w.width;
        for (std::ptrdiff_t i = 0; i < w.width; ++i) sum[i] -= sub[i];
    }
    for (std::ptrdiff_t i = 0; i < w.width; ++i) w.sums[i] = w.column[i];
    for (int j = 1; j < w.k; ++j) {
        const float *shifted = w.column + j * kChannels;
        for (std::ptrdiff_t i = 0; i < w.width; ++i) w.sums[i] += shifted[i];
    }
    return reinterpret_cast<const ColourSums *>(w.sums);
}

/// The raster cell under each wall sample of one grid row (its foot on the plane, within the
/// tolerance band of the wall's shape), or -1. Float scalars and selects only, so that the loop
/// vectorises; NaN points fail every test.
struct FootCells {
    float rx, ry, rz, ux, uy, uz, nx, ny, nz, d, col0, row0, cols, rows, band_k, band_min, band_max;
    std::int32_t ncols;
    RasterShape shape;
};

PROJSURF_CLONES
void footCells(const FootCells &f, const float *X, const float *Y, const float *Z, int n, std::int32_t *cell) {
    for (int i = 0; i < n; ++i) {
        const float px = X[i], py = Y[i], pz = Z[i];
        const float pc = f.rx * px + f.ry * py + f.rz * pz, pw = f.ux * px + f.uy * py + f.uz * pz;
        const float np = f.nx * px + f.ny * py + f.nz * pz;
        const float h = np + f.d - f.shape.at(pc + f.col0, pw + f.row0);
        // Where the camera ray meets the plane: a depth camera's bias moves a reading along its
        // ray, so the colour belongs there (its normal foot is off by the bias x tan(ray angle)).
        const float t = -f.d / np;
        const float c = t * pc + f.col0, r = t * pw + f.row0;
        const float band = std::min(std::max(f.band_k * pz * pz, f.band_min), f.band_max);
        const std::int32_t in = (c >= 0.0f) & (r >= 0.0f) & (c < f.cols) & (r < f.rows) & (std::abs(h) <= band);
        // Clamped first (NaN -> 0) so that the conversion is defined for the points discarded.
        const float kc = std::min(f.cols - 1.0f, std::max(0.0f, c)), kr = std::min(f.rows - 1.0f, std::max(0.0f, r));
        const std::int32_t index = static_cast<std::int32_t>(kr) * f.ncols + static_cast<std::int32_t>(kc);
        cell[i] = in ? index : -1;
    }
}

/// The bin holding the median of a histogram of n bins, or -1 when it is empty.
int medianBin(const int *histogram, int n) {
    long total = 0;
    for (int i = 0; i < n; ++i) total += histogram[i];
    if (total == 0) return -1;
    long below = 0;
    int bin = 0;
    while (bin < n - 1 && (below += histogram[bin]) * 2 < total) ++bin;
    return bin;
}

/// Hysteresis on texture: the weakly textured cells (window contrast above `weak`, fit so
/// far) within `reach` of a textured area at least a picture's narrowest wide (`core`: what
/// an opening keeps) are textured too. A calendar's grid of thin lines holds the texture level
/// only in patches; a seam or a cable (narrow) grows nothing, and nothing grows far.
void growTexture(cv::Mat unfit, const cv::Mat &contrast, const cv::Mat &core, const cv::Mat &reach, double weak) {
    const uchar textured = static_cast<uchar>(Unfit::Textured);
    const cv::Mat faint = (contrast > weak) & (unfit == 0);
    if (cv::countNonZero(faint) == 0) return;
    cv::Mat cores;
    cv::morphologyEx(unfit == textured, cores, cv::MORPH_OPEN, core, {-1, -1}, 1, cv::BORDER_REPLICATE);
    if (cv::countNonZero(cores) == 0) return;
    cv::dilate(cores, cores, reach, {-1, -1}, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    unfit.setTo(textured, faint & cores);
}

/// The verdicts refined on `unfit` (a box of them with a ring of fit cells about it, which
/// stands for the raster beyond): the rims of texture and glare given back, enclosed fit areas
/// filled, small areas and narrow texture given back; first, texture grown into the weakly
/// textured cells near it (`contrast`: the box's window contrast; weak is judged against the
/// wall's own median contrast `wall_texture`, so that a fabric or wood surface does not grow
/// texture everywhere). `cell` in m.
void refineUnfit(cv::Mat unfit, const cv::Mat &contrast, double cell, const SuitabilityOptions &opt,
                 double wall_texture) {
    const cv::Mat trim_kernel =
        cv::getStructuringElement(cv::MORPH_RECT, {2 * opt.trim_cells + 1, 2 * opt.trim_cells + 1});
    const int line = static_cast<int>(std::lround(opt.min_texture_width / cell));
    const cv::Mat line_kernel = cv::getStructuringElement(cv::MORPH_RECT, {std::max(1, line), std::max(1, line)});
    const int grow = static_cast<int>(std::lround(opt.texture_growth / cell));
    growTexture(unfit, contrast, line_kernel, cv::getStructuringElement(cv::MORPH_RECT, {2 * grow + 1, 2 * grow + 1}),
                std::max(opt.weak_contrast, opt.weak_over_wall * wall_texture));
    // The window reaches half its side beyond a thing's edge (its edge and its glare count
    // there): that margin of texture and glare is given back.
    const cv::Mat spread = (unfit == static_cast<uchar>(Unfit::Textured)) | (unfit == static_cast<uchar>(Unfit::Glare));
    if (opt.trim_cells > 0) {
        cv::Mat keep;
        cv::erode(unfit != 0, keep, trim_kernel, {-1, -1}, 1, cv::BORDER_REPLICATE);
        unfit.setTo(0, spread & (keep == 0));
    }
    fillEnclosed(unfit, opt.max_hole / (cell * cell));
    // Unfit areas too small to matter (a light switch plate that the camera clips) are fit,
    // and so is texture narrower than a picture could be everywhere (a door seam, a cable,
    // where two paints meet): an area that an opening of that width removes whole is given
    // back where it is textured. (A calendar's thin lines stay: they join its wider print.)
    cv::Mat opened, labels;
    if (line > 1)
        cv::morphologyEx(unfit != 0, opened, cv::MORPH_OPEN, line_kernel, {-1, -1}, 1, cv::BORDER_REPLICATE);
    else
        opened = unfit != 0;
    const int n = cv::connectedComponents(unfit != 0, labels, 8, CV_32S);
    std::vector<int> size(static_cast<std::size_t>(n), 0);
    std::vector<uchar> wide(static_cast<std::size_t>(n), 0);
    for (int r = 0; r < unfit.rows; ++r) {
        const int *label = labels.ptr<int>(r);
        const uchar *o = opened.ptr<uchar>(r);
        for (int c = 0; c < unfit.cols; ++c) {
            if (!label[c]) continue;
            ++size[static_cast<std::size_t>(label[c])];
            if (o[c]) wide[static_cast<std::size_t>(label[c])] = 1;
        }
    }
    const double min_cells = opt.min_unfit_area / (cell * cell);
    std::vector<uchar> small(static_cast<std::size_t>(n));
    for (std::size_t l = 0; l < small.size(); ++l) small[l] = size[l] < min_cells;
    for (int r = 0; r < unfit.rows; ++r) {
        const int *label = labels.ptr<int>(r);
        uchar *why = unfit.ptr<uchar>(r);
        for (int c = 0; c < unfit.cols; ++c) {
            if (!why[c]) continue;
            const std::size_t l = static_cast<std::size_t>(label[c]);
            if (small[l] || (why[c] == static_cast<uchar>(Unfit::Textured) && !wide[l])) why[c] = 0;
        }
    }
}

/// The raster widened by `margin` cells on every side.
RasterFrame widened(const RasterFrame &raster, int margin) {
    RasterFrame judged = raster;
    judged.top_left += Eigen::Vector2d(-margin * raster.cell, margin * raster.cell);
    judged.cols += 2 * margin;
    judged.rows += 2 * margin;
    return judged;
}

/// Where a wall sample's foot falls in `judged`, in float, as in observePlane: raster column
/// q . R + col0, row q . U + row0.
FootCells footCellsOf(const Plane &plane, const PlaneFrame &frame, const RasterFrame &judged,
                      const DepthTolerance &tolerance, const WallShape &shape) {
    const double cell = judged.cell;
    const Eigen::Vector3d R = frame.right / cell, U = -frame.up / cell;
    return FootCells{static_cast<float>(R.x()),
                     static_cast<float>(R.y()),
                     static_cast<float>(R.z()),
                     static_cast<float>(U.x()),
                     static_cast<float>(U.y()),
                     static_cast<float>(U.z()),
                     static_cast<float>(plane.normal.x()),
                     static_cast<float>(plane.normal.y()),
                     static_cast<float>(plane.normal.z()),
                     static_cast<float>(plane.d),
                     static_cast<float>(-frame.origin.dot(R) - judged.top_left.x() / cell),
                     static_cast<float>(-frame.origin.dot(U) + judged.top_left.y() / cell),
                     static_cast<float>(judged.cols),
                     static_cast<float>(judged.rows),
                     static_cast<float>(tolerance.sigmas * tolerance.noise_k),
                     static_cast<float>(tolerance.min_band),
                     static_cast<float>(tolerance.max_band),
                     judged.cols,
                     RasterShape(shape, judged)};
}

/// Each wall sample's colour (the grid rows of `box`, every opt.row_step-th) summed in the
/// cell under its foot; returns the bin (0 ... 255) of the samples' median luminance, -1 when
/// no sample fell on the raster.
int sumColours(const PointGrid &grid, const cv::Rect &box, const std::vector<std::array<std::uint8_t, 3>> &colours,
               const FootCells &f, const SuitabilityOptions &opt, std::vector<ColourSums> &sums) {
    const int glare = static_cast<int>(std::ceil(opt.glare_level * 255.0));
    std::vector<int> histogram(256, 0);
    const cv::Rect area = box & cv::Rect(0, 0, grid.cols, grid.rows);
    std::vector<std::int32_t> cell(static_cast<std::size_t>(std::max(0, area.width)));
    for (int gr = area.y; gr < area.y + area.height; gr += std::max(1, opt.row_step)) {
        const std::size_t first = static_cast<std::size_t>(gr) * grid.cols + area.x;
        footCells(f, grid.x.data() + first, grid.y.data() + first, grid.z.data() + first, area.width, cell.data());
        for (int i = 0; i < area.width; ++i) {
            if (cell[i] < 0) continue;
            const std::size_t index = static_cast<std::size_t>(grid.cloudIndex(gr, area.x + i));
            if (index >= colours.size()) continue;
            const auto &bgr = colours[index];
            const int luma = (29 * bgr[0] + 150 * bgr[1] + 77 * bgr[2] + 128) >> 8;
            const int hi = std::max({bgr[0], bgr[1], bgr[2]}), lo = std::min({bgr[0], bgr[1], bgr[2]});
            ColourSums &sum = sums[static_cast<std::size_t>(cell[i])];
            sum.samples += 1.0f;
            sum.luminance += static_cast<float>(luma);
            sum.luminance_sq += static_cast<float>(luma * luma);
            sum.chroma += static_cast<float>(hi - lo);
            sum.glare += hi >= glare ? 1.0f : 0.0f;
            ++histogram[std::min(255, luma)];
        }
    }
    return medianBin(histogram.data(), static_cast<int>(histogram.size()));
}

/// What a cell's sums are judged against (luminance in 0 ... 255).
struct VerdictLimits {
    float max_glare, dark, max_chroma, max_contrast, min_samples, min_tone;
};

VerdictLimits verdictLimits(const SuitabilityOptions &opt, double median_luminance) {
    VerdictLimits v;
    // A wall that is itself at the glare level is the camera's exposure clipping it, not glare.
    v.max_glare = median_luminance < opt.glare_level * opt.glare_wall_share ? static_cast<float>(opt.max_glare_share)
                                                                            : std::numeric_limits<float>::infinity();
    v.dark = static_cast<float>(std::max(opt.dark_min, opt.dark_relative * median_luminance) * 255.0);
    v.max_chroma = static_cast<float>(opt.max_chroma * 255.0);
    v.max_contrast = static_cast<float>(opt.max_contrast);
    v.min_samples = static_cast<float>(opt.min_samples);
    v.min_tone = static_cast<float>(opt.min_tone_samples);
    return v;
}

/// A cell's verdict from its window sums `s` (window contrast `contrast`) and its `tone` sums.
Unfit verdict(const ColourSums &s, const ColourSums &tone, float contrast, const VerdictLimits &v) {
    if (s.glare > v.max_glare * s.samples) return Unfit::Glare;
    if (tone.luminance < v.dark * tone.samples) return Unfit::Dark;
    if (contrast > v.max_contrast) return Unfit::Textured;
    if (tone.chroma > v.max_chroma * tone.samples) return Unfit::Saturated;
    return Unfit::None;
}

constexpr int kTextureBins = 200;  // of window contrast, 0 ... 1

/// What the first verdicts leave for refinement: the box of the unfit cells (empty when none)
/// and the histogram of window contrast over the cells with samples.
struct FirstVerdicts {
    cv::Rect unfit_box;
    std::array<int, kTextureBins> texture_histogram{};
};

/// Window sums about each cell of the rows x cols raster (sums in out.sums), and the verdicts
/// into out.judged_contrast and out.judged_unfit: texture and glare over the window, tone
/// (darkness, saturation) over the smaller tone window, so that a dark thing's edge is found to
/// within a cell. `cell` in m.
FirstVerdicts judgeCells(CellSuitability &out, int rows, int cols, double cell, const SuitabilityOptions &opt) {
    auto oddCells = [&](double metres) { return std::max(1, static_cast<int>(std::lround(metres / cell)) | 1); };
    RunningWindow window = startWindow(out.sums, rows, cols, oddCells(opt.window), out.window_rows);
    RunningWindow tone_window = startWindow(out.sums, rows, cols, oddCells(opt.tone_window), out.tone_rows);
    cv::Mat &contrast_all = out.judged_contrast, &unfit_all = out.judged_unfit;
    contrast_all.create(rows, cols, CV_32F);
    contrast_all.setTo(0);
    unfit_all.create(rows, cols, CV_8U);
    unfit_all.setTo(0);
    const VerdictLimits limits = verdictLimits(opt, out.median_luminance);
    FirstVerdicts first;
    int r0 = rows, r1 = -1, c0 = cols, c1 = -1;  // the unfit cells' box
    for (int r = 0; r < rows; ++r) {
        const ColourSums *w = windowRow(window, r), *t = windowRow(tone_window, r);
        float *contrast = contrast_all.ptr<float>(r);
        uchar *unfit = unfit_all.ptr<uchar>(r);
        for (int c = 0; c < cols; ++c) {
            const ColourSums &s = w[c];
            if (s.samples < limits.min_samples) continue;
            const float mean = s.luminance / s.samples;
            const float var = std::max(0.0f, s.luminance_sq / s.samples - mean * mean);
            contrast[c] = std::sqrt(var) / std::max(mean, 8.0f);  // Weber-like; near black: its floor
            ++first.texture_histogram[std::min(kTextureBins - 1, static_cast<int>(contrast[c] * kTextureBins))];
            // Tone over the tone window when it has the samples, else over the window.
            const Unfit why = verdict(s, t[c].samples >= limits.min_tone ? t[c] : s, contrast[c], limits);
            unfit[c] = static_cast<uchar>(why);
            if (why != Unfit::None)
                r0 = std::min(r0, r), r1 = std::max(r1, r), c0 = std::min(c0, c), c1 = std::max(c1, c);
        }
    }
    if (r1 >= 0) first.unfit_box = cv::Rect(c0, r0, c1 - c0 + 1, r1 - r0 + 1);
    return first;
}

}  // namespace

void cellSuitability(const PointGrid &grid, const cv::Rect &box,
                     const std::vector<std::array<std::uint8_t, 3>> &colours, const Plane &plane,
                     const PlaneFrame &frame, const RasterFrame &raster, const DepthTolerance &tolerance,
                     const WallShape &shape, const SuitabilityOptions &opt, CellSuitability &out) {
    out.rows = out.cols = 0;
    if (raster.rows <= 0 || raster.cols <= 0 || colours.empty()) return;
    // The wall is judged `context` beyond the raster on every side, so that a thing reaching
    // into the raster is judged with the rest of it; out holds views of the raster's part.
    const int margin = std::max(0, static_cast<int>(std::lround(opt.context / raster.cell)));
    const RasterFrame judged = widened(raster, margin);
    const int rows = judged.rows, cols = judged.cols;
    out.sums.assign(static_cast<std::size_t>(rows) * cols, ColourSums{});
    // 1. Each wall sample's colour, summed in the cell under its foot.
    const int median =
        sumColours(grid, box, colours, footCellsOf(plane, frame, judged, tolerance, shape), opt, out.sums);
    if (median < 0) return;
    out.median_luminance = median / 255.0;
    // 2. Window sums about each cell, and the verdicts.
    const FirstVerdicts first = judgeCells(out, rows, cols, raster.cell, opt);
    // 3. The rest looks at the unfit cells only: their box, with room for texture to grow.
    if (!first.unfit_box.empty()) {
        const int ring = 1 + std::max(0, static_cast<int>(std::lround(opt.texture_growth / raster.cell)));
        const cv::Rect &u = first.unfit_box;
        const cv::Rect refined =
            cv::Rect(u.x - ring, u.y - ring, u.width + 2 * ring, u.height + 2 * ring) & cv::Rect(0, 0, cols, rows);
        // The wall's own texture: its median window contrast.
        const double wall_texture = (medianBin(first.texture_histogram.data(), kTextureBins) + 0.5) / kTextureBins;
        refineUnfit(out.judged_unfit(refined), out.judged_contrast(refined), raster.cell, opt, wall_texture);
    }
    const cv::Rect inner(margin, margin, raster.cols, raster.rows);
    out.rows = raster.rows;
    out.cols = raster.cols;
    out.margin = margin;
    out.stride = cols;
    out.contrast = out.judged_contrast(inner);
    out.unfit = out.judged_unfit(inner);
}

RegionSuitability regionSuitability(const CellSuitability &s, const RasterFrame &raster, const Eigen::Vector2d &lo,
                                    const Eigen::Vector2d &hi) {
    RegionSuitability out;
    if (s.empty()) return out;
    const double cell = raster.cell;
    const int c0 = std::max(0, static_cast<int>(std::ceil((lo.x() - raster.top_left.x()) / cell - 0.5)));
    const int c1 = std::min(raster.cols - 1, static_cast<int>(std::floor((hi.x() - raster.top_left.x()) / cell - 0.5)));
    const int r0 = std::max(0, static_cast<int>(std::ceil((raster.top_left.y() - hi.y()) / cell - 0.5)));
    const int r1 = std::min(raster.rows - 1, static_cast<int>(std::floor((raster.top_left.y() - lo.y()) / cell - 0.5)));
    double samples = 0, luminance = 0, contrast = 0;
    int unfit = 0, seen = 0;
    for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
            ++out.cells;
            const ColourSums &sum = s.sumsAt(r, c);
            unfit += s.unfit.at<uchar>(r, c) != 0;
            samples += sum.samples;
            luminance += sum.luminance;
            if (sum.samples > 0) {
                contrast += s.contrast.at<float>(r, c);
                ++seen;
            }
        }
    if (out.cells == 0) return out;
    out.unfit_share = static_cast<double>(unfit) / out.cells;
    out.mean_luminance = samples > 0 ? luminance / samples / 255.0 : 0.0;
    out.contrast = seen > 0 ? contrast / seen : 0.0;
    return out;
}

}  // namespace projsurf
