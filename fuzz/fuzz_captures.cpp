// libFuzzer harness: one image of a calibration capture folder, read as calibrate reads it
// (readImage against the camera's pixels) and given to the step that uses it: a colour
// capture to the disc finder, a depth capture to the lift of the disc centre to 3D.
#include <opencv2/imgcodecs.hpp>

#include "fuzz_common.hpp"
#include "projsurf/calibration/calibration.hpp"
#include "projsurf/io/files/files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    if (size < 1) return 0;
    CameraIntrinsics camera;
    camera.width = 64;
    camera.height = 48;
    camera.fx = camera.fy = 52.5;
    camera.cx = 31.5;
    camera.cy = 23.5;
    const bool depth = (data[0] & 1) != 0;  // first byte: which image of the capture
    const std::string path = fuzz::writeInput(depth ? "capture_0_depth.png" : "capture_0_rgb.png", data + 1, size - 1);
    fuzz::expectOnlyInputErrors([&] {
        const cv::Mat image = readImage(path, depth ? cv::IMREAD_UNCHANGED : cv::IMREAD_COLOR, 64 * 48);
        if (depth) {
            if (image.type() == CV_16UC1 && image.cols == camera.width && image.rows == camera.height)
                (void)liftToDepth(image, camera, Eigen::Vector2d(31.5, 23.5), 4.0);
        } else {
            (void)findDisc(image);
        }
    });
    return 0;
}
