#include "projsurf/frontend/render/test_card.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <string>

namespace projsurf::frontend {

cv::Mat testCard(cv::Size size) {
    const int w = size.width, h = size.height;
    cv::Mat img(std::max(h, 0), std::max(w, 0), CV_8UC3, cv::Scalar(40, 40, 40));
    if (img.empty()) return img;
    const double u = std::min(w, h) / 800.0;  // scale relative to an 800 px tall card
    // Grid of squares: circles must look round and squares square when the picture is right.
    const int step = std::max(8, h / 10);
    for (int x = (w % step) / 2; x <= w; x += step) cv::line(img, {x, 0}, {x, h}, cv::Scalar(110, 110, 110), 1);
    for (int y = (h % step) / 2; y <= h; y += step) cv::line(img, {0, y}, {w, y}, cv::Scalar(110, 110, 110), 1);
    // Colour bars across the middle band.
    const cv::Scalar bars[] = {{255, 255, 255}, {0, 255, 255}, {255, 255, 0}, {0, 255, 0},
                               {255, 0, 255},   {0, 0, 255},   {255, 0, 0},   {20, 20, 20}};
    const int band_top = h * 58 / 100, band_h = h * 14 / 100;
    for (int i = 0; i < 8; ++i)
        cv::rectangle(img, cv::Rect(w * i / 8, band_top, w / 8 + 1, band_h), bars[i], cv::FILLED);
    // A big centred circle and smaller ones near the corners.
    const cv::Point c(w / 2, h * 36 / 100);
    cv::circle(img, c, h * 26 / 100, cv::Scalar(255, 255, 255), std::max(2, cvRound(6 * u)), cv::LINE_AA);
    cv::line(img, {c.x - h / 4, c.y}, {c.x + h / 4, c.y}, cv::Scalar(255, 255, 255), std::max(1, cvRound(3 * u)));
    cv::line(img, {c.x, c.y - h / 4}, {c.x, c.y + h / 4}, cv::Scalar(255, 255, 255), std::max(1, cvRound(3 * u)));
    const int r = h / 10;
    for (const cv::Point p : {cv::Point(r + r / 2, r + r / 2), cv::Point(w - r - r / 2, r + r / 2),
                              cv::Point(w - r - r / 2, h - r - r / 2), cv::Point(r + r / 2, h - r - r / 2)})
        cv::circle(img, p, r, cv::Scalar(0, 200, 255), std::max(2, cvRound(5 * u)), cv::LINE_AA);
    // Title.
    const std::string title = "projsurf";
    const double fs = 3.2 * u;
    const int th = std::max(2, cvRound(7 * u));
    int base = 0;
    const cv::Size ts = cv::getTextSize(title, cv::FONT_HERSHEY_DUPLEX, fs, th, &base);
    const cv::Point at((w - ts.width) / 2, h * 88 / 100 + ts.height / 2);
    cv::putText(img, title, at, cv::FONT_HERSHEY_DUPLEX, fs, cv::Scalar(255, 255, 255), th, cv::LINE_AA);
    // Border, so the picture's edges are visible on the wall.
    cv::rectangle(img, cv::Rect(0, 0, w, h), cv::Scalar(0, 220, 0), std::max(4, cvRound(12 * u)));
    return img;
}

}  // namespace projsurf::frontend
