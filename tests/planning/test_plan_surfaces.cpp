// Where a plan may put the picture (issue 41): only on surfaces detection does not refuse,
// with the share on wall assumed beyond the camera's view said and ranked down; `plan --rgb`
// as `detect --rgb`; the overlay's top-down sketch drawing the move the words say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "cli_run.hpp"
#include "label_fixtures.hpp"
#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/frontend/render/plan_overlay.hpp"
#include "projsurf/planning/floor_occupancy.hpp"
#include "projsurf/planning/plan_raster.hpp"
#include "projsurf/planning/plan_surfaces.hpp"
#include "projsurf/planning/stand_planner.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The distance of `p` to the plane of the scene's quad labelled `label` (the first one).
double offQuad(const sim::Scenario &sc, const std::string &label, const Eigen::Vector3d &p) {
    for (const auto &q : sc.scene.quads)
        if (q.label == label) return std::abs(q.normal().dot(p - q.corner));
    return 1e9;
}

/// The bounding box of the pixels of exactly `colour` in `img`.
cv::Rect pixelsOf(const cv::Mat &img, const cv::Scalar &colour) {
    cv::Mat mask;
    cv::inRange(img, colour, colour, mask);
    return cv::boundingRect(mask);
}

}  // namespace

TEST(PlanSurfaces, FacesDetectionRefusesHoldNoPicture) {
    // Paper 4.3's big box standing free before the wall: detect names its front an object; the
    // plan's surfaces leave it out, and the plan's picture is on the wall.
    const sim::Scenario sc = sim::makeScenario("big_obstacle", 2.0, 0.0);
    const sim::RgbdFrame f = sim::renderFrame(sc.scene, sim::SensorModel{}, 3);
    DefaultScratch scratch;
    const SeenSurfaces seen = seeVerticalSurfaces(f.cloud, DetectorConfig{}, sc.gravity, 0.03, 5.5, scratch);
    int objects = 0;
    std::size_t usable = 0;
    for (const SeenSurface &s : seen.surfaces) {
        objects += s.object ? 1 : 0;
        usable += s.usable() && !s.free.empty() && cv::countNonZero(s.free) > 0 ? 1 : 0;
    }
    EXPECT_GE(objects, 1);
    const FloorOccupancy floor(f.cloud, sc.gravity, 2.5, 0.08);
    EXPECT_EQ(planSurfaces(f.cloud, seen, floor, {}).size(), usable);
    const PlanResult plan = planStand(f.cloud, sim::exampleProjector(), DetectorConfig{}, sc.gravity);
    ASSERT_TRUE(plan.found) << plan.reason;
    for (const auto &c : plan.predicted.corners) EXPECT_LT(offQuad(sc, "wall", c), 0.05) << c.transpose();
}

TEST(PlanSurfaces, AssumedShareCountsTheCellsUnderThePicture) {
    // A wall 2 m ahead on a 0.1 m raster, assumed (not seen) left of its centre line.
    PlanSurface s;
    s.plane.normal = -Eigen::Vector3d::UnitZ();
    s.plane.d = 2.0;
    s.frame = makePlaneFrame(s.plane, Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 0, 2));
    s.raster = planRaster({-1.0, -1.0}, {1.0, 1.0}, 0.1);
    s.assumed = cv::Mat::zeros(s.raster.rows, s.raster.cols, CV_8UC1);
    for (int r = 0; r < s.raster.rows; ++r)
        for (int c = 0; c < s.raster.cols; ++c)
            if (s.raster.toPlane({c + 0.5, r + 0.5}).x() < 0.0) s.assumed.at<uchar>(r, c) = 255;
    cv::integral(s.assumed / 255, s.assumed_integral, CV_32S);
    EXPECT_NEAR(assumedShare(s, makeRectangle(s.frame, {-0.6, -0.5}, {0.6, 0.5})), 0.5, 1e-9);
    EXPECT_NEAR(assumedShare(s, makeRectangle(s.frame, {0.02, -0.5}, {0.98, 0.5})), 0.0, 1e-9);
    EXPECT_NEAR(assumedShare(s, makeRectangle(s.frame, {-0.98, -0.5}, {-0.02, 0.5})), 1.0, 1e-9);
    EXPECT_NEAR(assumedShare(s, makeRectangle(s.frame, {-0.2, -0.5}, {0.6, 0.5})), 0.25, 1e-9);
}

TEST(PlanSurfaces, WallIsAssumedBeyondTheViewOnlyWhereItWasSeenUpToTheEdge) {
    // A wall 2 m ahead across the whole view (1.22 m either side of the axis), seen free
    // everywhere, or only left of 0.9 m (it ends there, in view: a corner, a cupboard's side).
    const CameraIntrinsics camera;
    SeenSurfaces seen;
    seen.camera = camera;
    SeenSurface w;
    w.plane.normal = -Eigen::Vector3d::UnitZ();
    w.plane.d = 2.0;
    w.frame = makePlaneFrame(w.plane, Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 0, 2));
    w.raster = planRaster({-1.23, -0.92}, {1.23, 0.92}, 0.03);
    w.free = cv::Mat(w.raster.rows, w.raster.cols, CV_8UC1, cv::Scalar(255));
    seen.surfaces.push_back(w);
    const FloorOccupancy floor(Cloud{}, Eigen::Vector3d::UnitY(), 2.5, 0.08);
    // Assumed cells right of the view at mid-height (1.3-1.6 m right, within 0.2 m of the axis' height).
    auto assumedRightOfView = [&](const SeenSurfaces &ss) {
        const PlanSurface p = planSurfaces(Cloud{}, ss, floor, {}).at(0);
        int n = 0;
        for (int r = 0; r < p.raster.rows; ++r)
            for (int c = 0; c < p.raster.cols; ++c) {
                const Eigen::Vector2d uv = p.raster.toPlane({c + 0.5, r + 0.5});
                n += p.assumed.at<uchar>(r, c) && uv.x() > 1.3 && uv.x() < 1.6 && std::abs(uv.y()) < 0.2;
            }
        return n;
    };
    EXPECT_GT(assumedRightOfView(seen), 50);
    for (int r = 0; r < w.raster.rows; ++r)
        for (int c = 0; c < w.raster.cols; ++c)
            if (w.raster.toPlane({c + 0.5, r + 0.5}).x() > 0.9) seen.surfaces[0].free.at<uchar>(r, c) = 0;
    EXPECT_EQ(assumedRightOfView(seen), 0);
}

TEST(PlanSurfaces, APictureOnAssumedWallIsSaidAndRankedDown) {
    // 1 m from a wall that fills the view: the largest picture steps back onto wall assumed
    // beyond the view. The less a m^2 of assumed wall counts, the less of it the plan uses;
    // counted as nothing, the picture is mostly on seen wall.
    const sim::Scenario sc = sim::makeScenario("wall", 1.0, 0.0);
    const sim::RgbdFrame f = sim::renderFrame(sc.scene, sim::SensorModel{}, 3);
    std::vector<PlanResult> plans;
    for (double w : {1.0, PlanOptions{}.assumed_weight, 0.0}) {
        PlanOptions o;
        o.assumed_weight = w;
        plans.push_back(planStand(f.cloud, sim::exampleProjector(), DetectorConfig{}, sc.gravity, o));
        ASSERT_TRUE(plans.back().found) << plans.back().reason;
        std::printf("assumed weight %.2f: %s, %.3f m^2, %.0f %% assumed\n", w, moveInWords(plans.back().move).c_str(),
                    plans.back().predicted.area(), 100.0 * plans.back().assumed_share);
    }
    ASSERT_TRUE(plans[0].assumed()) << "the scene no longer tests the assumed wall";
    EXPECT_NE(plans[0].limit.find("% of the picture is on wall not seen"), std::string::npos) << plans[0].limit;
    EXPECT_LE(plans[1].assumed_share, plans[0].assumed_share + 1e-9);
    EXPECT_LT(plans[2].assumed_share, 0.5 * plans[0].assumed_share);
    for (const PlanResult &p : plans)
        if (!p.assumed()) {
            EXPECT_EQ(p.limit.find("not seen"), std::string::npos) << p.limit;
        }
    // A picture more than max_assumed_share on assumed wall is no proposal.
    PlanOptions capped;
    capped.max_assumed_share = 0.3;
    const PlanResult c = planStand(f.cloud, sim::exampleProjector(), DetectorConfig{}, sc.gravity, capped);
    ASSERT_TRUE(c.found) << c.reason;
    EXPECT_LE(c.assumed_share, 0.3);
    EXPECT_GT(c.predicted.area(), 1.5 * c.todayArea()) << "a seen picture still gains";
}

TEST(PlanSurfaces, TheSketchDrawsTheMoveTheWordsSay) {
    // 1.5 m left, then a quarter turn left: the robot after is drawn 1.5 m left of the robot now
    // (its disc's centre, 5 radii of 0.3 m), level with it, its arrow pointing left.
    const SyntheticWall wall(3.0);
    const Eigen::Vector3d gravity = Eigen::Vector3d::UnitY();
    const LevelledFrame lf = levelledFrame(gravity);
    PlanResult plan;
    plan.found = true;
    plan.rotation = turnAboutUp(lf, 0.5 * kPi);
    plan.translation = 1.5 * lf.left;
    plan.move = levelledMove(plan.rotation, plan.translation, gravity);
    ASSERT_EQ(moveInWords(plan.move), "move 1.50 m left, then turn 90 deg left");
    const cv::Mat img = renderPlanOverlay(wall.cloud, plan, DetectorConfig{}, &wall.camera, gravity, 0.3);
    const int side = img.rows - 36;  // the sketch: the square at the right, under the line of words
    const cv::Mat sketch = img(cv::Rect(img.cols - side, 36, side, side));
    const cv::Rect now = pixelsOf(sketch, cv::Scalar(255, 200, 0)), after = pixelsOf(sketch, cv::Scalar(80, 255, 80));
    ASSERT_FALSE(now.empty() || after.empty());
    // Now: the arrow up (forward), 1.5 radii beyond the centre; "now" is written above right.
    const double r = (now.br().y - now.y) / 2.5;
    const double cx = now.x + r, cy = now.br().y - r;
    // After: the arrow left, 1.5 radii beyond its centre, the disc's top and bottom 2 radii apart.
    // (Within a tenth of a radius and a quarter: the lines' width and smoothing; a turn the
    // other way would draw the arrow 2.5 radii to the right.)
    EXPECT_NEAR(after.br().y - after.y, 2.0 * r, 0.1 * r);
    const double ax = after.x + 1.5 * r, ay = after.br().y - r;
    EXPECT_NEAR(ay, cy, 0.1 * r);
    EXPECT_NEAR(cx - ax, 5.0 * r, 0.25 * r);
}

TEST(PlanSurfaces, APictureOnAssumedWallIsDrawnDashed) {
    // The same proposal (1 m back, a picture on the wall 3 m ahead) seen, then 40 % assumed:
    // its outline on the frame and its bottom edge in the sketch lose about half their pixels.
    const SyntheticWall wall(3.0);
    const Eigen::Vector3d gravity = Eigen::Vector3d::UnitY();
    PlanResult plan;
    plan.found = true;
    plan.translation = -1.0 * levelledFrame(gravity).forward;
    plan.move = levelledMove(plan.rotation, plan.translation, gravity);
    Plane plane;
    plane.normal = -Eigen::Vector3d::UnitZ();
    plane.d = 3.0;
    plan.predicted = makeRectangle(makePlaneFrame(plane, gravity, Eigen::Vector3d(0, 0, 3)), {-1.0, -0.6}, {1.0, 0.6});
    auto green = [&](double assumed) {
        plan.assumed_share = assumed;
        cv::Mat mask;
        const cv::Mat img = renderPlanOverlay(wall.cloud, plan, DetectorConfig{}, &wall.camera, gravity, 0.3);
        cv::inRange(img, cv::Scalar(80, 255, 80), cv::Scalar(80, 255, 80), mask);
        return cv::countNonZero(mask);
    };
    const int seen = green(0.0), assumed = green(0.4);
    EXPECT_GT(seen, 0);
    EXPECT_LT(assumed, 0.8 * seen);
    EXPECT_GT(assumed, 0.2 * seen);
}

TEST(PlanSurfaces, PlanRgbIsReadAsDetectReadsIt) {
    const std::string frame = std::string(PROJSURF_SOURCE_DIR) + "/data/tum_o3d_fr3_office_partition";
    const fs::path dir = freshDir("plan_rgb");
    const std::string args = "plan --depth " + frame + "/depth.png --camera " + frame + "/camera.yaml --calib " +
                             frame + "/calib.yaml --gravity auto --json " + (dir / "p.json").string() + " --overlay " +
                             (dir / "p.png").string();
    const auto plain = cli(args, dir);
    ASSERT_EQ(plain.status, 0) << plain.err;
    const cv::Mat grey_overlay = cv::imread((dir / "p.png").string());
    const auto coloured = cli(args + " --rgb " + frame + "/rgb.png", dir);
    ASSERT_EQ(coloured.status, 0) << coloured.err;
    const auto j = nlohmann::json::parse(slurp(dir / "p.json"));
    EXPECT_TRUE(j.at("assumed").is_boolean());
    EXPECT_GE(j.at("assumed_share").get<double>(), 0.0);
    EXPECT_LE(j.at("assumed_share").get<double>(), 1.0);
    // The colour is the overlay's background: the pictures differ.
    const cv::Mat colour_overlay = cv::imread((dir / "p.png").string());
    ASSERT_EQ(colour_overlay.size(), grey_overlay.size());
    EXPECT_GT(cv::norm(colour_overlay, grey_overlay, cv::NORM_L1), 1e6);
    // Colour of the wrong size: one line, exit 2, nothing written.
    cv::Mat small = cv::imread(frame + "/rgb.png");
    cv::resize(small, small, {small.cols / 2, small.rows / 2});
    cv::imwrite((dir / "small.png").string(), small);
    fs::remove(dir / "p.json");
    const auto bad = cli(args + " --rgb " + (dir / "small.png").string(), dir);
    EXPECT_EQ(bad.status, 2) << bad.err;
    EXPECT_EQ(bad.err.rfind("projsurf: error: ", 0), 0u) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_FALSE(fs::exists(dir / "p.json"));
    fs::remove_all(dir);
}
