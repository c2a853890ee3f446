// Projector calibration (paper 3.1): disc centroid, lift to 3-D, axis fit, refusals, and the
// end-to-end round trip (estimated calibration + noisy cloud) measured with eq. (8).
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <random>

#include "projsurf/calibration/calibration.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/sim/calibration_captures.hpp"
#include "synthetic_rig.hpp"

using namespace projsurf;

namespace {

/// Calibrates from noisy synthetic captures of `truth` (seeded); asserts success.
Calibration calibrateSynthetic(const Projector &truth, unsigned seed) {
    const CameraIntrinsics cam;
    std::mt19937 rng(seed);
    std::vector<CaptureImages> caps;
    for (const Plane &w : rig::calibrationWalls()) caps.push_back(rig::renderCapture(truth, w, cam, rng));
    return calibrateProjector(caps, cam);
}

}  // namespace

TEST(CalibrationDisc, CentroidOfANoisyDiscWithSpecks) {
    cv::Mat img(480, 640, CV_8UC3, cv::Scalar(15, 15, 15));
    std::mt19937 rng(1);
    cv::Mat noise(img.size(), CV_8UC3);
    cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(6));
    // A disc drawn with sub-pixel precision (shift = 4 bits) and antialiasing.
    const Eigen::Vector2d c(203.3125, 151.6875);
    cv::circle(img, cv::Point(static_cast<int>(c.x() * 16), static_cast<int>(c.y() * 16)), 30 * 16,
               cv::Scalar(230, 230, 230), -1, cv::LINE_AA, 4);
    // Small bright specks the opening must remove, and a thin bright line.
    cv::circle(img, cv::Point(500, 400), 1, cv::Scalar(255, 255, 255), -1);
    cv::circle(img, cv::Point(60, 50), 1, cv::Scalar(255, 255, 255), -1);
    cv::line(img, cv::Point(400, 40), cv::Point(600, 42), cv::Scalar(255, 255, 255), 1);
    img += noise;
    const auto d = findDisc(img);
    ASSERT_TRUE(d);
    EXPECT_LT((d->centroid - c).norm(), 0.25);
    EXPECT_NEAR(d->radius_px, 30.0, 1.5);
    EXPECT_GT(d->circularity, 0.8);
    EXPECT_EQ(d->candidates, 1);

    // Nothing bright: no disc.
    EXPECT_FALSE(findDisc(cv::Mat(480, 640, CV_8UC3, cv::Scalar(20, 20, 20))));
    EXPECT_FALSE(findDisc(cv::Mat()));
    // A dim disc is missed at the paper's threshold (50) and found with a lower one.
    cv::Mat dim(480, 640, CV_8UC1, cv::Scalar(10));
    cv::circle(dim, cv::Point(320, 240), 25, cv::Scalar(40), -1);
    EXPECT_FALSE(findDisc(dim));
    DiscConfig low;
    low.threshold = 25;
    const auto found = findDisc(dim, low);
    ASSERT_TRUE(found);
    EXPECT_LT((found->centroid - Eigen::Vector2d(320, 240)).norm(), 0.2);
    // Of two bright blobs the larger round one wins.
    cv::Mat two(480, 640, CV_8UC1, cv::Scalar(0));
    cv::circle(two, cv::Point(100, 100), 10, cv::Scalar(255), -1);
    cv::circle(two, cv::Point(400, 300), 35, cv::Scalar(255), -1);
    const auto big = findDisc(two);
    ASSERT_TRUE(big);
    EXPECT_LT((big->centroid - Eigen::Vector2d(400, 300)).norm(), 0.2);
    EXPECT_EQ(big->candidates, 2);
    // A disc cut by the image border is not used: its centroid is not the disc's centre.
    cv::Mat cut(480, 640, CV_8UC1, cv::Scalar(0));
    cv::circle(cut, cv::Point(630, 240), 30, cv::Scalar(255), -1);
    int at_border = 0;
    EXPECT_FALSE(findDisc(cut, DiscConfig{}, &at_border));
    EXPECT_EQ(at_border, 1);
}

TEST(CalibrationLift, ObliqueNoisyWallWithHoles) {
    const CameraIntrinsics cam;
    const Plane w = rig::wall(2.5, 30.0);
    std::mt19937 rng(5);
    std::normal_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    cv::Mat depth(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            const auto hit = intersectRay(w, Eigen::Vector3d::Zero(), cam.backProject(u, v, 1.0));
            if (uni(rng) < 0.3) continue;  // holes
            double z = hit->z() + rig::kinectSigma(hit->z()) * unit(rng);
            if (uni(rng) < 0.03) z += 0.5;  // flying pixels / outliers
            depth.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(std::lround(z * 1000));
        }
    // The disc area itself reads nothing.
    const Eigen::Vector2d px(350.25, 210.75);
    cv::circle(depth, cv::Point(350, 211), 12, cv::Scalar(0), -1);
    const auto lifted = liftToDepth(depth, cam, px, 12.0);
    ASSERT_TRUE(lifted.point);
    const auto truth = intersectRay(w, Eigen::Vector3d::Zero(), cam.backProject(px.x(), px.y(), 1.0));
    EXPECT_LT((*lifted.point - *truth).norm(), 0.004) << "at " << truth->transpose();
    EXPECT_GT(lifted.valid_points, 200);
    EXPECT_LT(lifted.inliers, lifted.valid_points);  // the outliers were rejected

    // No depth at all around the disc: refused.
    cv::Mat empty(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    EXPECT_FALSE(liftToDepth(empty, cam, px, 12.0).point);
    // Wrong type: refused, not a crash.
    EXPECT_FALSE(liftToDepth(cv::Mat(cam.height, cam.width, CV_8UC1, cv::Scalar(3)), cam, px, 12.0).point);
}

TEST(CalibrationAxis, LineFitDirectionOriginAndResiduals) {
    const Eigen::Vector3d o(0.05, 0.1, 0.0), d = Eigen::Vector3d(0.1, -0.05, 1.0).normalized();
    std::vector<Eigen::Vector3d> pts;
    for (double t : {1.0, 1.6, 2.2, 2.9}) pts.push_back(o + t * d);
    pts[1].x() += 0.002;  // one point off the line by 2 mm
    const auto fit = fitAxisLine(pts);
    ASSERT_TRUE(fit);
    EXPECT_LT(angleBetweenDeg(fit->direction, d), 0.1);
    EXPECT_GT(fit->direction.z(), 0.0);
    EXPECT_NEAR(fit->origin.z(), 0.0, 1e-12);
    EXPECT_LT((fit->origin - o).norm(), 0.003);
    EXPECT_NEAR(fit->spread_m, 1.9, 0.01);
    ASSERT_EQ(fit->residuals_m.size(), 4u);
    EXPECT_GT(fit->residuals_m[1], 0.001);
    EXPECT_NEAR(fit->max_m, *std::max_element(fit->residuals_m.begin(), fit->residuals_m.end()), 1e-15);
    // Reversed order of the points: the direction still points forward.
    std::reverse(pts.begin(), pts.end());
    EXPECT_GT(fitAxisLine(pts)->direction.z(), 0.0);
    EXPECT_FALSE(fitAxisLine({pts[0]}));
}

TEST(CalibrationSynthetic, RecoversTheAxisFromNoisyCaptures) {
    const Projector truth = rig::trueProjector();
    double worst_angle = 0.0, worst_origin = 0.0;
    for (unsigned seed : {11u, 12u}) {
        const Calibration cal = calibrateSynthetic(truth, seed);
        ASSERT_TRUE(cal.ok()) << cal.message;
        const double angle = angleBetweenDeg(cal.projector.direction, truth.direction);
        const double origin = (cal.projector.origin - truth.origin).norm();
        std::printf("seed %u: axis error %.4f deg, origin error %.2f mm, residual rms %.2f mm max %.2f mm\n", seed,
                    angle, origin * 1000, cal.axis.rms_m * 1000, cal.axis.max_m * 1000);
        worst_angle = std::max(worst_angle, angle);
        worst_origin = std::max(worst_origin, origin);
        EXPECT_EQ(cal.captures.size(), 5u);
        EXPECT_LT(cal.axis.max_m, 0.01);
        EXPECT_EQ(cal.projector.width, 1280);
        for (int i = 0; i < 4; ++i) EXPECT_NEAR(cal.pinhole_rays[i].norm(), 1.0, 1e-12);
    }
    std::printf("axis recovery: worst %.4f deg, origin worst %.2f mm (2 seeds x 5 captures at 1-3 m)\n", worst_angle,
                worst_origin * 1000);
    EXPECT_LE(worst_angle, 0.5);
    EXPECT_LT(worst_origin, 0.03);
}

TEST(CalibrationSynthetic, Refusals) {
    const Projector truth = rig::trueProjector();
    const CameraIntrinsics cam;
    std::mt19937 rng(3);
    const auto walls = rig::calibrationWalls();
    std::vector<CaptureImages> caps;
    for (int k = 0; k < 3; ++k) caps.push_back(rig::renderCapture(truth, walls[2 * k], cam, rng));

    // Too few.
    std::vector<CaptureImages> two(caps.begin(), caps.begin() + 2);
    auto cal = calibrateProjector(two, cam);
    EXPECT_EQ(cal.failure, CalibrationFailure::TooFewCaptures);

    // No disc in capture 1.
    rig::CaptureOptions none;
    none.no_disc = true;
    auto bad = caps;
    bad[1] = rig::renderCapture(truth, walls[2], cam, rng, none);
    cal = calibrateProjector(bad, cam);
    EXPECT_EQ(cal.failure, CalibrationFailure::NoDisc);
    EXPECT_EQ(cal.failed_capture, 1);

    // Depth missing at the disc in capture 2.
    rig::CaptureOptions nodepth;
    nodepth.drop_disc_depth = true;
    bad = caps;
    bad[2] = rig::renderCapture(truth, walls[4], cam, rng, nodepth);
    cal = calibrateProjector(bad, cam);
    EXPECT_EQ(cal.failure, CalibrationFailure::NoDepth);
    EXPECT_EQ(cal.failed_capture, 2);
    EXPECT_NE(cal.message.find("depth missing"), std::string::npos);

    // All at one distance: no line.
    std::vector<CaptureImages> same;
    for (double angle : {0.0, 5.0, -5.0}) same.push_back(rig::renderCapture(truth, rig::wall(2.0, angle), cam, rng));
    cal = calibrateProjector(same, cam);
    EXPECT_EQ(cal.failure, CalibrationFailure::Degenerate);
    EXPECT_NE(cal.message.find("different distances"), std::string::npos) << cal.message;

    // Depth of the wrong size.
    bad = caps;
    bad[0].depth = cv::Mat(240, 320, CV_16UC1, cv::Scalar(1000));
    cal = calibrateProjector(bad, cam);
    EXPECT_EQ(cal.failure, CalibrationFailure::SizeMismatch);
    EXPECT_EQ(cal.failed_capture, 0);

    // The good set calibrates.
    EXPECT_TRUE(calibrateProjector(caps, cam).ok());
}

TEST(CalibrationEndToEnd, EstimatedCalibrationAndNoisyCloud) {
    // Calibrate from noisy captures, fit the wall plane to a noisy cloud, build the rectangle
    // with the estimated projector, correct, and cast the picture back through the TRUE
    // projector onto the TRUE wall.
    const Projector truth = rig::trueProjector();
    const Calibration cal = calibrateSynthetic(truth, 21);
    ASSERT_TRUE(cal.ok()) << cal.message;
    const Projector &est = cal.projector;
    const CameraIntrinsics cam;
    std::mt19937 rng(77);
    const double distances[3] = {1.0, 2.0, 3.0}, angles[3] = {27.5, 17.19, -12.06};
    const char *names[3] = {"Horizontal", "Vertical", "Diagonals"};
    double cells[3][3][3][2] = {};  // angle, distance, error kind, (sum, sum of squares)
    const int trials = 5;
    double worst = 0.0, worst_offset = 0.0, worst_offset_rel = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 3; ++d) {
            const Plane w = rig::wall(distances[d], angles[a]);
            for (int t = 0; t < trials; ++t) {
                const auto pts = rig::noisyWallCloud(w, cam, rng);
                std::vector<int> idx(pts.size());
                for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
                const auto fitted = fitPlane(pts, idx);
                ASSERT_TRUE(fitted);
                const Rectangle rect = rig::rectangleInWorkspace(est, *fitted, 0.8);
                const auto k = computeKeystone(est, rect, cv::Size(640, 480));
                ASSERT_TRUE(k.keystone) << k.problem;
                Corners3 c;
                for (int i = 0; i < 4; ++i) c[i] = *castToWall(truth, k.keystone->picture_px[i], w);
                const auto e = shapeErrors(c);
                // The picture stays where it was meant to be: inside the rectangle, up to the
                // calibration's and the plane fit's error.
                for (int i = 0; i < 4; ++i) {
                    const double off = (c[i] - k.keystone->shown.corners[i]).norm();
                    worst_offset = std::max(worst_offset, off);
                    worst_offset_rel = std::max(worst_offset_rel, off / rect.width);
                }
                const double v[3] = {e.horizontal_pct, e.vertical_pct, e.diagonal_pct};
                for (int i = 0; i < 3; ++i) cells[a][d][i][0] += v[i], cells[a][d][i][1] += v[i] * v[i];
                worst = std::max(worst, e.worst_pct());
            }
        }
    std::printf("\neq. (8) errors, estimated calibration (seed 21), plane fitted to a noisy cloud, %d trials\n",
                trials);
    std::printf("%-8s %-12s %-16s %-16s %-16s\n", "angle", "error (%)", "1 m", "2 m", "3 m");
    for (int a = 0; a < 3; ++a)
        for (int i = 0; i < 3; ++i) {
            std::printf("%-8.2f %-12s", angles[a], names[i]);
            for (int d = 0; d < 3; ++d) {
                const double m = cells[a][d][i][0] / trials;
                const double sd = std::sqrt(std::max(0.0, (cells[a][d][i][1] - trials * m * m) / (trials - 1)));
                std::printf(" %.4f (%.4f)  ", m, sd);
            }
            std::printf("\n");
        }
    std::printf(
        "worst: %.4f %%; axis error %.4f deg; picture corners off by up to %.1f mm (%.3f %% of the "
        "rectangle's width)\n",
        worst, angleBetweenDeg(est.direction, truth.direction), worst_offset * 1000, worst_offset_rel * 100);
    EXPECT_LE(worst, 0.5);
    EXPECT_LT(worst_offset_rel, 0.01);
}

TEST(CalibrationSimulator, RecoversTheAxisFromTheSimulatorsKinectCaptures) {
    // An independent renderer (src/projsurf/sim: disparity quantisation, IR shadow, grazing
    // dropouts, walls turned by up to 20 deg, which shifts an ellipse's centroid off the
    // disc centre's image) as a cross-check of the synthetic captures above.
    const Projector truth = rig::trueProjector();
    double worst = 0.0;
    for (unsigned seed : {1u, 2u}) {
        const auto frames = sim::renderCalibrationCaptures(truth, sim::SensorModel{}, 5, seed);
        const Calibration cal = calibrateProjector(sim::captureImages(frames), sim::SensorModel{}.camera);
        ASSERT_TRUE(cal.ok()) << cal.message;
        const double angle = angleBetweenDeg(cal.projector.direction, truth.direction);
        std::printf("simulator seed %u: axis error %.4f deg, origin error %.2f mm, residual max %.2f mm\n", seed, angle,
                    (cal.projector.origin - truth.origin).norm() * 1000, cal.axis.max_m * 1000);
        worst = std::max(worst, angle);
    }
    EXPECT_LE(worst, 0.5);
}
