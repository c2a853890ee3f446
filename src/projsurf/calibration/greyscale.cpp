#include "projsurf/calibration/greyscale.hpp"

#include <opencv2/imgproc.hpp>

namespace projsurf {

cv::Mat greyscale(const cv::Mat &image) {
    cv::Mat grey;
    if (image.channels() == 3)
        cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    else if (image.channels() == 4)
        cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
    else
        grey = image;
    return grey;
}

}  // namespace projsurf
