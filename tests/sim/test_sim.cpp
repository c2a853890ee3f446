// The simulator against independent geometry: rendered walls lie on the true plane, noise
// follows the published model, obstacles hide the wall, the projected disc lands where the
// projector axis meets the wall, and the ground-truth rectangle respects footprint and obstacles.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "cli_run.hpp"
#include "projsurf/calibration/calibration_picture.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/ray_cast.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/plane.hpp"

using namespace projsurf;
using namespace projsurf::sim;

namespace {

bool isLabel(const Scenario &s, const RgbdFrame &f, int u, int v, const std::string &label) {
    const int q = f.quad.at<int>(v, u);
    return q >= 0 && s.scene.quads[q].label == label;
}

/// Standard deviation and mean of measured minus true depth on wall pixels.
std::pair<double, double> depthResidualStats(const Scenario &s, const SensorModel &sensor, unsigned seed) {
    const RgbdFrame truth = renderFrame(s.scene, SensorModel::ideal(), 0);
    const RgbdFrame noisy = renderFrame(s.scene, sensor, seed);
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int v = 0; v < truth.depth.rows; ++v)
        for (int u = 0; u < truth.depth.cols; ++u) {
            const std::size_t i = static_cast<std::size_t>(v) * truth.cloud.width + u;
            if (!isLabel(s, truth, u, v, "wall") || !isFinite(noisy.cloud.points[i]) ||
                !isFinite(truth.cloud.points[i]))
                continue;
            const double e = double(noisy.cloud.points[i].z()) - double(truth.cloud.points[i].z());
            sum += e;
            sum2 += e * e;
            ++n;
        }
    const double mean = sum / n;
    return {std::sqrt(sum2 / n - mean * mean), mean};
}

/// Is p (2-D) inside the convex polygon (any orientation), with a tolerance?
bool insideConvex(const std::vector<Eigen::Vector2d> &poly, const Eigen::Vector2d &p, double tol) {
    double sign = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % poly.size()];
        const Eigen::Vector2d e = (b - a).normalized();
        const double cross = e.x() * (p - a).y() - e.y() * (p - a).x();
        if (sign == 0) sign = cross > 0 ? 1 : -1;
        if (cross * sign < -tol) return false;
    }
    return true;
}

double distanceToSegment(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return (a + t * (b - a) - p).norm();
}

}  // namespace

TEST(SimGeometry, NoiseFreeWallPointsLieOnTheTruePlane) {
    for (double distance : {1.0, 2.0, 3.0})
        for (double angle : {0.0, 17.19, 27.5, -26.01}) {
            const Scenario s = makeScenario("wall", distance, angle);
            const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1);
            int on_wall = 0;
            for (int v = 0; v < f.depth.rows; ++v)
                for (int u = 0; u < f.depth.cols; ++u) {
                    const Point &p = f.cloud.points[static_cast<std::size_t>(v) * f.cloud.width + u];
                    if (!isLabel(s, f, u, v, "wall") || !isFinite(p)) continue;
                    ASSERT_LT(std::abs(s.wall.signedDistance(p.cast<double>())), 1e-6) << distance << " " << angle;
                    ++on_wall;
                }
            EXPECT_GT(on_wall, 10000) << distance << " " << angle;
            // The wall is where the scenario says: the optical axis meets it at `distance`,
            // and its orientation is the requested angle.
            EXPECT_NEAR(-s.wall.d / s.wall.normal.z(), distance, 1e-12);
            EXPECT_NEAR(orientationDeg(s.wall), std::abs(angle), 1e-9);
            // A pixel's depth equals the ray-plane intersection computed independently.
            const CameraIntrinsics cam;
            const Eigen::Vector3d ray((400 - cam.cx) / cam.fx, (200 - cam.cy) / cam.fy, 1.0);
            const auto hit = intersectRay(s.wall, Eigen::Vector3d::Zero(), ray);
            ASSERT_TRUE(hit);
            EXPECT_NEAR(f.cloud.points[200 * 640 + 400].z(), hit->z(), 1e-6);
            EXPECT_EQ(f.depth.at<std::uint16_t>(200, 400), static_cast<int>(std::lround(hit->z() * 1000.0)));
        }
}

TEST(SimGeometry, FrontalWallHasConstantDepthAndFloorIsBelow) {
    const Scenario s = makeScenario("wall", 3.0, 0.0);
    const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1);
    EXPECT_NEAR(f.cloud.points[100 * 640 + 100].z(), 3.0, 1e-6);
    EXPECT_EQ(f.depth.at<std::uint16_t>(240, 320), 3000);
    // The bottom image row sees the floor (from 1 / tan(24.5 deg) = 2.2 m on), 1.0 m below the camera (y = +1.0).
    const Point &p = f.cloud.points[479 * 640 + 320];
    ASSERT_TRUE(isLabel(s, f, 320, 479, "floor"));
    EXPECT_NEAR(p.y(), 1.0, 1e-6);
}

TEST(SimSensor, DepthNoiseMatchesTheKinectModel) {
    // Khoshelham & Oude Elberink 2012: sigma_z = 1.425e-3 z^2 (quantisation included).
    SensorModel sensor;
    sensor.ir_shadow = false;
    for (double distance : {1.0, 3.0}) {
        const Scenario s = makeScenario("wall", distance, 10.0);  // tilted: many depths per frame
        const auto [sigma, mean] = depthResidualStats(s, sensor, 7);
        const double expected = 1.425e-3 * distance * distance;
        EXPECT_NEAR(sigma, expected, 0.12 * expected) << distance;
        EXPECT_LT(std::abs(mean), 0.15 * expected) << distance;
    }
}

TEST(SimSensor, QuantisedDepthsComeInDisparitySteps) {
    SensorModel sensor = SensorModel::ideal();
    sensor.quantize = true;
    const Scenario s = makeScenario("wall", 3.0, 0.0);
    const RgbdFrame f = renderFrame(s.scene, sensor, 1);
    // Every reading is 1 / (offset - step * raw) for a whole raw value.
    for (int v = 0; v < 480; v += 37)
        for (int u = 0; u < 640; u += 41) {
            const Point &p = f.cloud.points[v * 640 + u];
            if (!isFinite(p)) continue;
            const double raw = (sensor.disparity_offset - 1.0 / p.z()) / sensor.disparity_step;
            EXPECT_NEAR(raw, std::round(raw), 1e-3);
        }
    // At 3 m a step is about 3.07e-3 * 9 = 2.8 cm.
    EXPECT_NEAR(sensor.quantumAt(3.0), 0.0276, 0.001);
}

TEST(SimSensor, NoReadingsOutOfRangeOrAtGrazingAngles) {
    {
        const Scenario s = makeScenario("wall", 5.0, 0.0);  // beyond 4.5 m
        const RgbdFrame f = renderFrame(s.scene, SensorModel(), 3);
        int wall_pixels = 0, wall_readings = 0;
        for (int v = 0; v < 480; ++v)
            for (int u = 0; u < 640; ++u)
                if (isLabel(s, f, u, v, "wall")) {
                    ++wall_pixels;
                    wall_readings += f.depth.at<std::uint16_t>(v, u) != 0;
                }
        EXPECT_GT(wall_pixels, 100000);
        EXPECT_EQ(wall_readings, 0);
    }
    {
        SensorModel sensor = SensorModel::ideal();
        sensor.min_depth = 0.8;
        const Scenario s = makeScenario("wall", 0.6, 0.0);  // nearer than the minimum
        const RgbdFrame f = renderFrame(s.scene, sensor, 3);
        EXPECT_EQ(cv::countNonZero(f.depth), 0);
    }
    {
        // A wall turned 70 degrees: on its far side the rays meet it at more than 80 degrees
        // from its normal and give no reading.
        const Scenario s = makeScenario("wall", 1.5, 70.0);
        const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 3);
        const CameraIntrinsics cam;
        int grazing = 0, seen = 0;
        for (int v = 0; v < 480; v += 4)
            for (int u = 0; u < 640; u += 4) {
                if (!isLabel(s, f, u, v, "wall")) continue;
                const Eigen::Vector3d d((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0);
                const auto hit = intersectRay(s.wall, Eigen::Vector3d::Zero(), d);
                if (!hit || hit->z() > 4.4) continue;
                const double angle = std::acos(std::abs(d.normalized().dot(s.wall.normal))) * 180.0 / M_PI;
                if (angle > 80.01) {
                    EXPECT_EQ(f.depth.at<std::uint16_t>(v, u), 0) << u << "," << v;
                    ++grazing;
                } else if (angle < 79.99) {
                    EXPECT_NE(f.depth.at<std::uint16_t>(v, u), 0) << u << "," << v;
                    ++seen;
                }
            }
        EXPECT_GT(grazing, 100);
        EXPECT_GT(seen, 100);
    }
}

TEST(SimSensor, SameSeedSameFrame) {
    const Scenario s = makeScenario("big_obstacle", 2.0, 17.19);
    const RgbdFrame a = renderFrame(s.scene, SensorModel(), 11), b = renderFrame(s.scene, SensorModel(), 11);
    const RgbdFrame c = renderFrame(s.scene, SensorModel(), 12);
    EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0.0);
    EXPECT_GT(cv::norm(a.depth, c.depth, cv::NORM_INF), 0.0);
}

TEST(SimScene, BoxInFrontOfTheWallHidesIt) {
    const Scenario s = makeScenario("big_obstacle", 2.0, 0.0);
    const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1);
    // The box spans s in [-0.45, 0.15], h in [0, 1.05] and sticks out 0.45 m: the camera ray
    // to a point on the wall behind its middle meets the box front first.
    const Eigen::Vector3d behind(-0.15, 1.0 - 0.6, 2.0);  // on the wall, 0.6 m above the floor
    const Eigen::Vector2d px = CameraIntrinsics().project(behind);
    const int u = static_cast<int>(std::lround(px.x())), v = static_cast<int>(std::lround(px.y()));
    ASSERT_TRUE(isLabel(s, f, u, v, "box"));
    EXPECT_NEAR(f.cloud.points[v * 640 + u].z(), 2.0 - 0.45, 1e-6);
    // Beside the box the wall is seen.
    const Eigen::Vector2d beside = CameraIntrinsics().project(Eigen::Vector3d(0.6, 0.4, 2.0));
    EXPECT_TRUE(isLabel(s, f, int(std::lround(beside.x())), int(std::lround(beside.y())), "wall"));
}

TEST(SimScene, IrShadowBesideABoxEdge) {
    // The emitter sits 7.5 cm right of the camera, so the wall just left of the box's left
    // edge is seen by the camera but not reached by the IR pattern.
    const Scenario s = makeScenario("big_obstacle", 2.0, 0.0);
    SensorModel sensor = SensorModel::ideal();
    sensor.ir_shadow = true;
    const RgbdFrame f = renderFrame(s.scene, sensor, 1);
    const RgbdFrame g = renderFrame(s.scene, SensorModel::ideal(), 1);
    // Box front left edge at x = -0.45, z = 1.55; the shadow on the wall (z = 2) spans
    // x from -0.45 * 2 / 1.55 ... back to the emitter line: about 2.2 cm wide.
    const int v = 300;  // a row that sees the box
    int shadow = 0;
    for (int u = 0; u < 640; ++u)
        if (isLabel(s, g, u, v, "wall") && g.depth.at<std::uint16_t>(v, u) != 0 && f.depth.at<std::uint16_t>(v, u) == 0)
            ++shadow;
    const double expected_px = 525.0 * 0.075 * (2.0 - 1.55) / 1.55 / 2.0;  // shadow width on the wall, in px
    EXPECT_NEAR(shadow, expected_px, 2.0);
}

TEST(SimProjector, CalibrationDiscIsCentredWhereTheAxisMeetsTheWall) {
    const Projector projector = exampleProjector();
    const cv::Mat disc = calibrationPicture(projector.width, projector.height);
    for (double distance : {1.2, 2.0, 3.0})
        for (double angle : {0.0, 17.19}) {
            const Scenario s = makeScenario("wall", distance, angle);
            const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1, Projection{projector, disc});
            cv::Mat grey, bright;
            cv::cvtColor(f.rgb, grey, cv::COLOR_BGR2GRAY);
            cv::threshold(grey, bright, 128, 255, cv::THRESH_BINARY);
            const cv::Moments m = cv::moments(bright, true);
            ASSERT_GT(m.m00, 50.0);
            const auto axis_hit = intersectRay(s.wall, projector.origin, projector.direction);
            ASSERT_TRUE(axis_hit);
            const Eigen::Vector2d expected = CameraIntrinsics().project(*axis_hit);
            EXPECT_NEAR(m.m10 / m.m00, expected.x(), 1.5) << distance << " " << angle;
            EXPECT_NEAR(m.m01 / m.m00, expected.y(), 1.5) << distance << " " << angle;
        }
}

TEST(SimProjector, ObstacleCastsAProjectorShadow) {
    // A white picture on the big box scene: the projector, 12 cm below the camera, throws the
    // box's shadow a few cm higher up the wall than the part the camera cannot see, so the
    // camera sees a dark band (ambient light only) above the box; the rest is lit.
    const Projector projector = exampleProjector();
    const cv::Mat white(projector.height, projector.width, CV_8UC3, cv::Scalar(255, 255, 255));
    const Scenario s = makeScenario("big_obstacle", 2.0, 0.0);
    const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1, Projection{projector, white});
    int shadowed = 0, lit = 0, wrong = 0;
    for (int v = 0; v < 480; ++v)
        for (int u = 0; u < 640; ++u) {
            if (!isLabel(s, f, u, v, "wall")) continue;
            const Eigen::Vector3d p = f.cloud.points[v * 640 + u].cast<double>();
            const auto fb = projector.toPixel(p);
            if (!p.allFinite() || !fb) continue;
            if (fb->x() < 2 || fb->x() > projector.width - 3 || fb->y() < 2 || fb->y() > projector.height - 3) continue;
            const bool blocked = segmentBlocked(s.scene, projector.origin, p, 0.01);
            const int g = f.rgb.at<cv::Vec3b>(v, u)[1];
            shadowed += blocked && g < 60;
            lit += !blocked && g > 180;
            wrong += blocked ? g >= 60 : g <= 180;
        }
    EXPECT_GT(shadowed, 800);  // a band about 3.5 cm x 0.6 m on the wall: about 9 x 157 px
    EXPECT_GT(lit, 50000);
    EXPECT_LT(wrong, 0.1 * shadowed);  // only at the shadow's edges (shadow-map texels)
}

TEST(SimProjector, LightTransportSeesWhatTheRenderSees) {
    // A structured-light sequence is rendered through the light transport, cast once: on the
    // box scene (a projector shadow, the floor) its colour must be renderFrame's, for the
    // paper's pinhole projector and for one with a lens offset, roll and distortion.
    const Scenario s = makeScenario("big_obstacle", 2.0, 15.0);
    for (const Projector &projector : {exampleProjector(), projectorRig({1.0, 1.0, 1.005, -0.05})}) {
        cv::Mat fb(projector.height, projector.width, CV_8UC3);
        cv::randu(fb, cv::Scalar::all(0), cv::Scalar::all(256));
        cv::GaussianBlur(fb, fb, cv::Size(0, 0), 3.0);  // smooth, like a picture, so bilinear is well posed
        const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1, Projection{projector, fb});
        const LightTransport t = lightTransport(s.scene, cameraView(SensorModel::ideal().camera), projector);
        cv::Mat lit;
        litBy(t, fb).convertTo(lit, CV_8UC3, 255.0);
        cv::Mat diff;
        cv::absdiff(lit, f.rgb, diff);
        const int lit_pixels = cv::countNonZero(t.fb_x >= 0);
        EXPECT_GT(lit_pixels, 50000);  // the projector lights about a quarter of the view
        // Equal up to remap's 1/32-pixel interpolation, except at the shadow map's texels.
        EXPECT_LT(cv::countNonZero(diff.reshape(1) > 2), 0.002 * lit_pixels);
        EXPECT_LT(cv::mean(diff)[0], 0.2);
    }
}

TEST(SimTruth, PlainWallRectangleIsLimitedByTheProjectorFootprint) {
    const Projector projector = exampleProjector();
    for (double angle : {0.0, 27.5}) {
        const Scenario s = makeScenario("wall", 2.0, angle);
        const GroundTruth gt = computeGroundTruth(s.scene, SensorModel(), projector, s.gravity);
        ASSERT_TRUE(gt.found);
        const SurfaceTruth &t = gt.best;
        EXPECT_EQ(t.label, "wall");
        EXPECT_LT((t.plane.coefficients() - s.wall.coefficients()).norm(), 1e-9);
        EXPECT_NEAR(t.rectangle.width / t.rectangle.height, projector.aspect(), 1e-9);
        ASSERT_TRUE(t.has_footprint);
        std::vector<Eigen::Vector2d> foot;
        for (const auto &c : t.footprint) foot.push_back(t.frame.toPlane(c));
        double touch = 1e9;
        for (const auto &c : t.rectangle.corners) {
            EXPECT_LT(std::abs(s.wall.signedDistance(c)), 1e-9);
            const Eigen::Vector2d p = t.frame.toPlane(c);
            EXPECT_TRUE(insideConvex(foot, p, 1e-9)) << angle;
            for (int i = 0; i < 4; ++i) touch = std::min(touch, distanceToSegment(p, foot[i], foot[(i + 1) % 4]));
        }
        EXPECT_LT(touch, 2 * t.cell) << angle;  // as big as the footprint allows
        // Corners are ordered TL, TR, BR, BL and the sides are upright (parallel to gravity).
        const auto &c = t.rectangle.corners;
        EXPECT_LT((c[0] - c[3]).normalized().dot(-s.gravity) - 1.0, 1e-9);
        EXPECT_GT((c[1] - c[0]).dot(t.frame.right), 0.0);
        // Frontal: the footprint is nearly a rectangle, so the truth covers most of it.
        if (angle == 0.0) {
            const double fw = 2 * 2.0 * std::tan(projector.fov_h / 2), fh = 2 * 2.0 * std::tan(projector.fov_v / 2);
            EXPECT_GT(t.rectangle.area(), 0.9 * fw * fh);
        }
    }
}

TEST(SimTruth, RectangleAvoidsObstacles) {
    const Projector projector = exampleProjector();
    const double plain =
        computeGroundTruth(makeScenario("wall", 2.0, 17.19).scene, SensorModel(), projector, Eigen::Vector3d::UnitY())
            .best.rectangle.area();
    for (const std::string name : {"small_obstacles", "big_obstacle", "person", "desk"}) {
        const Scenario s = makeScenario(name, 2.0, 17.19);
        const GroundTruth gt = computeGroundTruth(s.scene, SensorModel(), projector, s.gravity);
        ASSERT_TRUE(gt.found) << name;
        EXPECT_LT(gt.best.rectangle.area(), plain) << name;
        // Every point of the rectangle is seen by the camera and lit by the projector: the
        // first thing on both rays is the surface itself (the wall, or a box's flat face).
        const auto &c = gt.best.rectangle.corners;
        for (int i = 1; i < 10; ++i)  // inside points: a box face shares its edges with the next face
            for (int j = 1; j < 10; ++j) {
                // Just inside the edges: an edge may lie exactly on a box face's border.
                const double a = 0.001 + 0.998 * i / 10.0, b = 0.001 + 0.998 * j / 10.0;
                const Eigen::Vector3d p = c[3] + a * (c[2] - c[3]) + b * (c[0] - c[3]);
                for (const Eigen::Vector3d &from : {Eigen::Vector3d::Zero().eval(), projector.origin}) {
                    const auto hit = castRay(s.scene, from, p - from);
                    ASSERT_TRUE(hit);
                    EXPECT_EQ(s.scene.quads[hit->quad].surface, gt.best.surface) << name << " " << i << "," << j;
                    EXPECT_NEAR(hit->t, 1.0, 1e-6);
                }
            }
    }
}

TEST(SimTruth, ClosetFrontWinsNearAndPosterIsNotAnObstacle) {
    const Projector projector = exampleProjector();
    const Scenario near = makeScenario("closet", 1.5, -16.62);
    const GroundTruth g1 = computeGroundTruth(near.scene, SensorModel(), projector, near.gravity);
    ASSERT_TRUE(g1.found);
    EXPECT_EQ(g1.surfaces.size(), 4u);  // wall, closet front and both closet sides
    EXPECT_EQ(g1.best.label, "closet");
    // The poster is flat on the wall: the truth equals the plain wall's.
    const GroundTruth plain =
        computeGroundTruth(makeScenario("wall", 2.0, 17.19).scene, SensorModel(), projector, Eigen::Vector3d::UnitY());
    const Scenario poster = makeScenario("poster", 2.0, 17.19);
    const GroundTruth gp = computeGroundTruth(poster.scene, SensorModel(), projector, poster.gravity);
    EXPECT_NEAR(gp.best.rectangle.area(), plain.best.rectangle.area(), 1e-9);
}

TEST(SimScenarios, EveryScenarioRendersItsWall) {
    for (const auto &name : scenarioNames()) {
        const Scenario s = makeScenario(name, 2.0, 17.19);
        EXPECT_NEAR(s.gravity.norm(), 1.0, 1e-12);
        EXPECT_LT(std::abs(s.wall.normal.dot(s.gravity)), 1e-12) << name;  // the wall is vertical
        const RgbdFrame f = renderFrame(s.scene, SensorModel(), 5);
        int on_wall = 0;
        for (const auto &p : f.cloud.points)
            if (isFinite(p) && std::abs(s.wall.signedDistance(p.cast<double>())) < 0.03) ++on_wall;
        EXPECT_GT(on_wall, 30000) << name;
    }
    EXPECT_THROW(makeScenario("nonsense", 2.0, 0.0), std::invalid_argument);
    EXPECT_THROW(makeScenario("wall", 0.1, 0.0), std::invalid_argument);
    EXPECT_THROW(makeScenario("closet", 0.8, 0.0), std::invalid_argument);
    const Scenario rolled = makeScenario("rolled", 2.0, 0.0);
    EXPECT_NEAR(std::asin(std::abs(rolled.gravity.x())) * 180.0 / M_PI, 4.0, 1e-9);
}

namespace {

projsurf::test::CliRun runSimulate(const std::string &args, const std::string &tmp) {
    return projsurf::test::cli("simulate " + args, tmp);
}

std::string freshDir(const std::string &name) {
    const std::string dir = "/tmp/projsurf_test_sim_" + name + "_" + std::to_string(::getpid());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace

TEST(SimCli, WritesTheContractFilesAndTheTruth) {
    const std::string tmp = freshDir("cli");
    const std::string out = tmp + "/frame";
    const projsurf::test::CliRun r =
        runSimulate("--scenario big_obstacle --distance 2.5 --angle-deg 17.19 --seed 4 --captures 3 --out " + out, tmp);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char *f : {"cloud.pcd", "depth.png", "rgb.png", "camera.yaml", "calib.yaml", "truth.json",
                          "captures/camera.yaml", "captures/capture_0_rgb.png", "captures/capture_2_depth.png"})
        EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
    const cv::Mat depth = cv::imread(out + "/depth.png", cv::IMREAD_UNCHANGED);
    ASSERT_EQ(depth.type(), CV_16UC1);
    EXPECT_EQ(depth.cols, 640);
    EXPECT_GT(cv::countNonZero(depth), 200000);
    // The truth file matches the library's ground truth for the same scene.
    const nlohmann::json j = nlohmann::json::parse(projsurf::test::slurp(out + "/truth.json"));
    ASSERT_TRUE(j["found"].get<bool>());
    const Scenario s = makeScenario("big_obstacle", 2.5, 17.19);
    const GroundTruth gt = computeGroundTruth(s.scene, SensorModel(), exampleProjector(), s.gravity);
    EXPECT_NEAR(j["rectangle"]["area_m2"].get<double>(), gt.best.rectangle.area(), 1e-9);
    EXPECT_EQ(j["rectangle"]["corners"].size(), 4u);
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(j["plane"]["coefficients"][k].get<double>(), s.wall.coefficients()[k], 1e-9);
    EXPECT_EQ(j["scenario"]["name"], "big_obstacle");
    std::filesystem::remove_all(tmp);
}

TEST(SimCli, BadArgumentsExitTwoAndWriteNothing) {
    const std::string tmp = freshDir("bad");
    const std::string out = tmp + "/never";
    for (const std::string &args :
         std::vector<std::string>{"--scenario nonsense --out " + out, "--scenario wall --distance 0.1 --out " + out,
                                  std::string("--scenario wall"), "--scenario wall --captures 2 --out " + out,
                                  "--scenario wall --aspect 16x9 --out " + out,
                                  "--scenario wall --calib /nonexistent/calib.yaml --out " + out,
                                  "--scenario wall --picture /nonexistent/p.png --out " + out}) {
        const projsurf::test::CliRun r = runSimulate(args, tmp);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_NE(r.err.find("error"), std::string::npos) << args << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << args;
    }
    const projsurf::test::CliRun list = runSimulate("--list", tmp);
    EXPECT_EQ(list.status, 0);
    for (const auto &name : scenarioNames()) EXPECT_NE(list.out.find(name), std::string::npos) << name;
    std::filesystem::remove_all(tmp);
}

TEST(SimScenarios, PitchedCameraSeesTheFloorOneMetreDown) {
    // Looking down 15 degrees: gravity turns in the camera frame, and every floor point is
    // still 1.0 m below the camera along gravity.
    Scenario s = makeScenario("wall", 3.0, 17.19);
    pitchCamera(s, 15.0);
    EXPECT_NEAR(std::acos(s.gravity.dot(Eigen::Vector3d::UnitY())) * 180.0 / M_PI, 15.0, 1e-9);
    EXPECT_GT(s.gravity.z(), 0.0);  // looking down: gravity has a forward component
    const RgbdFrame f = renderFrame(s.scene, SensorModel::ideal(), 1);
    int floor = 0;
    for (int v = 0; v < 480; v += 3)
        for (int u = 0; u < 640; u += 3) {
            const Point &p = f.cloud.points[v * 640 + u];
            if (!isLabel(s, f, u, v, "floor") || !isFinite(p)) continue;
            EXPECT_NEAR(s.gravity.dot(p.cast<double>()), 1.0, 1e-6);
            ++floor;
        }
    EXPECT_GT(floor, 2000);
    EXPECT_LT(std::abs(s.wall.normal.dot(s.gravity)), 1e-12);
}

TEST(SimSensor, DepthEdgesAreRaggedOnlyWithNoise) {
    // The big box's left edge: with noise the first box column varies from row to row
    // (lateral edge noise), without it the edge is a straight line.
    const Scenario s = makeScenario("big_obstacle", 2.0, 0.0);
    for (const bool noisy : {false, true}) {
        SensorModel sensor = noisy ? SensorModel() : SensorModel::ideal();
        sensor.ir_shadow = false;
        const RgbdFrame f = renderFrame(s.scene, sensor, 9);
        std::vector<int> first;
        for (int v = 280; v < 380; ++v)
            for (int u = 100; u < 320; ++u) {
                const Point &p = f.cloud.points[v * 640 + u];
                if (isFinite(p) && p.z() < 1.8) {  // on the box front (1.55 m), not the wall (2 m)
                    first.push_back(u);
                    break;
                }
            }
        ASSERT_EQ(first.size(), 100u);
        const auto [lo, hi] = std::minmax_element(first.begin(), first.end());
        if (noisy)
            EXPECT_GE(*hi - *lo, 2);
        else
            EXPECT_EQ(*hi - *lo, 0);
    }
}

TEST(SimTruth, RequireDepthLeavesOutTheIrShadow) {
    // Beside the person the wall is free but the IR pattern cannot reach it (no depth there).
    const Scenario s = makeScenario("person", 2.5, 10.0);
    const Projector projector = exampleProjector();
    TruthOptions measurable;
    measurable.require_depth = true;
    const GroundTruth free_wall = computeGroundTruth(s.scene, SensorModel(), projector, s.gravity);
    const GroundTruth measured = computeGroundTruth(s.scene, SensorModel(), projector, s.gravity, measurable);
    ASSERT_TRUE(free_wall.found && measured.found);
    EXPECT_LT(measured.best.free_area, free_wall.best.free_area);
    EXPECT_LE(measured.best.rectangle.area(), free_wall.best.rectangle.area());
    const auto &c = measured.best.rectangle.corners;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) {
            const Eigen::Vector3d p =
                c[3] + (0.001 + 0.0998 * i) * (c[2] - c[3]) + (0.001 + 0.0998 * j) * (c[0] - c[3]);
            EXPECT_FALSE(segmentBlocked(s.scene, SensorModel().emitter, p, 0.01)) << i << "," << j;
        }
}

TEST(SimProjector, AudienceViewShowsTheProjectorFootprint) {
    // A white picture on a wall turned 27.5 degrees, seen by someone facing the wall: the lit
    // region is the keystoned footprint (the corner rays meeting the wall).
    const Projector projector = exampleProjector();
    const cv::Mat white(projector.height, projector.width, CV_8UC3, cv::Scalar(255, 255, 255));
    const Scenario s = makeScenario("wall", 2.0, 27.5);
    const auto axis_hit = intersectRay(s.wall, projector.origin, projector.direction);
    ASSERT_TRUE(axis_hit);
    const PinholeView viewer = facingView(s.wall, *axis_hit, 2.5, s.gravity);
    const cv::Mat img = renderView(s.scene, viewer, Projection{projector, white});
    std::vector<Eigen::Vector2d> corners;
    for (const auto &ray : projector.cornerRays()) {
        const auto hit = intersectRay(s.wall, projector.origin, ray);
        ASSERT_TRUE(hit);
        corners.push_back(viewer.pixelOf(viewer.toView(*hit)));
        ASSERT_TRUE(viewer.inside(corners.back()));
    }
    const Eigen::Vector2d centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    for (const auto &c : corners) {
        const Eigen::Vector2d towards = (centre - c).normalized();
        const Eigen::Vector2d in = c + 3.0 * towards, out = c - 3.0 * towards;
        EXPECT_GT(img.at<cv::Vec3b>(int(std::lround(in.y())), int(std::lround(in.x())))[1], 180);
        EXPECT_LT(img.at<cv::Vec3b>(int(std::lround(out.y())), int(std::lround(out.x())))[1], 60);
    }
    // Seen square-on, the footprint's near (left) side is shorter than its far (right) side.
    EXPECT_LT((corners[3] - corners[0]).norm(), (corners[2] - corners[1]).norm());
}
