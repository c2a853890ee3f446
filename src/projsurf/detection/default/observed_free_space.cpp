#include "projsurf/detection/default/observed_free_space.hpp"

#include "projsurf/detection/default/median_spread.hpp"
#include "projsurf/detection/default/step_edges.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

namespace projsurf {

cv::Mat proudCells(const PlaneObservation &observation, const ProudEvidence &proud, double cell) {
    if (!proud.enabled || observation.offset.empty() || observation.near.empty() || !(cell > 0.0)) return {};
    const int w = 2 * static_cast<int>(std::lround(0.5 * proud.window / cell)) + 1;
    cv::Mat sum, count;
    cv::boxFilter(observation.offset, sum, CV_32F, {w, w}, {-1, -1}, false, cv::BORDER_CONSTANT);
    cv::Mat near;
    observation.near.convertTo(near, CV_32F);
    cv::boxFilter(near, count, CV_32F, {w, w}, {-1, -1}, false, cv::BORDER_CONSTANT);
    const float min_points = static_cast<float>(std::max(1, proud.min_points));
    std::vector<float> sampled;  // windows half a window apart: the spread of nearly independent means
    const int step = std::max(1, w / 2);
    for (int r = 0; r < sum.rows; r += step) {
        const float *s = sum.ptr<float>(r), *n = count.ptr<float>(r);
        for (int c = 0; c < sum.cols; c += step)
            if (n[c] >= min_points) sampled.push_back(s[c] / n[c]);
    }
    const auto [centre, spread] = medianSpread(sampled);
    const float limit = std::max(static_cast<float>(proud.min_offset), static_cast<float>(proud.spreads) * spread);
    cv::Mat out = cv::Mat::zeros(sum.size(), CV_8U);
    for (int r = 0; r < sum.rows; ++r) {
        const float *s = sum.ptr<float>(r), *n = count.ptr<float>(r);
        uchar *o = out.ptr<uchar>(r);
        for (int c = 0; c < sum.cols; ++c)
            o[c] = n[c] >= min_points && std::abs(s[c] - centre * n[c]) > limit * n[c] ? 255 : 0;
    }
    // A window mean that stands out alone is the sensor's: an obstacle moves the means of
    // every window over it.
    const int k = static_cast<int>(std::lround(proud.min_extent / cell));
    if (k > 1) cv::morphologyEx(out, out, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {k, k}));
    return out;
}

SurfaceCells observedFreeSurface(const PlaneObservation &observation, int gap_cells, int min_blocked_neighbours,
                                 const ProudEvidence &proud, double cell, const StepEvidence &steps) {
    const cv::Mat &support = observation.support, &behind = observation.behind, &shadow = observation.shadow;
    const int gap = std::max(1, gap_cells);
    cv::Mat supported = support > 0;
    cv::morphologyEx(supported, supported, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, {2 * gap + 1, 2 * gap + 1}));
    const cv::Mat through = behind > support, in_front = shadow > 0;
    cv::Mat off_shape = proudCells(observation, proud, cell);
    if (off_shape.empty()) off_shape = cv::Mat::zeros(support.size(), CV_8U);
    const cv::Mat step = stepEdgeCells(observation, steps, cell);
    if (!step.empty()) off_shape |= step;
    cv::Mat blocked = through | in_front | off_shape;
    cv::Mat neighbours;
    cv::boxFilter(blocked / 255, neighbours, CV_16U, {3, 3}, {-1, -1}, false, cv::BORDER_CONSTANT);
    blocked &= neighbours >= min_blocked_neighbours;

    SurfaceCells out;
    const cv::Mat observed = supported & ~blocked;
    cv::erode(observed, out.free, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}), {-1, -1}, 1, cv::BORDER_CONSTANT,
              0);
    out.state = cv::Mat(support.size(), CV_8UC1, cv::Scalar(static_cast<int>(CellState::Edge)));
    out.state.setTo(static_cast<int>(CellState::Free), out.free);
    out.state.setTo(static_cast<int>(CellState::NoReading), ~supported);
    out.state.setTo(static_cast<int>(CellState::Proud), blocked & off_shape);
    out.state.setTo(static_cast<int>(CellState::SeenThrough), blocked & through);
    out.state.setTo(static_cast<int>(CellState::InFront), blocked & in_front);
    return out;
}

}  // namespace projsurf
