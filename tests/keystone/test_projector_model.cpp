// The full projector model : intrinsics with a lens offset, roll, distortion; the
// optional calibration keys; and the keystone with it against the paper's model.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "projsurf/keystone/keystone.hpp"
#include "projsurf/keystone/keystone_remap.hpp"
#include "projsurf/keystone/keystone_warper.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "eval/paper/experiments.hpp"
#include "eval/realistic/projector_eval.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/sim/scenes/scene.hpp"

using namespace projsurf::eval;  // the evaluation under test

using namespace projsurf;

namespace {

std::string tmpFile(const std::string &name, const std::string &text) {
    const auto dir = std::filesystem::temp_directory_path() / "projector_model_tests";
    std::filesystem::create_directories(dir);
    const auto path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
}

/// A 4 m x 3 m wall whose centre is `distance` m ahead, turned `yaw_deg` about the vertical.
struct WallRig {
    sim::Scene scene;
    Plane plane;
    explicit WallRig(double distance, double yaw_deg) {
        const double a = yaw_deg * M_PI / 180.0;
        const Eigen::Vector3d right(std::cos(a), 0, std::sin(a)), up(0, -1, 0);
        const Eigen::Vector3d centre(0, 0, distance);
        sim::addWall(scene, centre - 2.0 * right - 1.5 * up, right, up, 4.0, 3.0, {}, cv::Vec3f(0.8f, 0.8f, 0.8f),
                     "wall", 0);
        const Eigen::Vector3d n = right.cross(up).normalized();
        plane = makePlane(n, -n.dot(centre));
    }
    /// An upright rectangle of the framebuffer's aspect, `width` m wide, centred where the
    /// projector's centre pixel lands.
    Rectangle rectangle(const Projector &real, double width) const {
        const auto hit = intersectRay(plane, real.origin, real.ray({0.5 * (real.width - 1), 0.5 * (real.height - 1)}));
        const PlaneFrame frame = makePlaneFrame(plane, Eigen::Vector3d(0, 1, 0), *hit);
        const double h = width / real.aspect();
        return makeRectangle(frame, {-0.5 * width, -0.5 * h}, {0.5 * width, 0.5 * h});
    }
};

double roundTripError(const Projector &p) {
    double worst = 0.0;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.5, p.width - 0.5), v(-0.5, p.height - 0.5), t(0.5, 4.0);
    for (int i = 0; i < 500; ++i) {
        const Eigen::Vector2d px(u(rng), v(rng));
        const auto back = p.toPixel(p.origin + t(rng) * p.ray(px));
        if (!back) return HUGE_VAL;
        worst = std::max(worst, (*back - px).norm());
    }
    return worst;
}

}  // namespace

TEST(ProjectorModel, RayAndToPixelAreInverseWithOffsetRollAndDistortion) {
    for (const auto &spec : sim::evalRigs()) {
        const Projector p = sim::projectorRig(spec);
        ASSERT_TRUE(isValidProjector(p)) << spec.name();
        EXPECT_LT(roundTripError(p), 1e-6) << spec.name();
    }
    // Stronger barrel and pincushion with tangential terms.
    Projector p = sim::projectorRig({1.0, 2.0, 1.0, -0.2});
    p.distortion = {-0.2, 0.05, 0.002, -0.001, 0.0};
    EXPECT_LT(roundTripError(p), 1e-6);
    p.distortion = {0.2, 0.0, 0.0, 0.0, 0.01};
    EXPECT_LT(roundTripError(p), 1e-6);
}

TEST(ProjectorModel, OffsetMovesThePrincipalPointAndRollTurnsTheImageAxes) {
    const Projector p = sim::projectorRig({1.0, 3.0, 1.0, 0.0});
    EXPECT_NEAR(p.cy(), 399.5 + 400.0, 1e-12);
    // The picture is above the lens axis: the axis meets the framebuffer's bottom edge.
    const auto on_axis = p.toPixel(p.origin + 2.0 * p.axis());
    ASSERT_TRUE(on_axis);
    EXPECT_NEAR(on_axis->y(), 799.5, 1e-9);
    // The centre pixel's ray is the example projector's axis.
    EXPECT_LT((p.ray({639.5, 399.5}) - sim::exampleProjector().axis()).norm(), 1e-12);
    // Roll: image right is no longer horizontal in the camera frame.
    EXPECT_NEAR(std::asin(std::abs(p.right().y())) * 180 / M_PI, 3.0, 0.1);
    EXPECT_NEAR((p.rotation->transpose() * *p.rotation - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
}

TEST(ProjectorModel, WithoutTheOptionalFieldsNothingChanges) {
    Projector p = sim::exampleProjector();
    EXPECT_FALSE(p.fullModel());
    // The same pinhole written out through the full model gives the same pixels.
    Projector full = p;
    full.intrinsics = ProjectorIntrinsics{p.fx(), p.fy(), p.cx(), p.cy()};
    Eigen::Matrix3d r;
    r << p.right(), p.down(), p.axis();
    full.setRotation(r);
    for (const Eigen::Vector3d &q : {Eigen::Vector3d(0.3, -0.2, 2.0), Eigen::Vector3d(-0.5, 0.1, 3.5)}) {
        EXPECT_LT((*full.toPixel(q) - *p.toPixel(q)).norm(), 1e-9);
        EXPECT_LT((*pixelFromWorkspace(p, q) - *p.toPixel(q)).norm(), 1e-9);
    }
    // An old-key file reads as before and writes back the same keys only.
    const std::string path = tmpFile("old.yaml",
                                     "projector:\n  resolution: [1280, 800]\n  fov_deg: [39.3, 24.0]\n  axis:\n"
                                     "    origin: [0.0, 0.12, 0.0]\n    direction: [0.0, -0.05, 1.0]\n");
    const Projector read = readCalibration(path);
    EXPECT_FALSE(read.fullModel());
    EXPECT_EQ(read.fx(), p.fx());
    EXPECT_EQ(read.cx(), 639.5);
    EXPECT_EQ(read.toPixel({0.3, -0.2, 2.0})->x(), p.toPixel({0.3, -0.2, 2.0})->x());
    const YAML::Node n = calibrationNode(read);
    EXPECT_FALSE(n["intrinsics"]);
    EXPECT_FALSE(n["rotation"]);
    EXPECT_FALSE(n["distortion"]);
}

TEST(ProjectorModel, FullModelKeysRoundTripAndBadRotationsAreRefused) {
    const Projector p = sim::projectorRig({1.33, -2.0, 1.005, 0.05});
    const auto dir = std::filesystem::temp_directory_path() / "projector_model_tests";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "full.yaml").string();
    writeCalibration(path, p);
    const Projector back = readCalibration(path);
    ASSERT_TRUE(back.fullModel());
    EXPECT_NEAR(back.fx(), p.fx(), 1e-6);
    EXPECT_NEAR(back.fy(), p.fy(), 1e-6);
    EXPECT_NEAR(back.cy(), p.cy(), 1e-6);
    EXPECT_NEAR(back.distortion[0], 0.05, 1e-9);
    for (const Eigen::Vector3d &q : {Eigen::Vector3d(0.3, -0.4, 2.0), Eigen::Vector3d(-0.5, -0.9, 3.5)})
        EXPECT_LT((*back.toPixel(q) - *p.toPixel(q)).norm(), 1e-4);
    // fov_deg follows from the intrinsics.
    const auto fov = fieldOfView(p);
    EXPECT_NEAR(back.fov_h, fov[0], 1e-6);
    EXPECT_NEAR(back.fov_v, fov[1], 1e-6);

    const std::string head =
        "projector:\n  resolution: [1280, 800]\n  fov_deg: [39.3, 24.0]\n  axis:\n"
        "    origin: [0.0, 0.12, 0.0]\n    direction: [0.0, 0.0, 1.0]\n";
    const std::string ok_rot = "  rotation:\n    - [1, 0, 0]\n    - [0, 1, 0]\n    - [0, 0, 1]\n";
    EXPECT_NO_THROW(readCalibration(tmpFile("rot_ok.yaml", head + ok_rot)));
    EXPECT_THROW(readCalibration(tmpFile("rot_scaled.yaml", head + "  rotation:\n    - [1.01, 0, 0]\n    - [0, 1, 0]\n"
                                                                   "    - [0, 0, 1]\n")),
                 InputError);
    EXPECT_THROW(readCalibration(tmpFile("rot_mirror.yaml", head + "  rotation:\n    - [-1, 0, 0]\n    - [0, 1, 0]\n"
                                                                   "    - [0, 0, 1]\n")),
                 InputError);
    const double c = std::cos(M_PI / 180), s = std::sin(M_PI / 180);  // 1 deg yaw: third column off the axis
    EXPECT_THROW(readCalibration(tmpFile("rot_off.yaml", head + "  rotation:\n    - [" + std::to_string(c) + ", 0, " +
                                                             std::to_string(s) + "]\n    - [0, 1, 0]\n    - [" +
                                                             std::to_string(-s) + ", 0, " + std::to_string(c) + "]\n")),
                 InputError);
    EXPECT_THROW(readCalibration(tmpFile("dist_short.yaml", head + "  distortion: [0.1, 0]\n")), InputError);
    EXPECT_THROW(
        readCalibration(tmpFile("intr_bad.yaml", head + "  intrinsics: {fx: -5, fy: 1800, cx: 639.5, cy: 799.5}\n")),
        InputError);
}

TEST(ProjectorModel, OffsetProjectorCorrectedWithTheFullModelIsARectangle) {
    const cv::Size picture(1280, 800);
    for (const double yaw : {0.0, 25.0}) {
        const WallRig wall(2.0, yaw);
        for (const auto &spec : {sim::RigSpec{1.0, 0.0, 1.0, 0.0}, sim::RigSpec{1.33, 2.0, 1.005, -0.05}}) {
            const Projector real = sim::projectorRig(spec);
            const Rectangle rect = wall.rectangle(real, 0.8);
            const eval::WallPicture full = eval::pictureOnWall(real, real, wall.scene, rect, picture);
            ASSERT_TRUE(full.ok) << full.problem;
            EXPECT_LT(full.errors.worst_pct(), 0.2) << spec.name() << " yaw " << yaw;
            // The corners land on the rectangle (letterboxed: same aspect, so the same corners).
            for (int i = 0; i < 4; ++i) EXPECT_LT((full.corners[i] - rect.corners[i]).norm(), 1e-3);
            // The paper's model of the same projector: a visibly trapezoidal picture.
            const eval::WallPicture paper =
                eval::pictureOnWall(sim::paperModelOf(real), real, wall.scene, rect, picture, 1e9);
            ASSERT_TRUE(paper.ok) << paper.problem;
            EXPECT_GT(paper.errors.worst_pct(), 3.0) << spec.name() << " yaw " << yaw;
            if (spec.offset == 1.0 && yaw == 0.0) {
                // The worked figure is about 4.9 %; with the paper model's field of view
                // taken as the framebuffer's true span it comes out a little larger.
                EXPECT_NEAR(paper.errors.horizontal_pct, 5.2, 0.8);
            }
        }
    }
}

TEST(ProjectorModel, DistortedKeystoneIsARemapThatShowsTheWholePicture) {
    const Projector real = sim::projectorRig({1.0, 0.0, 1.0, -0.05});
    const WallRig wall(2.0, 15.0);
    const Rectangle rect = wall.rectangle(real, 0.8);
    const auto k = computeKeystone(real, rect, cv::Size(320, 200));
    ASSERT_TRUE(k.keystone) << k.problem;
    ASSERT_FALSE(k.keystone->remap.empty());
    cv::Mat pic(200, 320, CV_8UC3, cv::Scalar(255, 255, 255));
    const cv::Mat fb = warpToFramebuffer(pic, *k.keystone);
    ASSERT_EQ(fb.size(), cv::Size(1280, 800));
    // Each lit framebuffer pixel lands inside the rectangle on the wall, and the picture's
    // corners' pixels are lit.
    int lit = 0, outside = 0;
    const PlaneFrame frame = makePlaneFrame(wall.plane, Eigen::Vector3d(0, 1, 0), rect.center());
    const Eigen::Vector2d lo = frame.toPlane(rect.corners[3]), hi = frame.toPlane(rect.corners[1]);
    for (int v = 0; v < fb.rows; v += 4)
        for (int u = 0; u < fb.cols; u += 4) {
            if (fb.at<cv::Vec3b>(v, u)[0] < 128) continue;
            ++lit;
            const auto hit = castToWall(real, Eigen::Vector2d(u, v), wall.plane);
            ASSERT_TRUE(hit);
            const Eigen::Vector2d uv = frame.toPlane(*hit);
            if (uv.x() < lo.x() - 0.003 || uv.x() > hi.x() + 0.003 || uv.y() < lo.y() - 0.003 ||
                uv.y() > hi.y() + 0.003)
                ++outside;
        }
    EXPECT_GT(lit, 1000);
    EXPECT_EQ(outside, 0);
    for (const auto &c : k.keystone->picture_px) {
        const int u = std::clamp(static_cast<int>(std::lround(c.x())), 1, 1278),
                  v = std::clamp(static_cast<int>(std::lround(c.y())), 1, 798);
        int near_lit = 0;
        for (int dv = -2; dv <= 2; ++dv)
            for (int du = -2; du <= 2; ++du)
                near_lit += fb.at<cv::Vec3b>(std::clamp(v + dv, 0, 799), std::clamp(u + du, 0, 1279))[0] > 128;
        EXPECT_GT(near_lit, 0);
    }
    // The warper class gives the same framebuffer.
    KeystoneWarper warper(*k.keystone);
    EXPECT_EQ(cv::norm(warper.warp(pic), fb, cv::NORM_INF), 0.0);
}

TEST(ProjectorModel, FootprintRaysStayInsideTheLitArea) {
    for (const double k1 : {-0.05, 0.05}) {
        const Projector p = sim::projectorRig({1.0, 1.0, 1.0, k1});
        for (const auto &ray : p.footprintRays()) {
            const auto px = p.toPixel(p.origin + 2.0 * ray);
            ASSERT_TRUE(px);
            EXPECT_GE(px->x(), -0.5 - 1e-6);
            EXPECT_LE(px->x(), p.width - 0.5 + 1e-6);
            EXPECT_GE(px->y(), -0.5 - 1e-6);
            EXPECT_LE(px->y(), p.height - 0.5 + 1e-6);
        }
    }
}

TEST(ProjectorModel, EvalScoreSeparatesTheTrueModelFromThePapersModel) {
    const Projector truth = sim::projectorRig({1.0, 2.0, 1.005, -0.05});
    const sim::SensorModel sensor;
    const eval::CalibrationScore exact = eval::scoreCalibration(truth, truth, sensor, 4);
    ASSERT_TRUE(exact.ok) << exact.problem;
    EXPECT_LT(exact.rms_px, 1e-6);
    EXPECT_LT(exact.eq8_pct, 0.2);
    EXPECT_LT(exact.upright_deg, 0.1);
    EXPECT_LT(exact.corner_mm, 5.0);
    const eval::CalibrationScore paper = eval::scoreCalibration(sim::paperModelOf(truth), truth, sensor, 4);
    EXPECT_GT(paper.rms_px, 5.0);
    EXPECT_GT(paper.upright_deg, 1.0);
}

TEST(ProjectorModel, DirectionsBeyondTheLensFoldAreNotLit) {
    Projector p = sim::projectorRig({0.0, 0.0, 1.0, -0.05});
    // r = tan(angle); r (1 + k1 r^2) peaks at r = 1 / sqrt(3 * 0.05) = 2.58 (69 deg).
    const Eigen::Vector3d wide =
        p.origin + std::cos(80 * M_PI / 180) * p.axis() + std::sin(80 * M_PI / 180) * p.right();
    EXPECT_FALSE(p.toPixel(wide).has_value());
    const Eigen::Vector3d inside =
        p.origin + std::cos(15 * M_PI / 180) * p.axis() + std::sin(15 * M_PI / 180) * p.right();
    EXPECT_TRUE(p.toPixel(inside).has_value());
}
