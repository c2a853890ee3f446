// projsurf verify : the projected picture found in the simulated colour image lands
// where the true projector puts it, with a right and with a wrong calibration.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_run.hpp"
#include "projsurf/calibration/projected_picture.hpp"
#include "eval/paper/experiments.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf::eval;  // the evaluation under test

using namespace projsurf;
namespace fs = std::filesystem;

namespace {

struct Loop {
    Detection det;
    Keystone keystone;
    cv::Mat framebuffer;
    sim::RgbdFrame seen;
    Corners3 landed;  ///< where the true projector put the picture's corners
};

/// Detect with `believed`, correct the test card, project it with `truth`, capture.
Loop closeLoop(const Projector &believed, const Projector &truth, const sim::Scenario &sc, unsigned seed) {
    Loop l;
    const sim::SensorModel sensor;
    const sim::RgbdFrame before = sim::renderFrame(sc.scene, sensor, seed);
    l.det = detectSurface(before.cloud, believed, DetectorConfig{}, sc.gravity);
    EXPECT_TRUE(l.det.found) << l.det.reason;
    const cv::Mat card = verificationCard(1280, 800);
    const auto k = computeKeystone(believed, l.det.rectangle, card.size());
    EXPECT_TRUE(k.keystone) << k.problem;
    l.keystone = *k.keystone;
    l.framebuffer = warpToFramebuffer(card, l.keystone);
    l.seen = sim::renderFrame(sc.scene, sensor, seed + 1, sim::Projection{truth, l.framebuffer});
    l.landed = eval::framebufferOnWall(truth, sc.scene, l.keystone.picture_px).corners;
    return l;
}

/// The closed loop through a realistic sensor (`simulate --sensor`): detect with `believed`,
/// correct the card, project it with `truth`, capture, find the card, check the landing.
std::optional<LandingCheck> sensorLoop(sim::SensorKind kind, const Projector &believed, const Projector &truth,
                                       const sim::Scenario &sc, unsigned seed) {
    const sim::DepthSensor sensor = sim::makeDepthSensor(kind, 0);
    const sim::RgbdFrame before = sim::renderSensorFrame(sc.scene, sensor, seed, std::nullopt, false);
    const Detection det = detectSurface(before.cloud, believed, DetectorConfig{}, sc.gravity);
    EXPECT_TRUE(det.found) << det.reason;
    if (!det.found) return std::nullopt;
    const cv::Mat card = verificationCard(believed.width, believed.height);
    const auto k = computeKeystone(believed, det.rectangle, card.size());
    EXPECT_TRUE(k.keystone) << k.problem;
    if (!k.keystone) return std::nullopt;
    const cv::Mat framebuffer = warpToFramebuffer(card, *k.keystone);
    const sim::RgbdFrame seen = sim::renderSensorFrame(sc.scene, sensor, seed + 1, sim::Projection{truth, framebuffer});
    const FoundPicture f = findProjectedPicture(seen.rgb, seen.depth, sensor.truthModel().camera);
    EXPECT_TRUE(f.found) << f.reason;
    const auto lit = litFramebufferCorners(framebuffer);
    if (!f.found || !lit) return std::nullopt;
    return checkLanding(believed, *lit, f, det.rectangle.corners);
}

}  // namespace

// The grid (docs/projector.md): Kinect v1, ToF and D435 at 1, 2 and 3 m, frontal and
// 30 deg; verify's default tolerance passes the exact calibration and fails one whose axis is 1
// deg off in yaw, in every case, however far the detection's corners lie from the landing.
TEST(Verify, DefaultTolerancePassesTheExactCalibrationAndFailsOneDegreeOfYawOnEverySensor) {
    const Projector truth = sim::exampleProjector();  // `simulate`'s projector
    Projector wrong = truth;  // its axis turned 1 deg about the camera's vertical
    wrong.direction = Eigen::AngleAxisd(1.0 * M_PI / 180, Eigen::Vector3d::UnitY()) * truth.direction;
    double worst_right = 0, least_wrong = HUGE_VAL, worst_detection = 0;
    for (const sim::SensorKind kind : sim::sensorKinds())
        for (const double distance : {1.0, 2.0, 3.0})
            for (const double angle : {0.0, 30.0}) {
                const sim::Scenario sc = sim::makeScenario("wall", distance, angle);
                char where_c[80];
                std::snprintf(where_c, sizeof where_c, "%s at %.0f m, %.0f deg", sim::sensorName(kind).c_str(),
                              distance, angle);
                const std::string where = where_c;
                const auto right = sensorLoop(kind, truth, truth, sc, 11);
                const auto off = sensorLoop(kind, wrong, truth, sc, 11);
                ASSERT_TRUE(right && off) << where;
                // verify's default tolerance, as verify computes it with the calibration it is given
                const double tolerance = calibrationTolerance(truth, right->expected),
                             off_tolerance = calibrationTolerance(wrong, off->expected);
                std::printf("%-30s exact: %.1f mm (detection's corners %.1f mm), 1 deg yaw: %.1f mm; tolerance "
                            "%.1f mm\n",
                            where.c_str(), right->max_calibration_error_m * 1000, right->max_detection_error_m * 1000,
                            off->max_calibration_error_m * 1000, tolerance * 1000);
                EXPECT_LE(right->max_calibration_error_m, tolerance) << where;
                EXPECT_GT(off->max_calibration_error_m, off_tolerance) << where;
                worst_right = std::max(worst_right, right->max_calibration_error_m);
                least_wrong = std::min(least_wrong, off->max_calibration_error_m);
                worst_detection = std::max(worst_detection, right->max_detection_error_m);
            }
    std::printf("exact calibration: at most %.1f mm; 1 deg yaw: at least %.1f mm; the detection's corners of the exact "
                "calibration: up to %.1f mm from the landing\n",
                worst_right * 1000, least_wrong * 1000, worst_detection * 1000);
}

TEST(Verify, FindsWhereThePictureLandedWithARightAndAWrongCalibration) {
    const Projector truth = sim::projectorRig({1.0, 1.0, 1.005, -0.05});
    Projector wrong = truth;
    wrong.setRotation(Eigen::AngleAxisd(1.0 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                      *truth.rotation);
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 20.0);
    const sim::SensorModel sensor;
    for (const Projector *believed : std::vector<const Projector *>{&truth, &wrong}) {
        const Loop l = closeLoop(*believed, truth, sc, 21);
        const FoundPicture f = findProjectedPicture(l.seen.rgb, l.seen.depth, sensor.camera);
        ASSERT_TRUE(f.found) << f.reason;
        double worst = 0, off = 0;
        for (int i = 0; i < 4; ++i) {
            worst = std::max(worst, (f.corners[i] - l.landed[i]).norm());
            off = std::max(off, (l.landed[i] - l.det.rectangle.corners[i]).norm());
        }
        std::printf(
            "%s calibration: measured corners within %.1f mm of the true landing points; those are %.1f mm "
            "from the detection's corners\n",
            believed == &truth ? "right" : "1 deg yaw wrong", worst * 1000, off * 1000);
        EXPECT_LT(worst, 0.005);
        if (believed == &wrong) {
            EXPECT_GT(off, 0.02);
        }
    }
}

TEST(Verify, NothingProjectedOnTheRepositorysRealFramesIsNotFound) {
    // A capture of a room with nothing projected: its brightest region is no test card (on the
    // TUM frame it once made a "card" whose corners lay 2.1 m from the detection's).
    for (const char *frame : {"tum_o3d_fr3_office_partition", "ufsec_livingroom_sofa_1"}) {
        const std::string dir = std::string(PROJSURF_SOURCE_DIR) + "/data/" + frame;
        const CameraIntrinsics camera = readCamera(dir + "/camera.yaml");
        const cv::Mat rgb = cv::imread(dir + "/rgb.png", cv::IMREAD_COLOR);
        const cv::Mat depth = cv::imread(dir + "/depth.png", cv::IMREAD_UNCHANGED);
        ASSERT_FALSE(rgb.empty() || depth.empty()) << dir;
        const FoundPicture f = findProjectedPicture(rgb, depth, camera);
        EXPECT_FALSE(f.found) << frame;
        EXPECT_FALSE(f.reason.empty()) << frame;
    }
    // The card wholly in view is found; moved until the image's left edge cuts it, it is not.
    const sim::SensorModel sensor;
    const Projector truth = sim::exampleProjector();
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 10.0);
    const Loop l = closeLoop(truth, truth, sc, 7);
    ASSERT_TRUE(findProjectedPicture(l.seen.rgb, l.seen.depth, sensor.camera).found);
    const std::array<Eigen::Vector2d, 4> px = findProjectedPicture(l.seen.rgb, l.seen.depth, sensor.camera).image_px;
    const int left = static_cast<int>(std::min(px[0].x(), px[3].x()));
    cv::Mat shifted;
    const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, -(left + 20), 0, 1, 0);
    cv::warpAffine(l.seen.rgb, shifted, m, l.seen.rgb.size(), cv::INTER_NEAREST, cv::BORDER_REPLICATE);
    const FoundPicture partial = findProjectedPicture(shifted, l.seen.depth, sensor.camera);
    EXPECT_FALSE(partial.found);
    EXPECT_NE(partial.reason.find("edge of the colour image"), std::string::npos) << partial.reason;
}

TEST(Verify, CliReportsPassedForTheRightCalibrationAndNotFoundForADarkImage) {
    const fs::path dir = test::freshDir("projector_verify");
    const Projector truth = sim::projectorRig({1.33, 0.0, 1.0, 0.0});
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 15.0);
    const Loop l = closeLoop(truth, truth, sc, 5);
    writeCalibration((dir / "calib.yaml").string(), truth);
    std::ofstream((dir / "det.json").string()) << detectionToJson(l.det, DetectorConfig{}).dump(2);
    cv::imwrite((dir / "fb.png").string(), l.framebuffer);
    fs::create_directories(dir / "caps");
    writeCamera((dir / "caps" / "camera.yaml").string(), sim::SensorModel{}.camera);
    cv::imwrite((dir / "caps" / "rgb.png").string(), l.seen.rgb);
    cv::imwrite((dir / "caps" / "depth.png").string(), l.seen.depth);
    const std::string args = "verify --calib " + (dir / "calib.yaml").string() + " --detection " +
                             (dir / "det.json").string() + " --framebuffer " + (dir / "fb.png").string() +
                             " --captures " + (dir / "caps").string() + " --json " + (dir / "v.json").string();
    const auto r = test::cli(args, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = test::slurp(dir / "v.json");
    EXPECT_NE(json.find("\"found\": true"), std::string::npos) << json;
    EXPECT_NE(json.find("\"passed\": true"), std::string::npos) << json;
    // The same capture against a tolerance no real landing meets: written, FAILED, exit 3.
    const auto strict = test::cli(args + " --tolerance 0.000001", dir);
    EXPECT_EQ(strict.status, 3) << strict.err;
    EXPECT_NE(test::slurp(dir / "v.json").find("\"passed\": false"), std::string::npos);
    EXPECT_NE(strict.out.find("FAILED"), std::string::npos) << strict.out;
    cv::imwrite((dir / "caps" / "rgb.png").string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar(20, 20, 20)));
    const auto dark = test::cli(args, dir);
    EXPECT_EQ(dark.status, 0) << dark.err;  // not found: `found: false`, exit 0 (the contract)
    EXPECT_NE(test::slurp(dir / "v.json").find("\"found\": false"), std::string::npos);
    // A bright quadrilateral that is not the card (a lit window: no grey disc at its centre).
    cv::Mat window(480, 640, CV_8UC3, cv::Scalar(20, 20, 20));
    cv::rectangle(window, cv::Rect(200, 150, 240, 150), cv::Scalar(250, 250, 250), cv::FILLED);
    cv::imwrite((dir / "caps" / "rgb.png").string(), window);
    const auto other = test::cli(args, dir);
    EXPECT_EQ(other.status, 0) << other.err;
    EXPECT_NE(test::slurp(dir / "v.json").find("\"found\": false"), std::string::npos) << test::slurp(dir / "v.json");
    EXPECT_NE(other.out.find("not the test card"), std::string::npos) << other.out;
    // A framebuffer of another size: one line, exit 2.
    cv::imwrite((dir / "fb.png").string(), cv::Mat(100, 100, CV_8UC3, cv::Scalar(255, 255, 255)));
    const auto bad = test::cli(args, dir);
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << bad.err;
    fs::remove_all(dir);
}
