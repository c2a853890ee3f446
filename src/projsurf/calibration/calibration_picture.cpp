#include "projsurf/calibration/calibration_picture.hpp"

namespace projsurf {

cv::Mat calibrationPicture(int width, int height, double radius_px) {
    if (radius_px <= 0.0) radius_px = height / 8.0;
    cv::Mat img(height, width, CV_8UC3, cv::Scalar(0, 0, 0));
    const double cx = 0.5 * (width - 1), cy = 0.5 * (height - 1), r2 = radius_px * radius_px;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r2) img.at<cv::Vec3b>(y, x) = cv::Vec3b(255, 255, 255);
    return img;
}

}  // namespace projsurf
