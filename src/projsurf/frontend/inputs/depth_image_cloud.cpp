#include "projsurf/frontend/inputs/depth_image_cloud.hpp"

#include <cmath>
#include <limits>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/types/lens_model_check.hpp"

namespace projsurf::frontend {

CameraIntrinsics pinholeCamera(const std::string &what, int width, int height, double fx, double fy, double cx,
                               double cy, double depth_scale) {
    if (!(fx > 0 && fy > 0 && std::isfinite(fx) && std::isfinite(fy)))
        throw InputError(what, "has no focal length (fx and fy must be positive)");
    if (!(std::isfinite(cx) && std::isfinite(cy))) throw InputError(what, "cx and cy must be finite");
    if (!(depth_scale > 0 && std::isfinite(depth_scale))) throw InputError(what, "depth_scale must be positive");
    CameraIntrinsics cam;
    cam.width = width;
    cam.height = height;
    cam.fx = fx;
    cam.fy = fy;
    cam.cx = cx;
    cam.cy = cy;
    cam.depth_scale = depth_scale;
    if (const std::string problem = cameraModelProblem(cam); !problem.empty()) throw InputError(what, problem);
    return cam;
}

Cloud depthImageToCloud(const std::string &what, const cv::Mat &depth, const CameraIntrinsics &camera) {
    if (depth.cols != camera.width || depth.rows != camera.height)
        throw InputError(what, "image is " + std::to_string(depth.cols) + "x" + std::to_string(depth.rows) +
                                   ", the camera's is " + std::to_string(camera.width) + "x" +
                                   std::to_string(camera.height));
    if (depth.type() == CV_16UC1) return depthToCloud(depth, camera);
    if (depth.type() != CV_32FC1)
        throw InputError(what, "expected a 16-bit depth image (depth_scale units per metre) or 32-bit float metres");
    Cloud cloud;
    cloud.width = depth.cols;
    cloud.height = depth.rows;
    cloud.points.resize(static_cast<std::size_t>(depth.cols) * depth.rows);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int v = 0; v < depth.rows; ++v) {
        const float *row = depth.ptr<float>(v);
        for (int u = 0; u < depth.cols; ++u) {
            const double z = row[u];
            Point &p = cloud.points[static_cast<std::size_t>(v) * depth.cols + u];
            if (z > 0.0 && std::isfinite(z))
                p = camera.backProject(u, v, z).cast<float>();
            else
                p = Point(nan, nan, nan);
        }
    }
    return cloud;
}

}  // namespace projsurf::frontend
