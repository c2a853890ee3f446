// Where to stand (contract "Where to stand"): the planned move, then the scene rendered from
// the moved robot and detected again; the picture found is at least 95 % of the predicted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "projsurf/io/cloud_io.hpp"
#include "projsurf/io/yaml_files.hpp"
#include "projsurf/detection/detector.hpp"
#include "projsurf/planning/stand_planner.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenarios.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {

struct Realised {
    PlanResult plan;
    double before = 0.0, after = 0.0;  ///< m^2 detected today and from the moved robot
    double after_width = 0.0;
};

Realised planAndMove(const std::string &scenario, double distance, double angle, const PlanOptions &options) {
    Realised r;
    const sim::Scenario sc = sim::makeScenario(scenario, distance, angle);
    const Projector projector = sim::exampleProjector();
    const sim::RgbdFrame today = sim::renderFrame(sc.scene, sim::SensorModel(), 4);
    const DetectorConfig cfg;
    const Detection det = detectSurface(today.cloud, projector, cfg, sc.gravity);
    r.before = det.found ? det.rectangle.area() : 0.0;
    r.plan = planStand(today.cloud, projector, cfg, sc.gravity, options);
    if (!r.plan.found) return r;
    // The moved camera sees P_moved = R^T (P_today - t).
    Eigen::Isometry3d today_from_moved = Eigen::Isometry3d::Identity();
    today_from_moved.linear() = r.plan.rotation;
    today_from_moved.translation() = r.plan.translation;
    const sim::Scene moved = sim::transformed(sc.scene, today_from_moved.inverse());
    const sim::RgbdFrame after = sim::renderFrame(moved, sim::SensorModel(), 5);
    const Detection d2 = detectSurface(after.cloud, projector, cfg, r.plan.rotation.transpose() * sc.gravity);
    if (d2.found) {
        r.after = d2.rectangle.area();
        r.after_width = d2.rectangle.width;
    }
    return r;
}

}  // namespace

TEST(Plan, LargestPictureAfterTheMoveIsRealised) {
    struct Case {
        const char *scenario;
        double distance, angle;
    };
    for (const Case c : {Case{"wall", 1.0, 0.0}, Case{"wall", 1.2, 0.0}, Case{"wall", 1.5, 35.0},
                         Case{"wall", 2.0, 17.19}, Case{"wall", 3.0, 30.0}, Case{"small_obstacles", 1.3, 10.0},
                         Case{"closet", 1.5, 0.0}, Case{"big_obstacle", 1.5, 17.19}, Case{"corner", 1.5, 0.0},
                         Case{"desk", 1.5, 10.0}, Case{"poster", 1.2, 20.0}}) {
        const Realised r = planAndMove(c.scenario, c.distance, c.angle, PlanOptions{});
        ASSERT_TRUE(r.plan.found) << c.scenario << ": " << r.plan.reason;
        const double predicted = r.plan.predicted.area();
        std::printf(
            "plan %s %.1f m %.0f deg: move %.2f m, turn %.1f deg; today %.3f m^2, predicted %.3f m^2, "
            "realised %.3f m^2 (%.1f %% of predicted, %.2fx today)\n",
            c.scenario, c.distance, c.angle, r.plan.translation.norm(),
            std::acos(std::clamp((r.plan.rotation.trace() - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / 3.14159265358979,
            r.before, predicted, r.after, 100.0 * r.after / predicted, r.after / std::max(r.before, 1e-9));
        EXPECT_LE(r.plan.translation.norm(), 2.0 + 1e-9);
        EXPECT_GE(r.after, 0.95 * predicted) << c.scenario;
        // A robot this close can gain; at 3 m the depth camera's range (PlanOptions::max_distance) leaves less.
        if (c.distance <= 2.0) {
            EXPECT_GE(r.after, 1.5 * r.before) << c.scenario << ": a robot this close should gain";
        } else {
            EXPECT_GE(r.after, r.before) << c.scenario;
        }
    }
}

TEST(Plan, SmallestMoveForAWidth) {
    PlanOptions o;
    o.width = 1.2;
    const Realised r = planAndMove("wall", 1.2, 0.0, o);
    ASSERT_TRUE(r.plan.found) << r.plan.reason;
    EXPECT_GE(r.plan.predicted.width, 1.2);
    EXPECT_GE(r.after_width, 0.95 * 1.2);
    std::printf("plan for 1.2 m wide: move %.2f m, predicted %.2f m wide, realised %.2f m wide\n",
                r.plan.translation.norm(), r.plan.predicted.width, r.after_width);
    // Further than possible within the bound: a clear refusal.
    o.width = 20.0;
    const Realised none = planAndMove("wall", 1.2, 0.0, o);
    EXPECT_FALSE(none.plan.found);
    EXPECT_FALSE(none.plan.reason.empty());
}

TEST(Plan, NeverOntoOccupiedSpace) {
    // A big box stands between the robot and the wall: the planned position is not inside it.
    const sim::Scenario sc = sim::makeScenario("big_obstacle", 1.4, 0.0);
    const Projector projector = sim::exampleProjector();
    const sim::RgbdFrame today = sim::renderFrame(sc.scene, sim::SensorModel(), 4);
    const PlanResult plan = planStand(today.cloud, projector, DetectorConfig{}, sc.gravity);
    ASSERT_TRUE(plan.found) << plan.reason;
    EXPECT_GT(plan.poses_occupied, 0);
    // The camera's new position is not within 0.3 m of any box face.
    const Eigen::Vector3d at = plan.translation;
    for (const auto &q : sc.scene.quads) {
        if (q.label == "wall" || q.label == "floor") continue;
        const Eigen::Vector3d n = q.normal();
        const double off = std::abs(n.dot(at - q.corner));
        const Eigen::Vector3d foot = at - n.dot(at - q.corner) * n;
        const double a = (foot - q.corner).dot(q.edge_a) / q.edge_a.squaredNorm();
        const double b = (foot - q.corner).dot(q.edge_b) / q.edge_b.squaredNorm();
        if (a >= 0 && a <= 1 && b >= 0 && b <= 1) {
            EXPECT_GT(off, 0.25) << q.label;
        }
    }
}

TEST(Plan, CliWritesTheContractsJson) {
    const fs::path dir = freshDir("people_plan_cli");
    const sim::Scenario sc = sim::makeScenario("wall", 1.2, 0.0);
    writeCalibration((dir / "calib.yaml").string(), sim::exampleProjector());
    writeCloudPcd((dir / "now.pcd").string(), sim::renderFrame(sc.scene, sim::SensorModel(), 4).cloud);
    const auto r = cli("plan --cloud " + (dir / "now.pcd").string() + " --calib " + (dir / "calib.yaml").string() +
                           " --json " + (dir / "plan.json").string(),
                       dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(dir / "plan.json"));
    ASSERT_TRUE(j.at("found").get<bool>());
    EXPECT_TRUE(j.at("reason").is_null());
    const auto &rot = j.at("camera_pose").at("rotation");
    ASSERT_EQ(rot.size(), 3u);
    Eigen::Matrix3d m;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) m(a, b) = rot[a][b].get<double>();
    EXPECT_LT((m * m.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-9);
    const auto &t = j.at("camera_pose").at("translation");
    EXPECT_LE(Eigen::Vector3d(t[0].get<double>(), t[1].get<double>(), t[2].get<double>()).norm(), 2.0 + 1e-9);
    EXPECT_EQ(j.at("predicted").at("corners").size(), 4u);
    EXPECT_GT(j.at("predicted").at("area_m2").get<double>(), 1.5 * j.at("today").at("area_m2").get<double>());
    // Bad input: one line, exit 2.
    const auto bad = cli("plan --depth x.png --calib " + (dir / "calib.yaml").string(), dir);
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err.rfind("projsurf: error: ", 0), 0u) << bad.err;
    fs::remove_all(dir);
}
