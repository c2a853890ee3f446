#include "projsurf/keystone/keystone_remap.hpp"

#include <opencv2/imgproc.hpp>

#include "projsurf/keystone/keystone_warper.hpp"

namespace projsurf {

cv::Mat keystoneRemap(const Projector &projector, const Keystone &k) {
    const WarpSource source = warpSourceFor(k, k.picture);
    const cv::Matx33d inv = source.homography.inv();
    cv::Mat map(k.framebuffer, CV_32FC2);
    const double w = source.size.width, h = source.size.height;
    for (int v = 0; v < map.rows; ++v) {
        cv::Vec2f *row = map.ptr<cv::Vec2f>(v);
        for (int u = 0; u < map.cols; ++u) {
            const Eigen::Vector2d ideal = projector.idealFromPixel({u, v});
            const cv::Vec3d q = inv * cv::Vec3d(ideal.x(), ideal.y(), 1.0);
            const double x = q[0] / q[2], y = q[1] / q[2];
            const bool inside = q[2] > 0 && x > -1.0 && x < w && y > -1.0 && y < h;
            row[u] = inside ? cv::Vec2f(static_cast<float>(x), static_cast<float>(y)) : cv::Vec2f(-10.f, -10.f);
        }
    }
    return map;
}

cv::Mat remapToFramebuffer(const cv::Mat &picture, const Keystone &k) {
    const cv::Mat src = reducedSource(picture, k).image;
    cv::Mat fb(k.framebuffer, picture.type(), cv::Scalar::all(0));
    cv::remap(src, fb, k.remap, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    return fb;
}

}  // namespace projsurf
