// Keystone correction: eq. (7) against the pinhole model, letterboxing, the warp, and the
// round trip through a synthetic projector and wall measured with the paper's eq. (8).
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <random>

#include "projsurf/calibration/euler_rodrigues.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "synthetic_rig.hpp"

using namespace projsurf;

namespace {

const double kDistances[3] = {1.0, 2.0, 3.0};     // m, paper section 4.4
const double kAngles[3] = {27.5, 17.19, -12.06};  // deg, paper section 4.4

/// Casts the picture's framebuffer corners through `truth` onto `wall`: where the corrected
/// picture's corners really appear.
Corners3 onWall(const Projector &truth, const Corners2 &px, const Plane &wall) {
    Corners3 out;
    for (int i = 0; i < 4; ++i) out[i] = *castToWall(truth, px[i], wall);
    return out;
}

/// True when p lies inside the convex quadrilateral q (framebuffer pixels), with a tolerance.
bool insideQuad(const Eigen::Vector2d &p, const Corners2 &q, double tol) {
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d a = q[i], b = q[(i + 1) % 4];
        const Eigen::Vector2d e = (b - a).normalized();
        const double cross = e.x() * (p - a).y() - e.y() * (p - a).x();  // > 0: right of the edge (y down)
        if (cross < -tol) return false;
    }
    return true;
}

struct Stats {
    std::vector<double> v;
    void add(double x) { v.push_back(x); }
    double mean() const {
        double s = 0;
        for (double x : v) s += x;
        return s / v.size();
    }
    double sd() const {
        const double m = mean();
        double s = 0;
        for (double x : v) s += (x - m) * (x - m);
        return v.size() > 1 ? std::sqrt(s / (v.size() - 1)) : 0.0;
    }
    double max() const { return *std::max_element(v.begin(), v.end()); }
};

/// Prints eq. (8) errors in the form of the paper's Table 3: mean (sd) per distance.
void printTable(const char *title, Stats cells[3][3][3]) {
    std::printf("\n%s\n%-8s %-22s %-16s %-16s %-16s\n", title, "angle", "error (%)", "1 m", "2 m", "3 m");
    const char *names[3] = {"Horizontal", "Vertical", "Diagonals"};
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) {
            std::printf("%-8.2f %-22s", kAngles[a], names[k]);
            for (int d = 0; d < 3; ++d) std::printf(" %.4f (%.4f)  ", cells[a][d][k].mean(), cells[a][d][k].sd());
            std::printf("\n");
        }
}

}  // namespace

TEST(KeystoneEq7, AgreesWithThePinholeModel) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0.0;
    for (int trial = 0; trial < 50; ++trial) {
        Projector p;
        p.origin = Eigen::Vector3d(0.2 * u(rng), 0.2 * u(rng), 0.1 * u(rng));
        p.direction = Eigen::Vector3d(0.3 * u(rng), 0.3 * u(rng), 1.0).normalized();
        p.width = 800 + static_cast<int>(600 * (u(rng) + 1));
        p.height = 600 + static_cast<int>(300 * (u(rng) + 1));
        p.fov_h = (30 + 15 * u(rng)) * rig::kDeg;
        p.fov_v = (20 + 10 * u(rng)) * rig::kDeg;
        for (int i = 0; i < 20; ++i) {
            const Eigen::Vector2d px((u(rng) + 1) * 0.6 * p.width, (u(rng) + 1) * 0.6 * p.height);
            const Eigen::Vector3d point = p.origin + (1.0 + 1.5 * (u(rng) + 1)) * p.ray(px);
            const auto a = pixelFromWorkspace(p, point);
            const auto b = p.toPixel(point);
            ASSERT_TRUE(a && b);
            worst = std::max(worst, (*a - *b).norm());
        }
    }
    EXPECT_LT(worst, 1e-6);
    // Behind the lens: no pixel.
    EXPECT_FALSE(pixelFromWorkspace(Projector{}, Eigen::Vector3d(0, 0.12, -1.0)));
}

TEST(KeystoneLetterbox, FitsThePictureWholeAndCentred) {
    const Projector p = rig::trueProjector();
    const Rectangle rect = rig::rectangleInWorkspace(p, rig::wall(2.0, 17.19));  // 16:10
    for (double aspect : {4.0 / 3.0, 16.0 / 10.0, 21.0 / 9.0, 9.0 / 16.0, 1.0}) {
        const Rectangle s = letterbox(rect, aspect);
        EXPECT_NEAR(s.width / s.height, aspect, 1e-9);
        EXPECT_LT((s.center() - rect.center()).norm(), 1e-9);
        EXPECT_LE(s.width, rect.width + 1e-9);
        EXPECT_LE(s.height, rect.height + 1e-9);
        // One dimension is full: nothing is wasted that needn't be.
        EXPECT_TRUE(std::abs(s.width - rect.width) < 1e-9 || std::abs(s.height - rect.height) < 1e-9);
        const auto e = shapeErrors(s.corners);
        EXPECT_LT(e.worst_pct(), 1e-9);
    }
}

TEST(KeystoneRefuses, RectangleOutsideTheFramebufferOrBehind) {
    const Projector p = rig::trueProjector();
    const Plane w = rig::wall(2.0, 0.0);
    Rectangle rect = rig::rectangleInWorkspace(p, w, 1.3);  // larger than the workspace
    auto r = computeKeystone(p, rect, cv::Size(640, 480));
    EXPECT_FALSE(r.keystone);
    EXPECT_NE(r.problem.find("leaves the projector's framebuffer"), std::string::npos) << r.problem;
    rect = rig::rectangleInWorkspace(p, w);
    for (auto &c : rect.corners) c.z() = -c.z();
    r = computeKeystone(p, rect, cv::Size(640, 480));
    EXPECT_FALSE(r.keystone);
    EXPECT_NE(r.problem.find("behind the projector"), std::string::npos) << r.problem;
    EXPECT_FALSE(computeKeystone(p, rig::rectangleInWorkspace(p, w), cv::Size(0, 0)).keystone);
}

TEST(KeystoneWarp, PicturePixelsLandInsideTheQuadAndBlackOutside) {
    const Projector p = rig::trueProjector();
    const Rectangle rect = rig::rectangleInWorkspace(p, rig::wall(1.5, 27.5));
    // A picture with a distinct colour per quadrant, 4:3 (pillarboxed in the 16:10 rectangle).
    cv::Mat pic(480, 640, CV_8UC3);
    pic(cv::Rect(0, 0, 320, 240)).setTo(cv::Scalar(255, 0, 0));
    pic(cv::Rect(320, 0, 320, 240)).setTo(cv::Scalar(0, 255, 0));
    pic(cv::Rect(320, 240, 320, 240)).setTo(cv::Scalar(0, 0, 255));
    pic(cv::Rect(0, 240, 320, 240)).setTo(cv::Scalar(255, 255, 255));
    const auto r = computeKeystone(p, rect, pic.size());
    ASSERT_TRUE(r.keystone) << r.problem;
    const Keystone &k = *r.keystone;
    const cv::Mat fb = warpToFramebuffer(pic, k);
    ASSERT_EQ(fb.cols, 1280);
    ASSERT_EQ(fb.rows, 800);
    ASSERT_EQ(fb.type(), CV_8UC3);
    // The homography maps the picture's outer corners onto the eq. (7) pixels.
    const double w = pic.cols, h = pic.rows;
    const double sx[4] = {-0.5, w - 0.5, w - 0.5, -0.5}, sy[4] = {-0.5, -0.5, h - 0.5, h - 0.5};
    for (int i = 0; i < 4; ++i) {
        const cv::Vec3d q = k.homography * cv::Vec3d(sx[i], sy[i], 1.0);
        EXPECT_NEAR(q[0] / q[2], k.picture_px[i].x(), 1e-6);
        EXPECT_NEAR(q[1] / q[2], k.picture_px[i].y(), 1e-6);
    }
    // Quadrant centres show their colours; every pixel outside the picture's quad is black.
    const double qx[4] = {160, 480, 480, 160}, qy[4] = {120, 120, 360, 360};
    const cv::Vec3b colours[4] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int i = 0; i < 4; ++i) {
        const cv::Vec3d q = k.homography * cv::Vec3d(qx[i], qy[i], 1.0);
        const cv::Vec3b got =
            fb.at<cv::Vec3b>(static_cast<int>(std::lround(q[1] / q[2])), static_cast<int>(std::lround(q[0] / q[2])));
        EXPECT_EQ(got, colours[i]) << "quadrant " << i;
    }
    int lit_outside = 0, dark_inside = 0;
    for (int y = 0; y < fb.rows; ++y)
        for (int x = 0; x < fb.cols; ++x) {
            const bool lit = fb.at<cv::Vec3b>(y, x) != cv::Vec3b(0, 0, 0);
            if (lit && !insideQuad(Eigen::Vector2d(x, y), k.picture_px, 1.0)) ++lit_outside;
            if (!lit && insideQuad(Eigen::Vector2d(x, y), k.picture_px, -1.0)) ++dark_inside;
        }
    EXPECT_EQ(lit_outside, 0);
    EXPECT_EQ(dark_inside, 0);
}

TEST(KeystoneWarp, StrongShrinkIsAreaAveraged) {
    // A one-pixel checkerboard shrunk ~8x: bilinear sampling alone would alias to near black or
    // white patches; area averaging gives an even grey.
    const Projector p = rig::trueProjector();
    const Rectangle rect = rig::rectangleInWorkspace(p, rig::wall(2.0, 0.0), 0.5);
    cv::Mat pic(2000, 3200, CV_8UC1);
    for (int y = 0; y < pic.rows; ++y)
        for (int x = 0; x < pic.cols; ++x) pic.at<uchar>(y, x) = ((x + y) % 2) ? 255 : 0;
    const auto r = computeKeystone(p, rect, pic.size());
    ASSERT_TRUE(r.keystone) << r.problem;
    const cv::Mat fb = warpToFramebuffer(pic, *r.keystone);
    const cv::Vec3d c = r.keystone->homography * cv::Vec3d(1600, 1000, 1.0);
    const cv::Rect centre(static_cast<int>(c[0] / c[2]) - 40, static_cast<int>(c[1] / c[2]) - 40, 80, 80);
    cv::Scalar mean, sd;
    cv::meanStdDev(fb(centre), mean, sd);
    EXPECT_NEAR(mean[0], 127.5, 10.0);
    EXPECT_LT(sd[0], 10.0);
}

TEST(KeystoneRoundTrip, ExactCalibrationAtThePapersDistancesAndAngles) {
    const Projector p = rig::trueProjector();
    Stats cells[3][3][3];
    double worst = 0.0, worst_stock = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 3; ++d) {
            const Plane w = rig::wall(kDistances[d], kAngles[a]);
            const Rectangle rect = rig::rectangleInWorkspace(p, w);
            for (cv::Size pic : {cv::Size(640, 480), cv::Size(1920, 800), cv::Size(1280, 800)}) {
                const auto k = computeKeystone(p, rect, pic);
                ASSERT_TRUE(k.keystone) << k.problem;
                for (const auto &px : k.keystone->picture_px) {
                    EXPECT_GE(px.x(), -0.5 - 1e-9);
                    EXPECT_LE(px.x(), p.width - 0.5 + 1e-9);
                    EXPECT_GE(px.y(), -0.5 - 1e-9);
                    EXPECT_LE(px.y(), p.height - 0.5 + 1e-9);
                    EXPECT_TRUE(insideQuad(px, k.keystone->rectangle_px, 1e-6));
                }
                const auto e = shapeErrors(onWall(p, k.keystone->picture_px, w));
                cells[a][d][0].add(e.horizontal_pct);
                cells[a][d][1].add(e.vertical_pct);
                cells[a][d][2].add(e.diagonal_pct);
                worst = std::max(worst, e.worst_pct());
                // The shown picture has the picture's aspect ratio on the wall.
                const auto c = onWall(p, k.keystone->picture_px, w);
                EXPECT_NEAR((c[1] - c[0]).norm() / (c[3] - c[0]).norm(), double(pic.width) / pic.height, 1e-6);
                // The paper's own rays (Euler-Rodrigues, Appendix) in the eq. (7) construction:
                // their workspace is not a rectangle, so the result is slightly off.
                Corners2 stock;
                const auto rays = paperCornerRays(p.direction, p.fov_h, p.fov_v);
                for (int i = 0; i < 4; ++i) stock[i] = *pixelFromWorkspace(p, k.keystone->shown.corners[i], rays);
                worst_stock = std::max(worst_stock, shapeErrors(onWall(p, stock, w)).worst_pct());
            }
        }
    printTable("eq. (8) errors, exact calibration, exact wall (3 pictures per cell)", cells);
    std::printf("worst: %.2e %%; with the paper's Euler-Rodrigues corner rays in eq. (7): %.3f %%\n", worst,
                worst_stock);
    EXPECT_LE(worst, 0.2);
    EXPECT_LT(worst, 1e-6);        // exact geometry: only rounding
    EXPECT_LT(worst_stock, 3.46);  // the paper's worst reported error
}

TEST(KeystoneRoundTrip, ExactCalibrationNoisyCloud) {
    // The rectangle comes from a least-squares plane fitted to a Kinect-noisy cloud of the wall;
    // the corrected picture is cast back onto the true wall.
    const Projector p = rig::trueProjector();
    const CameraIntrinsics cam;
    const Eigen::Vector3d gravity(0, 1, 0);
    Stats cells[3][3][3];
    double worst = 0.0;
    std::mt19937 rng(2024);
    for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 3; ++d) {
            const Plane w = rig::wall(kDistances[d], kAngles[a]);
            for (int trial = 0; trial < 10; ++trial) {
                const auto pts = rig::noisyWallCloud(w, cam, rng);
                std::vector<int> idx(pts.size());
                for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
                const auto fitted = fitPlane(pts, idx);
                ASSERT_TRUE(fitted);
                const Rectangle rect = rig::rectangleInWorkspace(p, *fitted);
                const auto k = computeKeystone(p, rect, cv::Size(640, 480));
                ASSERT_TRUE(k.keystone) << k.problem;
                const auto e = shapeErrors(onWall(p, k.keystone->picture_px, w));
                cells[a][d][0].add(e.horizontal_pct);
                cells[a][d][1].add(e.vertical_pct);
                cells[a][d][2].add(e.diagonal_pct);
                worst = std::max(worst, e.worst_pct());
            }
        }
    printTable("eq. (8) errors, exact calibration, plane fitted to a noisy cloud (10 trials per cell)", cells);
    std::printf("worst: %.4f %%\n", worst);
    EXPECT_LE(worst, 0.2);
}

TEST(KeystoneRoundTrip, LensOffsetAlongTheAxis) {
    // The calibration puts the lens where the axis crosses z = 0 (paper, A.1). A real lens some
    // centimetres in front of or behind the camera's optical centre is off by that much along
    // the axis; this measures what that costs at the paper's distances and angles. On a flat
    // wall the true picture is then a scaled copy of the intended one about the lens (every
    // wall point's distance ratio is the same), so eq. (8) cannot see it: the cost is placement.
    double previous = -1.0;
    for (double dz : {0.0, 0.02, 0.05, 0.10}) {
        Projector truth = rig::trueProjector();
        truth.origin.z() = dz;
        Projector assumed = truth;  // exact axis, lens moved along it to z = 0
        assumed.origin = axisPointAtZeroZ(truth.origin, truth.direction);
        double worst = 0.0, worst_outside_mm = 0.0;
        for (double angle : kAngles)
            for (double distance : kDistances) {
                const Plane w = rig::wall(distance, angle);
                const Rectangle rect = rig::rectangleInWorkspace(assumed, w);
                const auto k = computeKeystone(assumed, rect, cv::Size(640, 480));
                ASSERT_TRUE(k.keystone) << k.problem;
                const Corners3 c = onWall(truth, k.keystone->picture_px, w);
                worst = std::max(worst, shapeErrors(c).worst_pct());
                // How far the picture's corners land from where they were meant to be.
                for (int i = 0; i < 4; ++i)
                    worst_outside_mm = std::max(worst_outside_mm, 1000 * (c[i] - k.keystone->shown.corners[i]).norm());
            }
        std::printf("lens %.0f mm off z = 0: worst eq. (8) error %.4f %%, corners displaced up to %.1f mm\n", dz * 1000,
                    worst, worst_outside_mm);
        EXPECT_LT(worst, 1e-6);                        // still an undistorted rectangle
        EXPECT_GT(worst_outside_mm, previous);         // but displaced, more with a larger offset
        EXPECT_LT(worst_outside_mm, 400 * dz + 1e-9);  // under 0.4 mm per mm of offset
        previous = worst_outside_mm;
    }
}
