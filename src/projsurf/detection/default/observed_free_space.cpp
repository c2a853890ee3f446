#include "projsurf/detection/default/observed_free_space.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace projsurf {

SurfaceCells observedFreeSurface(const PlaneObservation &observation, int gap_cells, int min_blocked_neighbours) {
    const cv::Mat &support = observation.support, &behind = observation.behind, &shadow = observation.shadow;
    const int gap = std::max(1, gap_cells);
    cv::Mat supported = support > 0;
    cv::morphologyEx(supported, supported, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, {2 * gap + 1, 2 * gap + 1}));
    const cv::Mat through = behind > support, in_front = shadow > 0;
    cv::Mat blocked = through | in_front;
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
    out.state.setTo(static_cast<int>(CellState::SeenThrough), blocked & through);
    out.state.setTo(static_cast<int>(CellState::InFront), blocked & in_front);
    return out;
}

cv::Mat footprintCells(const RasterFrame &raster, const std::array<Eigen::Vector2d, 4> &footprint_uv) {
    cv::Mat cells = cv::Mat::zeros(raster.rows, raster.cols, CV_8UC1);
    // Whole cells inside: the footprint's edges moved in by half a cell diagonal.
    fillPolygon(cells, raster, insetConvexPolygon({footprint_uv.begin(), footprint_uv.end()}, 0.7072 * raster.cell),
                255);
    return cells;
}

}  // namespace projsurf
