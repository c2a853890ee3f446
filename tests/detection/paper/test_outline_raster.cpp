// The paper method's outline raster (detection/paper/outline_raster.hpp): hull edges drawn with
// Bresenham, everything outside them filled row by row; 1 = not projectable.
#include <gtest/gtest.h>

#include <vector>

#include "projsurf/detection/paper/outline_raster.hpp"

using namespace projsurf;

namespace {

std::vector<cv::Point> setCells(const cv::Mat &grid) {
    std::vector<cv::Point> out;
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.cols; ++c)
            if (grid.at<uchar>(r, c)) out.emplace_back(c, r);
    return out;
}

}  // namespace

TEST(PaperOutlineRaster, BresenhamLineCells) {
    cv::Mat grid = cv::Mat::zeros(3, 7, CV_8UC1);
    drawLine(grid, {0, 0}, {6, 2}, 7);
    // y = x / 3 rounded: 0 0 1 1 1 2 2, one cell per column.
    const std::vector<cv::Point> want = {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 1}, {5, 2}, {6, 2}};
    std::vector<cv::Point> got = setCells(grid);
    std::sort(got.begin(), got.end(), [](const cv::Point &a, const cv::Point &b) { return a.x < b.x; });
    EXPECT_EQ(got, want);
    EXPECT_EQ(grid.at<uchar>(1, 2), 7);
    // Drawn the other way, the same cells.
    cv::Mat back = cv::Mat::zeros(3, 7, CV_8UC1);
    drawLine(back, {6, 2}, {0, 0}, 7);
    EXPECT_EQ(cv::countNonZero(back != grid), 0);
}

TEST(PaperOutlineRaster, SteepAndOffGridLines) {
    cv::Mat grid = cv::Mat::zeros(5, 5, CV_8UC1);
    drawLine(grid, {2, 0}, {2, 4}, 1);  // vertical: the whole column
    EXPECT_EQ(cv::countNonZero(grid.col(2)), 5);
    EXPECT_EQ(cv::countNonZero(grid), 5);
    cv::Mat clipped = cv::Mat::zeros(5, 5, CV_8UC1);
    drawLine(clipped, {-3, 1}, {8, 1}, 1);  // only the cells inside the grid are written
    EXPECT_EQ(cv::countNonZero(clipped.row(1)), 5);
    EXPECT_EQ(cv::countNonZero(clipped), 5);
}

TEST(PaperOutlineRaster, FillOutsideRowsStopsAtTheBorder) {
    cv::Mat grid = cv::Mat::zeros(3, 7, CV_8UC1);
    grid.at<uchar>(0, 1) = 1;
    grid.at<uchar>(0, 5) = 1;
    grid.at<uchar>(1, 3) = 1;
    // row 2 has no border: all of it is outside.
    fillOutsideRows(grid, 9);
    const uchar row0[] = {9, 1, 0, 0, 0, 1, 9}, row1[] = {9, 9, 9, 1, 9, 9, 9};
    for (int c = 0; c < 7; ++c) {
        EXPECT_EQ(grid.at<uchar>(0, c), row0[c]) << c;
        EXPECT_EQ(grid.at<uchar>(1, c), row1[c]) << c;
        EXPECT_EQ(grid.at<uchar>(2, c), 9) << c;
    }
}

TEST(PaperOutlineRaster, OutlineMaskOfASquare) {
    // 10 x 10 cells of 0.1 m over u, v in [0, 1]; the square [0.25, 0.75]^2 lies on the cells
    // 2..7 (rows and columns): its border cells and everything outside are 1, the 4 x 4
    // cells inside it 0.
    RasterFrame frame;
    frame.top_left = Eigen::Vector2d(0.0, 1.0);
    frame.cell = 0.1;
    frame.cols = frame.rows = 10;
    const std::vector<Eigen::Vector2d> square = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
    const cv::Mat m = outlineMask(frame, polygonEdges(square));
    ASSERT_EQ(m.rows, 10);
    ASSERT_EQ(m.cols, 10);
    ASSERT_EQ(m.type(), CV_8UC1);
    for (int r = 0; r < 10; ++r)
        for (int c = 0; c < 10; ++c) {
            const bool inside = r >= 3 && r <= 6 && c >= 3 && c <= 6;
            EXPECT_EQ(m.at<uchar>(r, c), inside ? 0 : 1) << "row " << r << " col " << c;
        }
}

TEST(PaperOutlineRaster, NoEdgesIsAllOutsideAndFarEdgesAreClipped) {
    RasterFrame frame;
    frame.cols = 8;
    frame.rows = 6;
    EXPECT_EQ(cv::countNonZero(outlineMask(frame, {})), 48);
    // An edge from far away to far away across the grid must not hang or overflow.
    frame.top_left = Eigen::Vector2d(0.0, 0.12);
    frame.cell = 0.02;
    const std::vector<Segment2> far = {Segment2{Eigen::Vector2d(-1e9, 0.05), Eigen::Vector2d(1e9, 0.05)}};
    const cv::Mat m = outlineMask(frame, far);
    EXPECT_EQ(m.rows, 6);
    EXPECT_EQ(cv::countNonZero(m), 48);  // a line alone encloses nothing
}
