#include "eval/paper/experiments.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "projsurf/sim/calibration_captures.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double mean(const std::vector<double> &v) {
    if (v.empty()) return kNaN;
    double s = 0.0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

/// The true surface a rectangle lies on (the one whose plane is nearest its corners).
const SurfaceTruth *surfaceOf(const Rectangle &r, const GroundTruth &truth, double tolerance) {
    const SurfaceTruth *best = nullptr;
    double best_err = tolerance;
    for (const auto &s : truth.surfaces) {
        double worst = 0.0;
        for (const auto &c : r.corners) worst = std::max(worst, std::abs(s.plane.signedDistance(c)));
        if (worst <= best_err) {
            best_err = worst;
            best = &s;
        }
    }
    return best;
}

std::string describePose(const std::string &scenario, double distance, double angle) {
    std::ostringstream s;
    s.precision(4);
    s << scenario << " " << distance << " m " << angle << " deg";
    return s.str();
}

}  // namespace

MethodVariant paperVariant(HullKind hull) {
    MethodVariant v;
    v.name = hull == HullKind::Concave ? "paper-concave" : "paper-convex";
    v.config.method = Method::Paper;
    v.config.paper.hull = hull;
    return v;
}

MethodVariant defaultVariant() {
    MethodVariant v;
    v.name = "default";
    v.config.method = Method::Default;
    return v;
}

RoundsVerdict paperCriterion(const std::vector<std::optional<double>> &areas, double tolerance) {
    RoundsVerdict v;
    for (const auto &a : areas)
        if (a && (std::isnan(v.best_area) || *a > v.best_area)) v.best_area = *a;
    for (const auto &a : areas) {
        if (!a) {
            v.success.push_back(false);
            v.area_error.push_back(kNaN);
            continue;
        }
        const double err = v.best_area - *a;
        v.area_error.push_back(err);
        v.success.push_back(err <= tolerance + 1e-12);
    }
    return v;
}

void applyPaperCriterion(std::vector<Trial> &trials, double tolerance) {
    std::map<std::tuple<std::string, double, double, std::string>, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < trials.size(); ++i) {
        const Trial &t = trials[i];
        groups[{t.scenario, t.distance, t.angle_deg, t.method}].push_back(i);
    }
    for (const auto &[key, idx] : groups) {
        std::vector<std::optional<double>> areas;
        for (std::size_t i : idx)
            areas.push_back(trials[i].found ? std::optional<double>(trials[i].area) : std::nullopt);
        const RoundsVerdict v = paperCriterion(areas, tolerance);
        for (std::size_t k = 0; k < idx.size(); ++k) {
            trials[idx[k]].paper_success = v.success[k];
            trials[idx[k]].paper_area_error = v.area_error[k];
        }
    }
}

Trial scoreTrial(const Detection &det, const GroundTruth &truth, const Projector &projector,
                 const Eigen::Vector3d &gravity, double aspect) {
    Trial t;
    t.found = det.found;
    const auto total = det.timing_ms.find("total");
    t.time_ms = total != det.timing_ms.end() ? total->second : 0.0;
    t.checked = det.rectangle.area() > 0.0;
    t.accepted = t.checked && det.surface_check.accepted;
    t.check_points = det.surface_check.points;
    t.outliers = det.surface_check.outliers;
    t.area = det.found ? det.rectangle.area() : 0.0;
    t.score = scoreDetection(det, truth, projector, gravity, aspect);
    ScoreOptions slack;
    slack.pixel_tolerance = kFramebufferSlackPx;
    t.slack_success = scoreDetection(det, truth, projector, gravity, aspect, slack).success;
    if (t.checked) {
        Detection shown = det;  // the rectangle the checker judged, as if it had been accepted
        shown.found = true;
        t.checked_valid = scoreDetection(shown, truth, projector, gravity, aspect, slack).valid;
        if (const SurfaceTruth *s = surfaceOf(det.rectangle, truth, ScoreOptions{}.plane_tolerance))
            t.surface = s->label;
    }
    return t;
}

double quantile(std::vector<double> values, double q) {
    values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return std::isnan(x); }), values.end());
    if (values.empty()) return kNaN;
    std::sort(values.begin(), values.end());
    const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
    const std::size_t i = static_cast<std::size_t>(std::floor(pos));
    const std::size_t j = std::min(i + 1, values.size() - 1);
    return values[i] + (pos - static_cast<double>(i)) * (values[j] - values[i]);
}

std::vector<const Trial *> select(const std::vector<Trial> &trials, const std::function<bool(const Trial &)> &keep) {
    std::vector<const Trial *> out;
    for (const auto &t : trials)
        if (keep(t)) out.push_back(&t);
    return out;
}

Summary summarize(const std::vector<const Trial *> &trials) {
    Summary s;
    std::vector<double> truth_err, paper_err, areas, best, outliers, shares, times;
    for (const Trial *t : trials) {
        ++s.n;
        s.found += t->found;
        s.truth_success += t->score.success;
        s.slack_success += t->slack_success;
        s.paper_success += t->paper_success;
        truth_err.push_back(std::abs(t->score.area_error));
        best.push_back(t->score.best_area);
        if (!std::isnan(t->paper_area_error)) paper_err.push_back(t->paper_area_error);
        if (t->found) areas.push_back(t->area);
        if (t->checked) {
            ++s.checked;
            s.accepted += t->accepted;
            s.decisions_correct += (t->accepted == t->checked_valid);
            outliers.push_back(t->outliers);
            if (t->check_points > 0) shares.push_back(static_cast<double>(t->outliers) / t->check_points);
        }
        times.push_back(t->time_ms);
    }
    s.truth_area_error = mean(truth_err);
    s.paper_area_error = mean(paper_err);
    s.mean_area = mean(areas);
    s.best_area = mean(best);
    s.outliers_median = quantile(outliers, 0.5);
    s.outliers_min = quantile(outliers, 0.0);
    s.outliers_max = quantile(outliers, 1.0);
    s.outlier_share_median = quantile(shares, 0.5);
    s.time_median_ms = quantile(times, 0.5);
    s.time_p90_ms = quantile(times, 0.9);
    return s;
}

CalibrationRun calibrateFromSimulation(const Projector &truth, const SensorModel &sensor, int captures, unsigned seed) {
    const auto t0 = Clock::now();
    CalibrationRun run;
    run.seed = seed;
    const std::vector<RgbdFrame> frames = renderCalibrationCaptures(truth, sensor, captures, seed);
    CalibrationConfig config;
    config.width = truth.width;
    config.height = truth.height;
    config.fov_h = truth.fov_h;
    config.fov_v = truth.fov_v;
    const Calibration cal = calibrateProjector(captureImages(frames), sensor.camera, config);
    run.ok = cal.ok();
    run.message = cal.message;
    if (run.ok) {
        run.projector = cal.projector;
        run.axis_error_deg = angleBetweenDeg(cal.projector.direction, truth.direction);
        run.origin_error_m = (cal.projector.origin - truth.origin).norm();
        run.max_residual_m = cal.axis.max_m;
    }
    run.ms = msSince(t0);
    return run;
}

WallPicture pictureOnWall(const Projector &believed, const Projector &real, const Scene &scene, const Rectangle &rect,
                          cv::Size picture, double tolerance_px) {
    const KeystoneResult k = computeKeystone(believed, rect, picture, tolerance_px);
    if (!k.keystone) {
        WallPicture w;
        w.problem = k.problem;
        return w;
    }
    WallPicture w = framebufferOnWall(real, scene, k.keystone->picture_px);
    for (const auto &p : k.keystone->picture_px) {
        const double out =
            std::max({-0.5 - p.x(), p.x() - (believed.width - 0.5), -0.5 - p.y(), p.y() - (believed.height - 0.5)});
        w.overshoot_px = std::max(w.overshoot_px, out);
    }
    return w;
}

WallPicture framebufferOnWall(const Projector &real, const Scene &scene, const Corners2 &framebuffer_px) {
    WallPicture w;
    w.framebuffer_px = framebuffer_px;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector3d dir = real.ray(framebuffer_px[i]);
        const std::optional<Hit> hit = castRay(scene, real.origin, dir);
        if (!hit) {
            w.problem = "a corner ray of the picture misses the scene";
            return w;
        }
        w.corners[i] = real.origin + hit->t * dir;
    }
    w.errors = shapeErrors(w.corners);
    w.ok = true;
    return w;
}

EvalPlan paperEvalPlan(int rounds, bool quick, unsigned seed) {
    EvalPlan plan;
    plan.rounds = std::max(1, rounds);
    plan.seed = seed;
    for (const PaperExperiment &e : paperExperiments()) {
        const bool keystone = e.source.find("Table 3") != std::string::npos;
        for (double d : e.distances) {
            if (quick && std::abs(d - 2.0) > 1e-9) continue;
            for (double a : e.angles_deg) {
                const bool seen = std::any_of(plan.jobs.begin(), plan.jobs.end(), [&](const PoseJob &j) {
                    return j.scenario == e.scenario && j.distance == d && j.angle_deg == a && j.keystone == keystone;
                });
                if (seen) continue;
                PoseJob job;
                job.scenario = e.scenario;
                job.distance = d;
                job.angle_deg = a;
                job.keystone = keystone;
                job.variants.push_back(paperVariant(HullKind::Concave));
                if (e.scenario == "wall" && !keystone)
                    job.variants.push_back(paperVariant(HullKind::Convex));  // Table 1
                job.variants.push_back(defaultVariant());
                plan.jobs.push_back(job);
            }
        }
    }
    return plan;
}

namespace {

/// The run's progress: one step per calibration and per round of a pose.
struct EvalTicker {
    const Progress &progress;
    int total = 0;
    int done = 0;
    void tick(const std::string &what) {
        ++done;
        if (progress) progress(done, total, what);
    }
};

/// Table 3 uses a projector calibrated from simulated captures, one calibration per round.
std::vector<CalibrationRun> roundCalibrations(const EvalPlan &plan, const Projector &projector,
                                              const SensorModel &sensor, EvalTicker &ticker) {
    std::vector<CalibrationRun> calibrations;
    for (int r = 0; r < plan.rounds; ++r) {
        calibrations.push_back(calibrateFromSimulation(projector, sensor, plan.calibration_captures,
                                                       plan.seed + 500000u + 17u * static_cast<unsigned>(r)));
        ticker.tick("calibration " + std::to_string(r + 1) + "/" + std::to_string(plan.rounds));
    }
    return calibrations;
}

/// One round of Tables 1-2 and Fig 15: the detection with the true projector, scored against
/// the ground truth.
Trial detectionTrial(const Cloud &cloud, const PoseJob &job, const Scenario &sc, const GroundTruth &truth,
                     const Projector &projector, const std::string &method, const DetectorConfig &cfg, int round) {
    const Detection det = detectSurface(cloud, projector, cfg, sc.gravity);
    Trial t = scoreTrial(det, truth, projector, sc.gravity, projector.aspect());
    t.scenario = job.scenario;
    t.distance = job.distance;
    t.angle_deg = job.angle_deg;
    t.round = round;
    t.seed = cfg.seed;
    t.method = method;
    return t;
}

/// One round of Table 3: the detection with the round's calibrated projector, and eq. 8 of
/// the corrected picture cast through the true one.
KeystoneTrial keystoneTrial(const Cloud &cloud, const PoseJob &job, const Scenario &sc, const Projector &projector,
                            const CalibrationRun &cal, const std::string &method, const DetectorConfig &cfg, int round,
                            double tolerance_px) {
    KeystoneTrial k;
    k.distance = job.distance;
    k.angle_deg = job.angle_deg;
    k.round = round;
    k.method = method;
    k.axis_error_deg = cal.axis_error_deg;
    if (!cal.ok) {
        k.problem = "calibration failed: " + cal.message;
        return k;
    }
    const Detection det = detectSurface(cloud, cal.projector, cfg, sc.gravity);
    k.found = det.found;
    if (!det.found) {
        k.problem = "not found: " + det.reason;
        return k;
    }
    const WallPicture w = pictureOnWall(cal.projector, projector, sc.scene, det.rectangle,
                                        cv::Size(projector.width, projector.height), tolerance_px);
    k.shown = w.ok;
    k.overshoot_px = w.overshoot_px;
    k.problem = w.problem;
    k.errors = w.errors;
    return k;
}

/// Every round of the plan's j-th pose, each method on the same noisy frame.
void runPoseJob(const EvalPlan &plan, std::size_t j, const SensorModel &sensor, const Projector &projector,
                EvalResults &res, EvalTicker &ticker) {
    const PoseJob &job = plan.jobs[j];
    const Scenario sc = makeScenario(job.scenario, job.distance, job.angle_deg);
    const std::string pose =
        (job.keystone ? "table 3: " : "") + describePose(job.scenario, job.distance, job.angle_deg);
    GroundTruth truth;
    if (!job.keystone) {
        TruthOptions topt;
        topt.cell = plan.truth_cell;
        topt.aspect = projector.aspect();
        truth = computeGroundTruth(sc.scene, sensor, projector, sc.gravity, topt);
    }
    for (int r = 0; r < plan.rounds; ++r) {
        const unsigned seed = plan.seed + 1000u * static_cast<unsigned>(j) + static_cast<unsigned>(r);
        const RgbdFrame frame = renderFrame(sc.scene, sensor, seed);
        for (const MethodVariant &v : job.variants) {
            DetectorConfig cfg = v.config;
            cfg.seed = seed;
            if (!job.keystone)
                res.trials.push_back(detectionTrial(frame.cloud, job, sc, truth, projector, v.name, cfg, r));
            else
                res.keystone.push_back(keystoneTrial(frame.cloud, job, sc, projector, res.calibrations[r], v.name, cfg,
                                                     r, plan.keystone_tolerance_px));
        }
        ticker.tick(pose);
    }
}

}  // namespace

EvalResults runEval(const EvalPlan &plan, const Progress &progress) {
    const auto t0 = Clock::now();
    EvalResults res;
    res.rounds = plan.rounds;
    const SensorModel sensor;  // Kinect v1 class, noisy
    const Projector projector = exampleProjector();
    const bool any_keystone =
        std::any_of(plan.jobs.begin(), plan.jobs.end(), [](const PoseJob &j) { return j.keystone; });
    EvalTicker ticker{progress, static_cast<int>(plan.jobs.size()) * plan.rounds + (any_keystone ? plan.rounds : 0)};
    if (progress) progress(0, ticker.total, "starting");
    if (any_keystone) res.calibrations = roundCalibrations(plan, projector, sensor, ticker);
    for (std::size_t j = 0; j < plan.jobs.size(); ++j) runPoseJob(plan, j, sensor, projector, res, ticker);
    applyPaperCriterion(res.trials);
    res.seconds = msSince(t0) / 1000.0;
    return res;
}

}  // namespace projsurf::eval
