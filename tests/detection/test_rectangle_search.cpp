// The largest free rectangle of a fixed aspect ratio, against an exhaustive search.
#include <gtest/gtest.h>

#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>

#include "projsurf/detection/rectangle_search.hpp"

using namespace projsurf;

namespace {

bool allFree(const cv::Mat &mask, int row, int col, int rows, int cols) {
    return cv::countNonZero(mask(cv::Rect(col, row, cols, rows))) == rows * cols;
}

/// The tallest fitting size by trying every size and placement; then the placement whose
/// centre is nearest `prefer` (first in row-major order on ties).
std::optional<GridRect> exhaustive(const cv::Mat &mask, double aspect, const Eigen::Vector2d &prefer) {
    for (int rows = mask.rows; rows >= 1; --rows) {
        const int cols = widthForRows(rows, aspect);
        if (cols > mask.cols) continue;
        std::optional<GridRect> best;
        double best_d = std::numeric_limits<double>::infinity();
        for (int r = 0; r + rows <= mask.rows; ++r)
            for (int c = 0; c + cols <= mask.cols; ++c) {
                if (!allFree(mask, r, c, rows, cols)) continue;
                const double d = (Eigen::Vector2d(c + 0.5 * cols, r + 0.5 * rows) - prefer).squaredNorm();
                if (d < best_d) {
                    best_d = d;
                    best = GridRect{c, r, cols, rows};
                }
            }
        if (best) return best;
    }
    return std::nullopt;
}

}  // namespace

TEST(LargestAspectRect, MatchesAnExhaustiveSearch) {
    std::mt19937 rng(7);
    int found = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int rows = 1 + static_cast<int>(rng() % 30), cols = 1 + static_cast<int>(rng() % 45);
        cv::Mat mask(rows, cols, CV_8UC1, cv::Scalar(255));
        for (int b = static_cast<int>(rng() % 6); b > 0; --b)
            cv::circle(mask, {static_cast<int>(rng() % cols), static_cast<int>(rng() % rows)},
                       1 + static_cast<int>(rng() % 6), 0, -1);
        if (trial % 3 == 0)
            for (int k = 0; k < rows * cols / 40; ++k) mask.at<uchar>(rng() % rows, rng() % cols) = 0;
        const double aspect = 0.4 + (rng() % 1000) / 400.0;
        const Eigen::Vector2d prefer(rng() % cols, rng() % rows);
        const auto want = exhaustive(mask, aspect, prefer);
        const auto got = largestAspectRect(mask, aspect, prefer);
        ASSERT_EQ(got.has_value(), want.has_value()) << "trial " << trial;
        if (!want) continue;
        ++found;
        EXPECT_EQ(got->rows, want->rows) << "trial " << trial;
        EXPECT_EQ(got->cols, want->cols) << "trial " << trial;
        EXPECT_EQ(got->row, want->row) << "trial " << trial;
        EXPECT_EQ(got->col, want->col) << "trial " << trial;
    }
    EXPECT_GT(found, 200);
}

TEST(LargestAspectRect, NoneWhenNothingIsFree) {
    const cv::Mat blocked(10, 20, CV_8UC1, cv::Scalar(0));
    EXPECT_FALSE(largestAspectRect(blocked, 1.6, {10, 5}));
    cv::Mat one = blocked.clone();
    one.at<uchar>(3, 4) = 255;  // one free cell: too narrow for aspect 1.6 (2 cells wide)
    EXPECT_FALSE(largestAspectRect(one, 1.6, {10, 5}));
    const auto square = largestAspectRect(one, 1.0, {0, 0});
    ASSERT_TRUE(square);
    EXPECT_EQ(square->col, 4);
    EXPECT_EQ(square->row, 3);
}
