#include "eval/realistic/plan_suite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "projsurf/detector/detector.hpp"
#include "projsurf/planning/floor_occupancy.hpp"
#include "projsurf/planning/stance_view.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The scene's quads sampled every 4 cm, as a cloud: the floor the reference's robot fits on.
Cloud sceneSamples(const Scene &scene) {
    Cloud c;
    for (const Quad &q : scene.quads) {
        const int na = std::max(1, static_cast<int>(q.edge_a.norm() / 0.04)),
                  nb = std::max(1, static_cast<int>(q.edge_b.norm() / 0.04));
        for (int i = 0; i <= na; ++i)
            for (int j = 0; j <= nb; ++j)
                c.points.push_back(
                    (q.corner + q.edge_a * (double(i) / na) + q.edge_b * (double(j) / nb)).cast<float>());
    }
    c.width = static_cast<int>(c.points.size());
    c.height = 1;
    return c;
}

/// A frame of `scene` through the options' sensor (PlanSuiteOptions::sensor).
RgbdFrame renderScene(const Scene &scene, const PlanSuiteOptions &o, unsigned seed) {
    if (o.sensor.empty()) return renderFrame(scene, SensorModel(), seed);
    return renderSensorFrame(scene, makeDepthSensor(*parseSensorKind(o.sensor), 0), seed, std::nullopt, false);
}

struct Reference {
    double area = 0.0, width = 0.0, move_to_width = -1.0;
};

/// Every stance of a 0.2 m grid within the longest move, turned in 10 deg steps up to 90 deg
/// either way, where the robot's disc fits and its way there is clear; each scored by the
/// ground truth from there (what the moved camera sees and the moved projector lights), with
/// the picture's far corner within the plan's range.
Reference referenceSearch(const Scenario &sc, const Projector &projector, const PlanOptions &o,
                          const std::string &sensor_name) {
    Reference ref;
    const FloorOccupancy floor(sceneSamples(sc.scene), sc.gravity, o.max_move + o.robot_radius + 0.2,
                               o.obstacle_height);
    SensorModel sensor = SensorModel::ideal();
    if (!sensor_name.empty()) sensor.camera = makeDepthSensor(*parseSensorKind(sensor_name), 0).camera();
    sensor.max_depth = o.max_distance;
    TruthOptions topt;
    topt.cell = 0.03;
    const double step = 0.2;
    const int n = static_cast<int>(std::floor(o.max_move / step + 1e-9));
    for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) {
            const double f = i * step, l = j * step, move = std::hypot(f, l);
            if (move > o.max_move + 1e-9) continue;
            const Stance at = makeStance(floor.frame(), f, l, 0.0);
            if (move > 0 &&
                (floor.occupied(at.translation, o.robot_radius) || floor.pathBlocked(at.translation, o.robot_radius)))
                continue;
            for (int k = -9; k <= 9; ++k) {
                const Stance s = makeStance(floor.frame(), f, l, k * 10.0 * kPi / 180.0);
                Eigen::Isometry3d today_from_moved = Eigen::Isometry3d::Identity();
                today_from_moved.linear() = s.rotation;
                today_from_moved.translation() = s.translation;
                const GroundTruth t = computeGroundTruth(transformed(sc.scene, today_from_moved.inverse()), sensor,
                                                         projector, s.rotation.transpose() * sc.gravity, topt);
                if (!t.found) continue;
                double far = 0.0;
                for (const auto &c : t.best.rectangle.corners) far = std::max(far, c.norm());
                if (far > o.max_distance + 0.05) continue;
                ref.area = std::max(ref.area, t.best.rectangle.area());
                ref.width = std::max(ref.width, t.best.rectangle.width);
                if (o.width > 0 && t.best.rectangle.width >= o.width &&
                    (ref.move_to_width < 0 || move < ref.move_to_width))
                    ref.move_to_width = move;
            }
        }
    return ref;
}

/// Detected from the moved robot: the scene rendered there.
Detection detectFromMoved(const Scenario &sc, const Projector &projector, const PlanResult &plan,
                          const PlanSuiteOptions &options) {
    Eigen::Isometry3d today_from_moved = Eigen::Isometry3d::Identity();
    today_from_moved.linear() = plan.rotation;
    today_from_moved.translation() = plan.translation;
    const RgbdFrame after = renderScene(transformed(sc.scene, today_from_moved.inverse()), options, options.seed + 1);
    return detectSurface(after.cloud, projector, DetectorConfig{}, plan.rotation.transpose() * sc.gravity);
}

}  // namespace

std::vector<PlanScene> planSuiteScenes() {
    return {
        {"wall", 1.0, 0.0, 0.0, "near"},
        {"wall", 1.2, 0.0, 0.0, "near"},
        {"wall", 1.5, 35.0, 0.0, "angled"},
        {"wall", 2.0, 17.19, 0.0, "angled"},
        {"wall", 3.0, 30.0, 0.0, "angled"},
        {"small_obstacles", 1.3, 10.0, 0.0, "furniture"},
        {"closet", 1.5, 0.0, 0.0, "furniture"},
        {"big_obstacle", 1.5, 17.19, 0.0, "furniture"},
        {"corner", 1.5, 0.0, 0.0, "corner"},
        {"desk", 1.5, 10.0, 0.0, "furniture"},
        {"poster", 1.2, 20.0, 0.0, "near"},
        {"wall", 1.5, 30.0, 0.0, "angled"},
        {"wall", 2.5, 48.0, 0.0, "angled"},
        {"wall", 1.5, -45.0, 0.0, "angled"},
        {"wall", 2.0, 60.0, 0.0, "angled"},
        {"closet", 1.2, 0.0, 0.0, "furniture"},
        {"closet", 1.5, -20.0, 0.0, "furniture"},
        {"desk", 1.2, 0.0, 0.0, "furniture"},
        {"big_obstacle", 1.2, 0.0, 0.0, "furniture"},
        {"wall", 0.86, 0.0, 1.2, "width"},
        {"wall", 1.0, 20.0, 1.4, "width"},
        {"wall", 1.2, 0.0, 1.2, "width"},
        {"corner", 2.0, 30.0, 0.0, "corner"},
        {"corner", 1.2, -20.0, 0.0, "corner"},
    };
}

std::vector<PlanScene> obliqueWallScenes() {
    std::vector<PlanScene> out;
    for (double angle : {30.0, 45.0, 60.0})
        for (double distance : {1.5, 2.25, 3.0}) out.push_back({"wall", distance, angle, 0.0, "oblique"});
    return out;
}

PlanSceneResult runPlanScene(const PlanScene &scene, const PlanSuiteOptions &options) {
    PlanSceneResult r;
    r.scene = scene;
    const Scenario sc = makeScenario(scene.scenario, scene.distance, scene.angle_deg);
    const Projector projector = exampleProjector();
    const RgbdFrame today = renderScene(sc.scene, options, options.seed);
    PlanOptions o;
    o.width = scene.width;
    const auto t0 = std::chrono::steady_clock::now();
    r.plan = planStand(today.cloud, projector, DetectorConfig{}, sc.gravity, o);
    r.plan_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    r.before = r.plan.todayArea();
    if (r.plan.found) {
        r.predicted = r.plan.predicted.area();
        const Detection after = r.plan.moves() ? detectFromMoved(sc, projector, r.plan, options) : r.plan.today;
        r.realised = after.found ? after.rectangle.area() : 0.0;
        r.realised_width = after.found ? after.rectangle.width : 0.0;
    }
    if (options.reference) {
        const Reference ref = referenceSearch(sc, projector, o, options.sensor);
        r.reference = ref.area;
        r.reference_width = ref.width;
        r.reference_move = ref.move_to_width;
    }
    const bool realised = r.plan.found && r.realised >= 0.95 * r.predicted;
    if (scene.width > 0.0) {
        r.allows_gain = r.reference_move >= 0.0;
        r.holds = realised && (!r.allows_gain || r.realised_width >= 0.95 * scene.width);
    } else {
        r.allows_gain = r.reference >= 1.5 * r.before;
        r.holds = realised && (!r.allows_gain || r.realised >= 1.5 * r.before);
    }
    return r;
}

std::string planSuiteMarkdown(const std::vector<PlanSceneResult> &rows) {
    std::string md =
        "| scene | m | deg | --width | move | today m^2 | predicted m^2 | realised m^2 | realised / predicted | "
        "gain | reference m^2 | allows 1.5x (or the width) | limit | plan ms | holds |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    char buf[1024];
    for (const PlanSceneResult &r : rows) {
        const std::string width = r.scene.width > 0 ? std::to_string(r.scene.width).substr(0, 4) + " m" : "-";
        const std::string realised_w =
            r.scene.width > 0 ? " (" + std::to_string(r.realised_width).substr(0, 4) + " m wide)" : "";
        const std::string ref =
            r.scene.width > 0
                ? std::to_string(r.reference_width).substr(0, 4) + " m wide at most" +
                      (r.reference_move >= 0 ? ", " + std::to_string(r.reference_move).substr(0, 4) + " m move" : "")
                : std::to_string(r.reference).substr(0, 5);
        std::snprintf(
            buf, sizeof buf,
            "| %s | %.2f | %.1f | %s | %s | %.3f | %.3f | %.3f%s | %.1f %% | %.2fx | %s | %s | %s | %.0f | %s |\n",
            r.scene.scenario.c_str(), r.scene.distance, r.scene.angle_deg, width.c_str(),
            r.plan.found ? moveInWords(r.plan.move).c_str() : ("not found: " + r.plan.reason).c_str(), r.before,
            r.predicted, r.realised, realised_w.c_str(), r.predicted > 0 ? 100.0 * r.realised / r.predicted : 0.0,
            r.realised / std::max(r.before, 1e-9), ref.c_str(), r.allows_gain ? "yes" : "no", r.plan.limit.c_str(),
            r.plan_ms, r.holds ? "yes" : "**no**");
        md += buf;
    }
    return md;
}

std::string planSuiteSummary(const std::vector<PlanSceneResult> &rows) {
    int holds = 0;
    double lo = 1e9, hi = 0.0, ms = 0.0;
    for (const PlanSceneResult &r : rows) {
        holds += r.holds ? 1 : 0;
        if (r.predicted > 0) {
            lo = std::min(lo, r.realised / r.predicted);
            hi = std::max(hi, r.realised / r.predicted);
        }
        ms = std::max(ms, r.plan_ms);
    }
    char buf[300];
    std::snprintf(
        buf, sizeof buf,
        "plan suite: the targets hold in %d of %zu scenes; realised %.1f-%.1f %% of predicted; plan at most %.0f ms",
        holds, rows.size(), 100.0 * lo, 100.0 * hi, ms);
    return buf;
}

std::string planGainSummary(const std::vector<PlanSceneResult> &rows) {
    std::string out;
    double least = 1e9;
    char buf[200];
    for (const PlanSceneResult &r : rows) {
        if (r.reference <= 0.0 || r.scene.width > 0.0) continue;
        const double share = r.realised / r.reference;
        least = std::min(least, share);
        std::snprintf(buf, sizeof buf, "%s %.2f m %.0f deg: gain %.2fx of the reference's %.2fx (%.0f %%)\n",
                      r.scene.scenario.c_str(), r.scene.distance, r.scene.angle_deg,
                      r.realised / std::max(r.before, 1e-9), r.reference / std::max(r.before, 1e-9), 100.0 * share);
        out += buf;
    }
    if (least < 1e9) {
        std::snprintf(buf, sizeof buf, "realised gain at least %.0f %% of the reference's (target 85 %%)\n",
                      100.0 * least);
        out += buf;
    }
    return out;
}

}  // namespace projsurf::eval
