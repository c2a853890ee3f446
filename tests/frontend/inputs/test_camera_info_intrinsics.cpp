// camera_info to a depth image's pinhole (frontend/inputs/camera_info_intrinsics.hpp), the one
// conversion of the node's topics and a bag's messages: the depth's unit named by the encoding
// (REP 118), a focal length that is zero or NaN refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "projsurf/frontend/inputs/camera_info_intrinsics.hpp"
#include "projsurf/io/files/errors.hpp"

using namespace projsurf;
using namespace projsurf::frontend;

namespace {

const std::array<double, 9> kK = {525.0, 0.0, 319.5, 0.0, 526.0, 239.5, 0.0, 0.0, 1.0};

std::string problemOf(const std::array<double, 9> &K, const std::string &encoding) {
    try {
        cameraInfoIntrinsics("camera_info", 640, 480, K, encoding);
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

TEST(FrontendCameraInfo, ReadsKAndSizeWithTheDepthUnitOfTheEncoding) {
    const CameraIntrinsics mm = cameraInfoIntrinsics("camera_info", 640, 480, kK, "16UC1");
    EXPECT_EQ(mm.width, 640);
    EXPECT_EQ(mm.height, 480);
    EXPECT_EQ(mm.fx, 525.0);
    EXPECT_EQ(mm.fy, 526.0);
    EXPECT_EQ(mm.cx, 319.5);
    EXPECT_EQ(mm.cy, 239.5);
    EXPECT_EQ(mm.depth_scale, kRosDepthMillimetres);
    EXPECT_EQ(mm.depth_scale, 1000.0) << "16UC1 is in millimetres (REP 118)";
    EXPECT_EQ(cameraInfoIntrinsics("camera_info", 640, 480, kK, "mono16").depth_scale, 1000.0);
    const CameraIntrinsics m = cameraInfoIntrinsics("camera_info", 640, 480, kK, "32FC1");
    EXPECT_EQ(m.depth_scale, kRosDepthMetres);
    EXPECT_EQ(m.depth_scale, 1.0) << "32FC1 is in metres";
    EXPECT_EQ(m.fx, mm.fx);
}

TEST(FrontendCameraInfo, RefusesAMissingFocalLengthAndOtherEncodings) {
    std::array<double, 9> zero = kK, nan_fy = kK, nan_cx = kK;
    zero[0] = 0.0;  // an uncalibrated driver's all-zero K
    nan_fy[4] = std::nan("");
    nan_cx[2] = std::nan("");
    EXPECT_EQ(problemOf(zero, "16UC1"), "camera_info: has no focal length (fx and fy must be positive)");
    EXPECT_EQ(problemOf(nan_fy, "32FC1"), "camera_info: has no focal length (fx and fy must be positive)");
    EXPECT_EQ(problemOf(nan_cx, "16UC1"), "camera_info: cx and cy must be finite");
    EXPECT_EQ(problemOf(kK, "bgr8"), "camera_info: encoding 'bgr8' (expected 16UC1 in mm or 32FC1 in m)");
    EXPECT_EQ(problemOf(kK, "16UC1"), "");
}

}  // namespace
