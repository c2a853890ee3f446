// Structured-light calibration : Gray-code patterns, decoding, lifting, the fit.
#include <gtest/gtest.h>

#include <cmath>

#include "projsurf/calibration/decoded_points.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/sim/projector_rigs.hpp"

using namespace projsurf;

TEST(StructuredLight, GrayPatternsDecodeEveryFramebufferPixelExactly) {
    // The framebuffer seen by an ideal camera of the same resolution decodes to itself.
    const int w = 100, h = 37;
    const auto patterns = grayPatterns(w, h);
    EXPECT_EQ(patterns.size(), 2u + 2u * (grayBits(w) + grayBits(h)));
    std::vector<cv::Mat> captures;
    for (const auto &p : patterns) captures.push_back(grayPatternImage(p, w, h));
    GrayDecodeConfig cfg;
    cfg.min_bits = 3;
    const GrayDecoding d = decodeGray(captures, w, h, cfg);
    EXPECT_EQ(d.decoded, w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            ASSERT_EQ(d.column.at<double>(y, x), x);
            ASSERT_EQ(d.row.at<double>(y, x), y);
        }
    // A pixel whose finest bit is grey (halfway between a stripe and its inverse) sits on the
    // boundary between two columns.
    for (std::size_t i = 2; i < patterns.size(); ++i)
        if (patterns[i].kind == GrayPattern::Kind::Column && patterns[i].bit == 0) captures[i].at<uchar>(5, 10) = 128;
    const GrayDecoding g = decodeGray(captures, w, h, cfg);
    EXPECT_DOUBLE_EQ(std::abs(g.column.at<double>(5, 10) - 10.0), 0.5);
}

TEST(StructuredLight, DarkOrMissingCapturesDecodeNothing) {
    const int w = 64, h = 40;
    std::vector<cv::Mat> captures(grayPatterns(w, h).size(), cv::Mat(h, w, CV_8UC1, cv::Scalar(30)));
    EXPECT_EQ(decodeGray(captures, w, h).decoded, 0);
    captures.pop_back();
    EXPECT_THROW(decodeGray(captures, w, h), std::invalid_argument);
}

TEST(StructuredLight, FlatSinglePoseAndTooFewPointsAreRefusedWithAdvice) {
    std::vector<ProjectorCorrespondence> flat;
    const Projector p = sim::projectorRig({1.0, 0.0, 1.0, 0.0});
    for (int v = 0; v < 800; v += 10)
        for (int u = 0; u < 1280; u += 10) {
            const Eigen::Vector3d d = p.ray({u, v});
            const double t = (2.0 - p.origin.z()) / d.z();
            flat.push_back({p.origin + t * d, Eigen::Vector2d(u, v)});
        }
    const ProjectorFit f = fitProjector(flat);
    EXPECT_FALSE(f.ok);
    EXPECT_NE(f.problem.find("pose_1"), std::string::npos) << f.problem;
    flat.resize(100);
    const ProjectorFit few = fitProjector(flat);
    EXPECT_FALSE(few.ok);
    EXPECT_NE(few.problem.find("decoded"), std::string::npos) << few.problem;
}

TEST(StructuredLight, ExactCorrespondencesGiveTheTrueModel) {
    const Projector truth = sim::projectorRig({1.33, 2.0, 1.005, -0.05});
    std::vector<ProjectorCorrespondence> pairs;
    for (double depth : {1.5, 2.5, 3.5})
        for (int v = 0; v < 800; v += 16)
            for (int u = 0; u < 1280; u += 16) {
                const Eigen::Vector3d d = truth.ray({u, v});
                pairs.push_back({truth.origin + depth / d.z() * d, Eigen::Vector2d(u, v)});
            }
    const ProjectorFit f = fitProjector(pairs);
    ASSERT_TRUE(f.ok) << f.problem;
    EXPECT_LT(f.rms_px, 0.01);
    EXPECT_LT((f.projector.origin - truth.origin).norm(), 1e-4);
    EXPECT_NEAR(f.projector.cy(), truth.cy(), 0.1);
    EXPECT_NEAR(f.projector.distortion[0], -0.05, 1e-3);
}

TEST(StructuredLight, SimulatedCapturesCalibrateAnOffsetProjector) {
    const Projector truth = sim::projectorRig({1.0, 1.0, 1.0, 0.0});
    const sim::SensorModel sensor;
    for (const auto &poses : {sim::flatWallPoses(), sim::reliefPose()}) {
        const ProjectorFit f = sim::structuredCalibration(truth, sensor, poses, 3);
        ASSERT_TRUE(f.ok) << f.problem;
        std::printf("poses %zu: %zu points, rms %.3f px, origin error %.1f mm, cy %.2f (true %.2f), relief %.3f m\n",
                    poses.size(), f.points, f.rms_px, (f.projector.origin - truth.origin).norm() * 1000,
                    f.projector.cy(), truth.cy(), f.relief_m);
        EXPECT_LT((f.projector.origin - truth.origin).norm(), 0.005);
        EXPECT_NEAR(f.projector.cy(), truth.cy(), 4.0);
    }
}
