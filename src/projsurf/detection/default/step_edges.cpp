#include "projsurf/detection/default/step_edges.hpp"

#include "projsurf/detection/default/median_spread.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace projsurf {

namespace {

constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

/// Mean offset of the strip of `w` columns starting at each cell's column and `l` rows centred
/// on its row; NaN where the strip holds fewer than `min_points` readings.
cv::Mat stripMeans(const cv::Mat &offset, const cv::Mat &count, int w, int l, int min_points) {
    cv::Mat sum, n;
    const cv::Point anchor(0, l / 2);
    cv::boxFilter(offset, sum, CV_32F, {w, l}, anchor, false, cv::BORDER_CONSTANT);
    cv::boxFilter(count, n, CV_32F, {w, l}, anchor, false, cv::BORDER_CONSTANT);
    cv::Mat mean(offset.size(), CV_32F);
    for (int r = 0; r < mean.rows; ++r) {
        const float *s = sum.ptr<float>(r), *k = n.ptr<float>(r);
        float *m = mean.ptr<float>(r);
        for (int c = 0; c < mean.cols; ++c) m[c] = k[c] >= min_points ? s[c] / k[c] : kNone;
    }
    return mean;
}

/// The step between columns c - 1 and c: the jump of the strip means across it, less the
/// slope of the strips beyond them (a smooth bend steps by nothing, a frame's border by its
/// height); NaN where a strip says nothing.
cv::Mat columnSteps(const cv::Mat &offset, const cv::Mat &count, int w, int l, int min_points) {
    const cv::Mat m = stripMeans(offset, count, w, l, min_points);
    cv::Mat step(m.size(), CV_32F, cv::Scalar(kNone));
    for (int r = 0; r < m.rows; ++r) {
        const float *row = m.ptr<float>(r);
        float *out = step.ptr<float>(r);
        for (int c = 2 * w; c + w < m.cols; ++c)
            out[c] = 1.5f * (row[c] - row[c - w]) - 0.5f * (row[c + w] - row[c - 2 * w]);
    }
    return step;
}

/// The robust spread (1.4826 MAD about the median) of the finite values of `a`, sampled every
/// `every` cells.
float robustSpread(const cv::Mat &a, int every) {
    std::vector<float> v;
    for (int r = 0; r < a.rows; r += every) {
        const float *row = a.ptr<float>(r);
        for (int c = 0; c < a.cols; c += every)
            if (std::isfinite(row[c])) v.push_back(row[c]);
    }
    return medianSpread(v).second;
}

/// Marks, at every step beyond max(min_step, spreads x the steps' robust spread) that is the
/// largest along its row (the strips see a step from up to a strip's width away), the cell on
/// its proud side (column c when the readings rise into it, else c - 1): the frame's border.
cv::Mat markSteps(const cv::Mat &step, const StepEvidence &steps, int every) {
    const float limit =
        std::max(static_cast<float>(steps.min_step), static_cast<float>(steps.spreads) * robustSpread(step, every));
    cv::Mat out = cv::Mat::zeros(step.size(), CV_8U);
    for (int r = 0; r < step.rows; ++r) {
        const float *s = step.ptr<float>(r);
        uchar *o = out.ptr<uchar>(r);
        for (int c = 1; c + 1 < step.cols; ++c) {
            const float a = std::abs(s[c]);
            // (NaN compares false: a step beside a strip that says nothing still counts.)
            if (a > limit && !(std::abs(s[c - 1]) > a) && !(std::abs(s[c + 1]) >= a)) o[s[c] > 0.0f ? c : c - 1] = 255;
        }
    }
    return out;
}

/// Keeps the marks (edges across the columns) that run on down the rows for at least `run`
/// cells, allowing a cell of sideways wander: a frame's border is a line, a lone step the
/// sensor's.
void keepLines(cv::Mat &marks, int run) {
    if (run < 2) return;
    cv::Mat wide, line;
    cv::dilate(marks, wide, cv::getStructuringElement(cv::MORPH_RECT, {3, 1}));
    cv::morphologyEx(wide, line, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {1, run}));
    marks &= line;
}

/// The step cells of edges across the columns of `offset` (see stepEdgeCells).
cv::Mat columnEdges(const cv::Mat &offset, const cv::Mat &count, const StepEvidence &steps, int w, int l) {
    cv::Mat marks = markSteps(columnSteps(offset, count, w, l, steps.min_points), steps, w);
    keepLines(marks, l / 2);
    return marks;
}

}  // namespace

cv::Mat stepEdgeCells(const PlaneObservation &observation, const StepEvidence &steps, double cell) {
    if (!steps.enabled || observation.offset.empty() || observation.near.empty() || !(cell > 0.0)) return {};
    const int w = std::max(1, static_cast<int>(std::lround(steps.width / cell)));
    const int l = 2 * static_cast<int>(std::lround(0.5 * steps.length / cell)) + 1;
    cv::Mat count, offset_t, count_t;
    observation.near.convertTo(count, CV_32F);
    cv::transpose(observation.offset, offset_t);
    cv::transpose(count, count_t);
    // Edges across the columns (a frame's sides) and, on the transposed raster, across the rows,
    // each direction with its own spread: a structured-light or stereo unit's error and
    // quantisation run along its baseline, so steps across the columns are the noisier.
    const cv::Mat sides = columnEdges(observation.offset, count, steps, w, l);
    cv::Mat ends;
    cv::transpose(columnEdges(offset_t, count_t, steps, w, l), ends);
    return sides | ends;
}

}  // namespace projsurf
