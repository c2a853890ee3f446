#include "projsurf/frontend/test_card.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace projsurf::frontend {

cv::Mat testCard(cv::Size size) {
    cv::Mat card(size, CV_8UC3, cv::Scalar(60, 40, 20));
    const int step = std::max(8, size.width / 16);
    for (int x = step; x < size.width; x += step) cv::line(card, {x, 0}, {x, size.height}, {120, 120, 120}, 1);
    for (int y = step; y < size.height; y += step) cv::line(card, {0, y}, {size.width, y}, {120, 120, 120}, 1);
    const int border = std::max(2, size.width / 100);
    cv::rectangle(card, {0, 0}, {size.width - 1, size.height - 1}, {255, 255, 255}, border);
    // An arrow pointing up, so an upside-down or mirrored picture is obvious on the wall.
    const cv::Point c(size.width / 2, size.height / 2);
    const int len = size.height / 3;
    cv::arrowedLine(card, {c.x, c.y + len}, {c.x, c.y - len}, {0, 200, 255}, std::max(2, size.width / 60), cv::LINE_AA,
                    0, 0.25);
    cv::putText(card, "projsurf", {border * 4, size.height - border * 4}, cv::FONT_HERSHEY_SIMPLEX, size.height / 300.0,
                {255, 255, 255}, std::max(1, size.height / 200), cv::LINE_AA);
    return card;
}

}  // namespace projsurf::frontend
