#include "projsurf/calibration/chessboard_corners.hpp"

#include <algorithm>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/greyscale.hpp"

namespace projsurf {

ChessboardCorners findChessboard(const cv::Mat &image, const std::vector<cv::Size> &sizes) {
    std::vector<cv::Size> tries = sizes;
    if (tries.empty()) {
        for (int a = 3; a <= 12; ++a)
            for (int b = 3; b <= a; ++b) tries.emplace_back(a, b);
        std::stable_sort(tries.begin(), tries.end(),
                         [](const cv::Size &p, const cv::Size &q) { return p.area() > q.area(); });
    }
    cv::Mat grey = greyscale(image);
    if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U);
    // Detection on a half-size image (fast), refinement at full size.
    cv::Mat small;
    const double scale = grey.cols > 1000 ? 0.5 : 1.0;
    if (scale < 1.0)
        cv::resize(grey, small, cv::Size(), scale, scale, cv::INTER_AREA);
    else
        small = grey;
    ChessboardCorners out;
    // Early stop: OpenCV's quick check (enough black and white quads of one size) asks more of a
    // larger board, so an image that fails it for the smallest board (3 x 3 inner corners)
    // fails it for every size: noise or a blank wall is answered after one check (0.03 s)
    // instead of a search of every size and orientation (3 poses of 1280 x 1024 noise took 42 s).
    if (sizes.empty() && !cv::checkChessboard(small, cv::Size(3, 3))) return out;
    for (const cv::Size &s : tries) {
        for (int turn = 0; turn < (s.width == s.height ? 1 : 2); ++turn) {
            const cv::Size t = turn == 0 ? s : cv::Size(s.height, s.width);
            std::vector<cv::Point2f> c;
            if (!cv::findChessboardCorners(small, t, c,
                                           cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE |
                                               cv::CALIB_CB_FAST_CHECK))
                continue;
            for (auto &p : c) p = (p + cv::Point2f(0.5f, 0.5f)) * static_cast<float>(1.0 / scale) - cv::Point2f(0.5f, 0.5f);
            // A search window of a third of the smallest corner spacing.
            double spacing = 1e9;
            for (int r = 0; r < t.height; ++r)
                for (int k = 0; k + 1 < t.width; ++k)
                    spacing = std::min(spacing, cv::norm(c[r * t.width + k + 1] - c[r * t.width + k]));
            const int win = std::clamp(static_cast<int>(spacing / 3), 2, 15);
            cv::cornerSubPix(grey, c, cv::Size(win, win), cv::Size(-1, -1),
                             cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 0.01));
            out.found = true;
            out.inner = t;
            out.corners = c;
            return out;
        }
    }
    return out;
}

std::vector<cv::Point3f> chessboardObjectPoints(cv::Size inner, double square) {
    std::vector<cv::Point3f> p;
    for (int r = 0; r < inner.height; ++r)
        for (int k = 0; k < inner.width; ++k)
            p.emplace_back(static_cast<float>(k * square), static_cast<float>(r * square), 0.f);
    return p;
}

}  // namespace projsurf
