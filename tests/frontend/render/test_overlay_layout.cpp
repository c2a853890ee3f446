// The overlay's layout (issue 40): `--explain`'s candidate outlines stay within what was seen
// (no line across the whole picture from a corner behind the camera), and the legend's columns
// do not run into each other.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "projsurf/frontend/render/overlay.hpp"

using namespace projsurf;

namespace {

CameraIntrinsics vga() {
    CameraIntrinsics c;
    c.width = 640;
    c.height = 480;
    c.fx = c.fy = 525.0;
    c.cx = 319.5;
    c.cy = 239.5;
    return c;
}

}  // namespace

TEST(OverlayLayout, ACandidateOutlineIsClippedToThePicture) {
    const cv::Size size(1280, 960);  // drawn at twice the camera's pixels
    // A side wall (x = -1 m) seen from 0.5 to 4 m, its box reaching 1 m behind the camera:
    // projected as it was, its near corners land far off the picture.
    const std::array<Eigen::Vector3d, 4> side{Eigen::Vector3d(-1, -1, 4), Eigen::Vector3d(-1, -1, -1),
                                              Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, 1, 4)};
    const std::vector<cv::Point2f> outline = outlineInView(side, vga(), 2.0, size);
    ASSERT_GE(outline.size(), 3u);
    for (const cv::Point2f &p : outline) {
        EXPECT_GE(p.x, -0.01f);
        EXPECT_LE(p.x, size.width - 1 + 0.01f);
        EXPECT_GE(p.y, -0.01f);
        EXPECT_LE(p.y, size.height - 1 + 0.01f);
    }
    // Its far edge (x = -1 m at 4 m: u = 2 * (525 * -0.25 + 320) - 0.5 = 377) is kept.
    float right = 0;
    for (const cv::Point2f &p : outline) right = std::max(right, p.x);
    EXPECT_NEAR(right, 2 * (525.0 * -0.25 + 320.0) - 0.5, 1.0);
    // A box wholly in view is unchanged; one wholly behind the camera gives nothing.
    const std::array<Eigen::Vector3d, 4> front{Eigen::Vector3d(-0.5, -0.5, 2), Eigen::Vector3d(0.5, -0.5, 2),
                                               Eigen::Vector3d(0.5, 0.5, 2), Eigen::Vector3d(-0.5, 0.5, 2)};
    EXPECT_NEAR(std::abs(cv::contourArea(outlineInView(front, vga(), 2.0, size))), std::pow(2 * 525 * 0.5, 2), 2.0);
    std::array<Eigen::Vector3d, 4> behind = front;
    for (auto &p : behind) p.z() = -2;
    EXPECT_TRUE(outlineInView(behind, vga(), 2.0, size).empty());
}

TEST(OverlayLayout, TheLegendsRightColumnStartsAfterItsLeftColumnsLongestEntry) {
    const std::vector<std::string> entries{"wall points (on the wall as fitted)", "free space on the wall",
                                           "projector workspace",
                                           "picture rectangle",
                                           "not free: stands proud of the wall (frame, switch), a long entry",
                                           "not free: no wall reading"};
    for (const int cols : {640, 1280}) {
        const int second = legendSecondColumn(entries, cols);
        if (second == 0) continue;  // one column: nothing to run into
        const double fs = std::max(0.45, cols / 1700.0);  // the legend's font (overlay.cpp)
        int base = 0;
        for (std::size_t i = 0; i < entries.size(); i += 2) {
            const int end = 10 + static_cast<int>(std::round(26 * fs / 0.5)) +
                            cv::getTextSize(entries[i], cv::FONT_HERSHEY_SIMPLEX, fs, 1, &base).width;
            EXPECT_LT(end, second) << cols << ": " << entries[i];
        }
        EXPECT_GE(second, cols / 2);
    }
    // Short entries keep the right column half-way.
    EXPECT_EQ(legendSecondColumn({"a", "b", "c"}, 1280), 640);
}
