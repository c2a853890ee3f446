#include "projsurf/core/surface_suitability.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace projsurf {
namespace {

/// Fills fit areas wholly enclosed by unfit cells, up to `max_cells` cells, with the reason of
/// a cell on their border.
void fillEnclosed(cv::Mat &unfit, double max_cells) {
    cv::Mat bad = unfit != 0;
    std::vector<std::vector<cv::Point>> contours;
    std::vector<cv::Vec4i> hierarchy;
    cv::findContours(bad, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
    for (std::size_t i = 0; i < contours.size(); ++i) {
        if (hierarchy[i][3] < 0) continue;  // an outer boundary, not a hole
        if (cv::contourArea(contours[i]) > max_cells) continue;
        const cv::Point p = contours[i].front();
        const uchar reason = unfit.at<uchar>(p.y, p.x) ? unfit.at<uchar>(p.y, p.x) : static_cast<uchar>(Unfit::Textured);
        cv::Mat hole = cv::Mat::zeros(unfit.size(), CV_8U);
        cv::drawContours(hole, contours, static_cast<int>(i), cv::Scalar(255), cv::FILLED);
        unfit.setTo(reason, hole & (unfit == 0));
    }
}

}  // namespace

CellSuitability cellSuitability(const PointGrid &grid, const cv::Rect &box,
                                const std::vector<std::array<std::uint8_t, 3>> &colours, const Plane &plane,
                                const PlaneFrame &frame, const RasterFrame &raster, const DepthTolerance &tolerance,
                                const WallShape &shape, const SuitabilityOptions &opt) {
    CellSuitability out;
    const int rows = raster.rows, cols = raster.cols;
    if (rows <= 0 || cols <= 0 || colours.empty()) return out;
    for (cv::Mat *m : {&out.samples, &out.luminance, &out.luminance_sq, &out.chroma, &out.glare})
        *m = cv::Mat::zeros(rows, cols, CV_32F);
    // 1. Each wall sample's colour, summed in the cell under its foot.
    const Eigen::Vector3d R = frame.right / raster.cell, U = -frame.up / raster.cell;
    const double col0 = -frame.origin.dot(R) - raster.top_left.x() / raster.cell;
    const double row0 = -frame.origin.dot(U) + raster.top_left.y() / raster.cell;
    const float glare = static_cast<float>(opt.glare_level * 255.0);
    std::vector<int> histogram(256, 0);
    const cv::Rect area = box & cv::Rect(0, 0, grid.cols, grid.rows);
    for (int gr = area.y; gr < area.y + area.height; ++gr)
        for (int gc = area.x; gc < area.x + area.width; ++gc) {
            const std::size_t k = static_cast<std::size_t>(gr) * grid.cols + gc;
            const Eigen::Vector3d p(grid.x[k], grid.y[k], grid.z[k]);
            if (!p.allFinite()) continue;
            const double c = p.dot(R) + col0, r = p.dot(U) + row0;
            if (!(c >= 0 && r >= 0 && c < cols && r < rows)) continue;
            const Eigen::Vector2d uv = frame.toPlane(p);
            if (std::abs(plane.signedDistance(p) - shape.height(uv)) > tolerance.band(static_cast<float>(p.z()))) continue;
            const std::size_t index = static_cast<std::size_t>(grid.cloudIndex(gr, gc));
            if (index >= colours.size()) continue;
            const auto &bgr = colours[index];
            const int luma = (29 * bgr[0] + 150 * bgr[1] + 77 * bgr[2] + 128) >> 8;
            const int hi = std::max({bgr[0], bgr[1], bgr[2]}), lo = std::min({bgr[0], bgr[1], bgr[2]});
            const int ic = static_cast<int>(c), ir = static_cast<int>(r);
            out.samples.at<float>(ir, ic) += 1.0f;
            out.luminance.at<float>(ir, ic) += luma;
            out.luminance_sq.at<float>(ir, ic) += static_cast<float>(luma * luma);
            out.chroma.at<float>(ir, ic) += static_cast<float>(hi - lo);
            out.glare.at<float>(ir, ic) += hi >= glare ? 1.0f : 0.0f;
            ++histogram[std::min(255, luma)];
        }
    int total = 0;
    for (int h : histogram) total += h;
    if (total == 0) return {};
    int below = 0, median = 0;
    while (median < 255 && (below += histogram[median]) * 2 < total) ++median;
    out.median_luminance = median / 255.0;

    // 2. Window sums about each cell, and the verdicts.
    const int k = std::max(1, static_cast<int>(std::lround(opt.window / raster.cell)) | 1);
    cv::Mat n, sy, syy, sc, sg;
    auto window = [&](const cv::Mat &in, cv::Mat &sum) {
        cv::boxFilter(in, sum, CV_32F, {k, k}, {-1, -1}, false, cv::BORDER_CONSTANT);
    };
    window(out.samples, n);
    window(out.luminance, sy);
    window(out.luminance_sq, syy);
    window(out.chroma, sc);
    window(out.glare, sg);
    out.contrast = cv::Mat::zeros(rows, cols, CV_32F);
    out.unfit = cv::Mat::zeros(rows, cols, CV_8U);
    const float dark = static_cast<float>(std::max(opt.dark_min, opt.dark_relative * out.median_luminance) * 255.0);
    const float max_chroma = static_cast<float>(opt.max_chroma * 255.0), max_contrast = static_cast<float>(opt.max_contrast),
                max_glare = static_cast<float>(opt.max_glare_share), min_samples = static_cast<float>(opt.min_samples);
    for (int r = 0; r < rows; ++r) {
        const float *pn = n.ptr<float>(r), *py = sy.ptr<float>(r), *pyy = syy.ptr<float>(r), *pc = sc.ptr<float>(r),
                    *pg = sg.ptr<float>(r);
        float *contrast = out.contrast.ptr<float>(r);
        uchar *unfit = out.unfit.ptr<uchar>(r);
        for (int c = 0; c < cols; ++c) {
            if (pn[c] < min_samples) continue;
            const float mean = py[c] / pn[c];
            const float var = std::max(0.0f, pyy[c] / pn[c] - mean * mean);
            contrast[c] = std::sqrt(var) / std::max(mean, 8.0f);  // Weber-like; near-black: its floor
            Unfit why = Unfit::None;
            if (pg[c] > max_glare * pn[c]) why = Unfit::Glare;
            else if (mean < dark) why = Unfit::Dark;
            else if (contrast[c] > max_contrast) why = Unfit::Textured;
            else if (pc[c] / pn[c] > max_chroma) why = Unfit::Saturated;
            unfit[c] = static_cast<uchar>(why);
        }
    }
    fillEnclosed(out.unfit, opt.max_hole / (raster.cell * raster.cell));
    return out;
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
            unfit += s.unfit.at<uchar>(r, c) != 0;
            samples += s.samples.at<float>(r, c);
            luminance += s.luminance.at<float>(r, c);
            if (s.samples.at<float>(r, c) > 0) {
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
