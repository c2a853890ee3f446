#include "eval/realistic/projector_eval.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "eval/paper/experiments.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on

namespace {
constexpr double kPi = 3.14159265358979323846;
}

CalibrationScore scoreCalibration(const Projector &believed, const Projector &truth, const SensorModel &sensor,
                                  unsigned seed) {
    CalibrationScore s;
    // Reprojection over points at 1-4 m along the true rays.
    double sum = 0;
    int n = 0;
    for (int j = 0; j <= 10; ++j)
        for (int i = 0; i <= 16; ++i) {
            const Eigen::Vector2d px(-0.5 + truth.width * i / 16.0, -0.5 + truth.height * j / 10.0);
            const Eigen::Vector3d ray = truth.ray(px);
            for (double depth : {1.0, 2.0, 3.0, 4.0}) {
                const auto q = believed.toPixel(truth.origin + depth / ray.dot(truth.axis()) * ray);
                const double e = q ? (*q - px).norm() : 1e9;
                sum += e * e;
                s.worst_px = std::max(s.worst_px, e);
                ++n;
            }
        }
    s.rms_px = std::sqrt(sum / n);
    s.origin_mm = (believed.origin - truth.origin).norm() * 1000;
    // End to end: detect on a noisy cloud with the estimate, correct, cast with the truth.
    const Scenario sc = makeScenario("wall", 2.0, 20.0);
    const RgbdFrame frame = renderFrame(sc.scene, sensor, seed);
    const Detection det = detectSurface(frame.cloud, believed, DetectorConfig{}, sc.gravity);
    if (!det.found) {
        s.problem = "no surface found: " + det.reason;
        return s;
    }
    const WallPicture w =
        pictureOnWall(believed, truth, sc.scene, det.rectangle, cv::Size(believed.width, believed.height));
    if (!w.ok) {
        s.problem = w.problem;
        return s;
    }
    const Rectangle shown = letterbox(det.rectangle, believed.aspect());
    s.eq8_pct = w.errors.worst_pct();
    for (int i = 0; i < 4; ++i) s.corner_mm = std::max(s.corner_mm, (w.corners[i] - shown.corners[i]).norm() * 1000);
    const Eigen::Vector3d n_wall = sc.wall.normal.normalized();
    Eigen::Vector3d up = -sc.gravity + sc.gravity.dot(n_wall) * n_wall;
    up.normalize();
    for (const auto &edge :
         {Eigen::Vector3d(w.corners[0] - w.corners[3]), Eigen::Vector3d(w.corners[1] - w.corners[2])}) {
        const Eigen::Vector3d e = (edge - edge.dot(n_wall) * n_wall).normalized();
        s.upright_deg = std::max(s.upright_deg, std::acos(std::clamp(e.dot(up), -1.0, 1.0)) * 180 / kPi);
    }
    s.ok = true;
    return s;
}

std::vector<ProjectorEvalRow> runProjectorEval(unsigned seed, bool quick) {
    const SensorModel sensor;
    std::vector<std::pair<RigSpec, bool>> jobs;  // rig, relief pose
    std::vector<RigSpec> rigs = evalRigs();
    if (quick) rigs = {rigs[1], rigs.back()};
    for (const auto &r : rigs) jobs.push_back({r, false});
    jobs.push_back({RigSpec{1.0, 1.0, 1.005, -0.05}, true});
    std::vector<ProjectorEvalRow> rows;
    unsigned k = 0;
    for (const auto &[rig, relief] : jobs) {
        const auto t0 = std::chrono::steady_clock::now();
        ProjectorEvalRow row;
        row.rig = rig;
        row.sl_poses = relief ? "1 relief" : "3 flat";
        const Projector truth = projectorRig(rig);
        // The disc method, given the projector's true field of view (its spec sheet).
        Projector spec = truth;
        const auto fov = fieldOfView(truth);
        spec.fov_h = fov[0];
        spec.fov_v = fov[1];
        const CalibrationRun disc = calibrateFromSimulation(spec, sensor, 5, seed + 10 * k);
        if (disc.ok)
            row.disc = scoreCalibration(disc.projector, truth, sensor, seed + 10 * k + 1);
        else
            row.disc.problem = disc.message;
        const ProjectorFit sl =
            structuredCalibration(truth, sensor, relief ? reliefPose() : flatWallPoses(), seed + 10 * k + 2);
        if (sl.ok)
            row.structured = scoreCalibration(sl.projector, truth, sensor, seed + 10 * k + 1);
        else
            row.structured.problem = sl.problem;
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rows.push_back(row);
        ++k;
    }
    return rows;
}

namespace {

std::string cells(const CalibrationScore &s) {
    char buf[200];
    if (!s.ok && s.rms_px == 0) return "| fails: " + s.problem + " | | | | | |";
    if (!s.ok)
        std::snprintf(buf, sizeof buf, "| %.2f | %.2f | %.1f | (%s) | | |", s.rms_px, s.worst_px, s.origin_mm,
                      s.problem.c_str());
    else
        std::snprintf(buf, sizeof buf, "| %.2f | %.2f | %.1f | %.3f | %.1f | %.3f |", s.rms_px, s.worst_px, s.origin_mm,
                      s.eq8_pct, s.corner_mm, s.upright_deg);
    return buf;
}

}  // namespace

std::string projectorEvalMarkdown(const std::vector<ProjectorEvalRow> &rows) {
    std::string md =
        "## Real projectors: disc vs structured-light calibration\n\n"
        "Simulated projectors (the example projector with a vertical lens offset, roll, fy scaled, radial k1); "
        "reprojection of points at 1-4 m (px), origin error (mm), and end to end on a noisy Kinect cloud of a wall "
        "at 2 m, 20 deg: eq. 8 worst error (%), farthest corner from the detected rectangle (mm), tilt of the "
        "picture's sides from the vertical (deg). Targets for structured light: <= 0.5 px RMS, <= 1.5 px worst, "
        "origin <= 5 mm, eq. 8 <= 0.2 %, corners <= 5 mm, upright <= 0.1 deg.\n\n"
        "| rig | method | RMS px | worst px | origin mm | eq. 8 % | corner mm | upright deg |\n"
        "|---|---|---|---|---|---|---|---|\n";
    for (const auto &r : rows) {
        md += "| " + r.rig.name() + " | disc (paper) " + cells(r.disc) + "\n";
        md += "| | structured light, " + r.sl_poses + " " + cells(r.structured) + "\n";
    }
    return md + "\n";
}

std::string projectorEvalSummary(const std::vector<ProjectorEvalRow> &rows) {
    CalibrationScore w;
    int failed = 0;
    for (const auto &r : rows) {
        const auto &s = r.structured;
        if (!s.ok) ++failed;
        w.rms_px = std::max(w.rms_px, s.rms_px);
        w.worst_px = std::max(w.worst_px, s.worst_px);
        w.origin_mm = std::max(w.origin_mm, s.origin_mm);
        w.eq8_pct = std::max(w.eq8_pct, s.eq8_pct);
        w.corner_mm = std::max(w.corner_mm, s.corner_mm);
        w.upright_deg = std::max(w.upright_deg, s.upright_deg);
    }
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "projector rigs: %zu, structured light worst: RMS %.2f px (<= 0.5), worst %.2f px (<= 1.5), origin "
                  "%.1f mm (<= 5), eq. 8 %.3f %% (<= 0.2), corners %.1f mm (<= 5), upright %.3f deg (<= 0.1)%s",
                  rows.size(), w.rms_px, w.worst_px, w.origin_mm, w.eq8_pct, w.corner_mm, w.upright_deg,
                  failed ? " (some failed)" : "");
    return buf;
}

}  // namespace projsurf::eval
