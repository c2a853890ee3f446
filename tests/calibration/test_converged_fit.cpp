// Fits that run to convergence (issue 37): OpenCV's calibrations with explicit criteria and
// their iterations counted, the cap reported when a fit stops on it, the leave-one-pose-out
// spread, and the structured-light fit's stages.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <opencv2/calib3d.hpp>

#include "projsurf/calibration/converged_fit.hpp"
#include "projsurf/calibration/pose_spread.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/calibration/stereo_fit.hpp"

using namespace projsurf;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A projector like procam-calibration's (1024 x 768, the picture thrown above the lens axis:
/// cy beyond the bottom edge) and a camera beside it, five poses of a 9 x 7 board of 75 mm
/// squares about 2.2 m away, turned by up to 25 deg. Corners exact, or with Gaussian noise.
struct Rig {
    cv::Matx33d kp{1895.0, 0, 484.0, 0, 1896.0, 850.0, 0, 0, 1};
    cv::Matx33d kc{3450.0, 0, 590.0, 0, 3450.0, 520.0, 0, 0, 1};
    cv::Matx33d r_pc;                       ///< projector from camera
    cv::Vec3d t_pc{0.09, -0.62, -0.24};     ///< m
    std::vector<StereoView> views;
};

Rig makeRig(double noise_px, unsigned seed) {
    Rig rig;
    cv::Mat r;
    cv::Rodrigues(cv::Vec3d(0.08, -0.06, 0.01), r);
    rig.r_pc = cv::Matx33d(r);
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, noise_px);
    const double tilt[5][3] = {{0.0, 0.0, 0.0}, {20, 0, 5}, {-18, 8, -3}, {5, -25, 2}, {-8, 20, -6}};
    for (const auto &t : tilt) {
        StereoView v;
        cv::Mat rb;
        cv::Rodrigues(cv::Vec3d(t[0], t[1], t[2]) * (kPi / 180), rb);
        const cv::Matx33d rot(rb);
        const cv::Vec3d pos(-0.3 + 0.002 * t[1], -0.2 + 0.002 * t[0], 2.2);  // camera frame, board origin
        for (int j = 0; j < 7; ++j)
            for (int i = 0; i < 9; ++i) {
                const cv::Vec3d b(i * 0.075, j * 0.075, 0);
                const cv::Vec3d pc = rot * b + pos, pp = rig.r_pc * pc + rig.t_pc;
                const cv::Vec3d uc = rig.kc * pc, up = rig.kp * pp;
                v.board.emplace_back(static_cast<float>(b[0]), static_cast<float>(b[1]), 0.f);
                v.camera.emplace_back(static_cast<float>(uc[0] / uc[2] + n(rng)), static_cast<float>(uc[1] / uc[2] + n(rng)));
                v.projector.emplace_back(static_cast<float>(up[0] / up[2] + n(rng)),
                                         static_cast<float>(up[1] / up[2] + n(rng)));
            }
        rig.views.push_back(v);
    }
    return rig;
}

std::vector<std::vector<cv::Point3f>> boards(const Rig &rig) {
    std::vector<std::vector<cv::Point3f>> out;
    for (const auto &v : rig.views) out.push_back(v.board);
    return out;
}

std::vector<std::vector<cv::Point2f>> projectorCorners(const Rig &rig) {
    std::vector<std::vector<cv::Point2f>> out;
    for (const auto &v : rig.views) out.push_back(v.projector);
    return out;
}

}  // namespace

// OpenCV's default (30 iterations) leaves this projector's principal point far from where its
// own fit ends; run to convergence, the fit finds the true projector, and says how many
// iterations that took. Capped at 30, it says it stopped on its cap and warns.
TEST(ConvergedFit, ThirtyIterationsDoNotConvergeTheProjectorTheConvergedFitIsRight) {
    const Rig rig = makeRig(0.0, 1);
    const cv::Size size(1024, 768);
    const int flags = cv::CALIB_ZERO_TANGENT_DIST;
    cv::Mat k, d;
    std::vector<cv::Mat> rv, tv;
    cv::calibrateCamera(boards(rig), projectorCorners(rig), size, k, d, rv, tv, flags);  // OpenCV's default criteria
    const double default_cy_error = std::abs(k.at<double>(1, 2) - 850.0);

    const CameraCalibration c = calibrateCameraConverged(boards(rig), projectorCorners(rig), size, flags, {}, "projector");
    EXPECT_NEAR(c.camera_matrix.at<double>(0, 0), 1895.0, 0.5);
    EXPECT_NEAR(c.camera_matrix.at<double>(0, 2), 484.0, 0.5);
    EXPECT_NEAR(c.camera_matrix.at<double>(1, 2), 850.0, 0.5);
    EXPECT_LT(c.rms_px, 1e-3);
    EXPECT_GT(c.convergence.iterations, 30) << describeConvergence(c.convergence);
    EXPECT_FALSE(c.convergence.on_cap);
    EXPECT_TRUE(convergenceWarning(c.convergence).empty());
    EXPECT_GT(default_cy_error, 5.0) << "OpenCV's default criteria converged here: the test shows nothing";

    LmCriteria thirty;
    thirty.max_iterations = 30;
    const CameraCalibration capped = calibrateCameraConverged(boards(rig), projectorCorners(rig), size, flags, thirty, "projector");
    EXPECT_TRUE(capped.convergence.on_cap);
    EXPECT_EQ(capped.convergence.iterations, 30);
    EXPECT_GT(capped.convergence.last_step_px, 0.0);
    EXPECT_NE(convergenceWarning(capped.convergence).find("iteration cap (30)"), std::string::npos);
    // The capped run is OpenCV's 30th iterate: the same numbers as the default criteria give.
    EXPECT_NEAR(capped.camera_matrix.at<double>(1, 2), k.at<double>(1, 2), 1e-6);

    // Without counting, one more run at cap - 1 still tells a fit on its cap from a converged one.
    thirty.count = false;
    EXPECT_TRUE(calibrateCameraConverged(boards(rig), projectorCorners(rig), size, flags, thirty, "p").convergence.on_cap);
    LmCriteria quick;
    quick.count = false;
    EXPECT_FALSE(calibrateCameraConverged(boards(rig), projectorCorners(rig), size, flags, quick, "p").convergence.on_cap);
}

// The whole chessboard fit: each step converged and reported, the pair's pose right, and each
// pose left out once (with noise, the spread is small but not zero).
TEST(ConvergedFit, StereoFitConvergesAndReportsTheLeaveOnePoseOutSpread) {
    const Rig rig = makeRig(0.1, 2);
    const StereoFit f = fitStereo(rig.views, cv::Size(1280, 1024), cv::Size(1024, 768));
    ASSERT_TRUE(f.ok) << f.problem;
    EXPECT_NEAR(f.projector.fx, 1895.0, 0.01 * 1895.0);
    EXPECT_NEAR(f.projector.cy, 850.0, 15.0);
    EXPECT_NEAR(f.projector.cx, 484.0, 15.0);
    const cv::Matx33d d = f.rotation * rig.r_pc.t();
    EXPECT_LT(std::acos(std::min(1.0, 0.5 * (cv::trace(d) - 1))) * 180 / kPi, 0.3);
    ASSERT_EQ(f.convergence.size(), 3u);
    for (const auto &c : f.convergence) {
        EXPECT_GT(c.iterations, 0) << c.fit;
        EXPECT_FALSE(c.on_cap) << describeConvergence(c);
    }
    EXPECT_EQ(f.spread.poses, 5);
    EXPECT_EQ(f.spread.failed, 0);
    EXPECT_EQ(f.spread.on_cap, 0);
    EXPECT_GT(f.spread.cy_px, 0.0);
    EXPECT_LT(f.spread.cy_px, 30.0);
    EXPECT_GT(f.spread.rotation_deg, 0.0);
    EXPECT_GT(f.spread.se_cx_px, 0.0);
    EXPECT_NE(describeSpread(f.spread).find("5 poses"), std::string::npos);
    // Too few poses to leave one out: not measured, no warning.
    const StereoFit two = fitStereo({rig.views[0], rig.views[1]}, cv::Size(1280, 1024), cv::Size(1024, 768));
    EXPECT_EQ(two.spread.poses, 0);
}

TEST(ConvergedFit, LargeSpreadIsWarnedAbout) {
    PoseSpread s;
    s.poses = 5;
    s.cx_px = 12;
    s.cy_px = 36;
    s.rotation_deg = 0.7;
    s.translation_dir_deg = 2.9;
    const std::string w = spreadWarning(s);
    EXPECT_NE(w.find("principal point 36.0 px"), std::string::npos) << w;
    EXPECT_NE(w.find("translation direction 2.90 deg"), std::string::npos) << w;
    EXPECT_EQ(w.find("rotation"), std::string::npos) << w;
    s.cy_px = 20;
    s.translation_dir_deg = 1.0;
    EXPECT_TRUE(spreadWarning(s).empty());
}

// The structured-light fit's Levenberg-Marquardt stages: each converged and counted; a cap too
// small is reported as such.
TEST(ConvergedFit, StructuredLightStagesReportTheirIterations) {
    Projector truth;
    truth.width = 1280;
    truth.height = 800;
    truth.intrinsics = ProjectorIntrinsics{1790.0, 1800.0, 640.0, 880.0};
    truth.origin = Eigen::Vector3d(0.05, 0.12, 0.0);
    truth.setRotation(Eigen::Matrix3d::Identity());
    std::vector<std::vector<ProjectorCorrespondence>> poses(3);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 4000; ++i) {
            const double z = 1.5 + 0.6 * k + 0.3 * u(rng);
            const Eigen::Vector3d p(-0.8 + 1.6 * u(rng), -0.6 + 1.0 * u(rng), z);
            const Eigen::Vector3d q = p - truth.origin;
            const Eigen::Vector2d px(640.0 + 1790.0 * q.x() / q.z(), 880.0 + 1800.0 * q.y() / q.z());
            if (px.x() < 0 || px.y() < 0 || px.x() > 1279 || px.y() > 799) continue;
            poses[k].push_back({p, px});
        }
    const ProjectorFit f = fitProjectorPoses(poses);
    ASSERT_TRUE(f.ok) << f.problem;
    EXPECT_NEAR(f.projector.cy(), 880.0, 0.5);
    ASSERT_EQ(f.convergence.size(), 3u);
    for (const auto &c : f.convergence) {
        EXPECT_GT(c.iterations, 0) << c.fit;
        EXPECT_FALSE(c.on_cap) << c.fit;
    }
    EXPECT_EQ(f.spread.poses, 3);
    EXPECT_LT(f.spread.cy_px, 1.0);
    EXPECT_TRUE(projectorFitWarnings(f).empty());
    ProjectorFitConfig tight;
    tight.max_iterations = 2;
    std::vector<ProjectorCorrespondence> all;
    for (const auto &p : poses) all.insert(all.end(), p.begin(), p.end());
    const ProjectorFit capped = fitProjector(all, tight);
    ASSERT_FALSE(capped.convergence.empty());
    EXPECT_TRUE(capped.convergence[0].on_cap);
    EXPECT_FALSE(projectorFitWarnings(capped).empty());
}
