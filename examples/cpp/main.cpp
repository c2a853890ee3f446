// projsurf as a library: read a calibration, get a cloud, find where the projector can show a
// picture upright on a wall, compute the keystone, warp the picture into the framebuffer.
//   projsurf_example CALIB.yaml FRAMEBUFFER.png [CLOUD.pcd|CLOUD.ply]
#include <exception>
#include <iostream>

#include "projsurf/detection.hpp"
#include "projsurf/detector.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/formats.hpp"
#include "projsurf/io/yaml.hpp"
#include "projsurf/keystone.hpp"
#include "synthetic_input.hpp"  // makeWallAndFloor(), makePicture(): when no file is given

int main(int argc, char **argv) {
    if (argc < 3 || argc > 4) {
        std::cerr << "usage: projsurf_example CALIB.yaml FRAMEBUFFER.png [CLOUD.pcd|CLOUD.ply]\n";
        return 2;
    }
    try {
        const projsurf::Projector projector = projsurf::readCalibration(argv[1]);
        // Camera optical frame (x right, y down, z forward), metres; NaN = no reading.
        const projsurf::Cloud cloud = argc == 4 ? projsurf::readCloud(argv[3]) : makeWallAndFloor();

        projsurf::DetectorConfig config;  // defaults commented with units and sources
        config.aspect = 16.0 / 9.0;       // the picture's width / height
        // Gravity in the camera frame, pointing down: the robot's IMU or tf if it has one;
        // here from the floor, with a level camera's [0, 1, 0] as the guess.
        Eigen::Vector3d gravity(0.0, 1.0, 0.0);
        if (const auto floor = projsurf::estimateGravityFromFloor(cloud, gravity)) gravity = floor->gravity;

        projsurf::SurfaceDetector detector(projector, config);  // keep it: it reuses its buffers
        const projsurf::Detection det = detector.detect(cloud, gravity);
        if (!det.found) {
            std::cout << "no surface: " << det.reason << "\n";
            return 0;
        }
        std::cout << "rectangle " << det.rectangle.width << " x " << det.rectangle.height << " m, "
                  << det.rectangle.center().norm() << " m away\n";

        const cv::Mat picture = makePicture();  // any 8-bit image, e.g. from cv::imread
        const projsurf::KeystoneResult keystone = projsurf::computeKeystone(projector, det.rectangle, picture.size());
        if (!keystone.keystone) {
            std::cout << "cannot show it: " << keystone.problem << "\n";
            return 0;
        }
        // Black, of the calibration's resolution, the picture warped into the rectangle.
        const cv::Mat framebuffer = projsurf::warpToFramebuffer(picture, *keystone.keystone);
        projsurf::writeImageAtomic(argv[2], framebuffer);
        std::cout << "framebuffer " << framebuffer.cols << "x" << framebuffer.rows << ", "
                  << cv::countNonZero(framebuffer.reshape(1)) << " lit values -> " << argv[2] << "\n";
    } catch (const projsurf::InputError &e) {
        // The file readers and writers throw InputError for a file or value they cannot use;
        // what() is "<file>: <problem>". The core throws std::invalid_argument only for a call
        // that breaks its contract (a picture of another size than the keystone's). "Nothing
        // found" is no exception: Detection::reason, KeystoneResult::problem.
        std::cerr << "projsurf_example: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "projsurf_example: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
