#include "projsurf/calibration/local_homography.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace projsurf {

std::vector<CornerInProjector> cornersInProjector(const GrayDecoding &d, const std::vector<cv::Point2f> &corners,
                                                  const LocalHomographyConfig &cfg) {
    const int half = cfg.half_patch > 0 ? cfg.half_patch : static_cast<int>(std::ceil(d.column.cols / 180.0));
    const int side = 2 * half + 1;
    std::vector<CornerInProjector> out(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const int cx = static_cast<int>(std::lround(corners[i].x)), cy = static_cast<int>(std::lround(corners[i].y));
        std::vector<cv::Point2f> cam, proj;
        // The patch's brightest direct light, for the share below.
        std::vector<float> lit;
        const bool has_light = d.direct.size() == d.column.size() && d.direct.type() == CV_32F;
        for (int y = std::max(0, cy - half); y <= std::min(d.direct.rows - 1, cy + half); ++y)
            for (int x = std::max(0, cx - half); x <= std::min(d.direct.cols - 1, cx + half); ++x)
                if (has_light && !std::isnan(d.column.at<double>(y, x))) lit.push_back(d.direct.at<float>(y, x));
        float floor_light = 0;
        if (!lit.empty() && cfg.min_direct_share > 0) {
            auto at = lit.begin() + static_cast<std::ptrdiff_t>(0.9 * (lit.size() - 1));
            std::nth_element(lit.begin(), at, lit.end());
            floor_light = static_cast<float>(cfg.min_direct_share * *at);
        }
        for (int y = cy - half; y <= cy + half; ++y)
            for (int x = cx - half; x <= cx + half; ++x) {
                if (x < 0 || y < 0 || x >= d.column.cols || y >= d.column.rows) continue;
                const double u = d.column.at<double>(y, x), v = d.row.at<double>(y, x);
                if (std::isnan(u) || std::isnan(v) || (has_light && d.direct.at<float>(y, x) < floor_light)) continue;
                cam.emplace_back(static_cast<float>(x), static_cast<float>(y));
                proj.emplace_back(static_cast<float>(u), static_cast<float>(v));
            }
        CornerInProjector &c = out[i];
        c.decoded = static_cast<int>(cam.size());
        if (c.decoded < std::max(8.0, cfg.min_decoded_share * side * side)) continue;
        // Coordinates relative to the corner, so that the fit is well conditioned.
        const cv::Point2f o(static_cast<float>(cx), static_cast<float>(cy));
        for (auto &p : cam) p -= o;
        cv::Mat mask;
        const cv::Mat h = cv::findHomography(cam, proj, cv::RANSAC, cfg.ransac_px, mask, 2000, 0.999);
        if (h.empty()) continue;
        c.inliers = cv::countNonZero(mask);
        if (c.inliers < std::max(8.0, cfg.min_decoded_share * side * side)) continue;
        const cv::Point2f q = corners[i] - o;
        const cv::Vec3d p = cv::Matx33d(h) * cv::Vec3d(q.x, q.y, 1.0);
        if (!(std::abs(p[2]) > 1e-12)) continue;
        c.projector = cv::Point2f(static_cast<float>(p[0] / p[2]), static_cast<float>(p[1] / p[2]));
        c.ok = std::isfinite(c.projector.x) && std::isfinite(c.projector.y);
    }
    return out;
}

double decodedBoardShare(const GrayDecoding &d, const std::vector<cv::Point2f> &corners, cv::Size inner) {
    if (corners.size() != static_cast<std::size_t>(inner.area()) || inner.width < 2 || inner.height < 2) return 0;
    const int w = inner.width, h = inner.height;
    std::vector<cv::Point> outline;
    for (int k = 0; k < w; ++k) outline.emplace_back(corners[k]);
    for (int r = 1; r < h; ++r) outline.emplace_back(corners[r * w + w - 1]);
    for (int k = w - 2; k >= 0; --k) outline.emplace_back(corners[(h - 1) * w + k]);
    for (int r = h - 2; r > 0; --r) outline.emplace_back(corners[r * w]);
    cv::Mat board(d.column.size(), CV_8U, cv::Scalar(0));
    cv::fillPoly(board, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(255));
    int inside = 0, decoded = 0;
    for (int y = 0; y < board.rows; ++y) {
        const uchar *b = board.ptr<uchar>(y);
        const double *u = d.column.ptr<double>(y);
        for (int x = 0; x < board.cols; ++x)
            if (b[x]) {
                ++inside;
                if (!std::isnan(u[x])) ++decoded;
            }
    }
    return inside > 0 ? static_cast<double>(decoded) / inside : 0.0;
}

}  // namespace projsurf
