// projsurf as a library, end to end: read a calibration, get a cloud, find where the projector
// can show a picture upright on a wall, compute the keystone, warp the picture into the
// projector's framebuffer.
//
//   projsurf_example CALIB.yaml FRAMEBUFFER.png [CLOUD.pcd|CLOUD.ply]
//
// Without a cloud file it makes one: what a level depth camera 0.8 m above the floor sees of a
// wall 2.5 m ahead. CI builds and runs this file against an installed projsurf.
#include <algorithm>
#include <cstdint>
#include <exception>
#include <iostream>

#include <opencv2/core.hpp>

#include "projsurf/core/camera.hpp"
#include "projsurf/core/gravity.hpp"
#include "projsurf/core/keystone.hpp"
#include "projsurf/io/cloud_io.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/yaml_files.hpp"
#include "projsurf/pipeline/detector.hpp"

namespace {

/// An organized cloud (camera frame, metres): a level 640x480 depth camera (525 px focal
/// length), 0.8 m above the floor, 2.5 m from a wall.
projsurf::Cloud makeWallAndFloor() {
    const projsurf::CameraIntrinsics camera;  // 640x480, fx = fy = 525 px, depth in mm
    cv::Mat depth(camera.height, camera.width, CV_16UC1);
    for (int v = 0; v < camera.height; ++v) {
        const double down = (v - camera.cy) / camera.fy;            // the pixel ray's y / z
        const double z = down > 0 ? std::min(2.5, 0.8 / down) : 2.5;  // floor or wall, m
        depth.row(v).setTo(static_cast<std::uint16_t>(z * camera.depth_scale));
    }
    return projsurf::depthToCloud(depth, camera);
}

/// A 16:9 picture of eight colour bars (any 8-bit image will do, e.g. from cv::imread).
cv::Mat makePicture() {
    cv::Mat picture(360, 640, CV_8UC3);
    for (int x = 0; x < picture.cols; ++x) {
        const int bar = x * 8 / picture.cols;
        picture.col(x).setTo(cv::Scalar(bar & 1 ? 255 : 0, bar & 2 ? 255 : 0, bar & 4 ? 255 : 0));
    }
    return picture;
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 3 || argc > 4) {
        std::cerr << "usage: projsurf_example CALIB.yaml FRAMEBUFFER.png [CLOUD.pcd|CLOUD.ply]\n";
        return 2;
    }
    try {
        const projsurf::Projector projector = projsurf::readCalibration(argv[1]);
        const projsurf::Cloud cloud = argc == 4 ? projsurf::readCloud(argv[3]) : makeWallAndFloor();

        // Gravity in the camera frame (pointing down): from the robot's IMU or tf when it has
        // one; here from the floor, with a level camera's [0, 1, 0] as the prior.
        projsurf::DetectorConfig config;  // defaults commented with units and sources
        config.aspect = 16.0 / 9.0;       // the picture's width / height
        if (const auto floor = projsurf::estimateGravityFromFloor(cloud, config.gravity))
            config.gravity = floor->gravity;

        projsurf::SurfaceDetector detector(projector, config);  // keep it: it reuses its buffers
        const projsurf::Detection det = detector.detect(cloud);
        if (!det.found) {
            std::cout << "no surface: " << det.reason << "\n";
            return 0;
        }
        std::cout << "rectangle " << det.rectangle.width << " x " << det.rectangle.height << " m, "
                  << det.rectangle.center().norm() << " m away\n";

        const cv::Mat picture = makePicture();
        const projsurf::KeystoneResult keystone =
            projsurf::computeKeystone(projector, det.rectangle, picture.size());
        if (!keystone.keystone) {
            std::cout << "cannot show it: " << keystone.problem << "\n";
            return 0;
        }
        const cv::Mat framebuffer = projsurf::warpToFramebuffer(picture, *keystone.keystone);
        projsurf::writeImageAtomic(argv[2], framebuffer);  // the calibration's resolution, black around
        std::cout << "framebuffer " << framebuffer.cols << "x" << framebuffer.rows << ", "
                  << cv::countNonZero(framebuffer.reshape(1)) << " lit values -> " << argv[2] << "\n";
    } catch (const projsurf::InputError &e) {
        // The readers and writers throw InputError for a file or value they cannot use; what()
        // is "<file>: <problem>". The core throws std::invalid_argument only for a call that
        // breaks its contract (a picture of another size than the keystone's); "nothing found"
        // is no exception: Detection::reason, KeystoneResult::problem.
        std::cerr << "projsurf_example: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "projsurf_example: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
