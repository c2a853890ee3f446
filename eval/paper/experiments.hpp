#pragma once
// Re-running the paper's experiments (section 4) in simulation: detections over rounds of
// sensor noise per pose, scored against ground truth and by the paper's own criterion,
// outlier counts of the surface check (Fig 15), and the keystone errors of eq. 8 (Table 3)
// with a projector calibrated from simulated captures. Knows nothing of files.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "eval/paper/scoring.hpp"
#include "projsurf/calibration/calibration.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::eval {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// px: a second ground-truth verdict lets the rectangle leave the framebuffer by this much (the
/// paper's 2 cm raster can put a corner a cell beyond the projector's footprint; its picture
/// would then be cut by a thin band), so other failures are not hidden behind that one.
constexpr double kFramebufferSlackPx = 40.0;

/// A way of detecting that the evaluation compares.
struct MethodVariant {
    std::string name;       ///< "paper-concave", "paper-convex", "default"
    DetectorConfig config;  ///< the seed is set per trial (gravity is the scene's)
};
MethodVariant paperVariant(HullKind hull);
MethodVariant defaultVariant();

/// One scored detection on one simulated frame.
struct Trial {
    std::string scenario;
    double distance = 0.0;  ///< m
    double angle_deg = 0.0;
    int round = 0;
    unsigned seed = 0;   ///< sensor noise and RANSAC seed
    std::string method;  ///< MethodVariant::name
    bool found = false;
    bool checked = false;   ///< a rectangle reached the surface check
    bool accepted = false;  ///< the checker's decision on it
    bool checked_valid =
        false;  ///< ground truth (with the framebuffer slack): that rectangle is on a surface, upright and free
    int check_points = 0;
    int outliers = 0;
    double area = 0.0;               ///< m^2 of the found rectangle (0 when not found)
    double time_ms = 0.0;            ///< detection, in-process
    std::string surface;             ///< label of the true surface the rectangle is on ("" when none)
    Score score;                     ///< against ground truth
    bool slack_success = false;      ///< ground truth, but corners may leave the framebuffer by kFramebufferSlackPx
    bool paper_success = false;      ///< paper 4.1: area within tolerance of the best round (applyPaperCriterion)
    double paper_area_error = kNaN;  ///< best round's area - this area, m^2 (found rounds only)
};

/// The paper's criterion (section 4.1) over the rounds of one pose and method: the best of
/// the areas found; a round succeeds when it found something within `tolerance` (m^2) of that
/// best. `areas[i]` is nullopt when round i found nothing (a failure, no area error).
struct RoundsVerdict {
    double best_area = kNaN;  ///< NaN when no round found anything
    std::vector<bool> success;
    std::vector<double> area_error;  ///< best - area, NaN for rounds that found nothing
};
RoundsVerdict paperCriterion(const std::vector<std::optional<double>> &areas, double tolerance = 0.05);

/// Applies paperCriterion to every group of trials with the same scenario, distance, angle
/// and method.
void applyPaperCriterion(std::vector<Trial> &trials, double tolerance = 0.05);

/// A trial from a detection already made: scores it against `truth`, also the rectangle that a
/// rejecting checker was shown.
Trial scoreTrial(const Detection &detection, const sim::GroundTruth &truth, const Projector &projector,
                 const Eigen::Vector3d &gravity, double aspect);

/// Aggregates of a set of trials.
struct Summary {
    int n = 0, found = 0, checked = 0, accepted = 0;
    int truth_success = 0;           ///< ground truth (scoreDetection)
    int slack_success = 0;           ///< ground truth with kFramebufferSlackPx
    int paper_success = 0;           ///< paper criterion
    int decisions_correct = 0;       ///< checked rounds where accepted == checked_valid
    double truth_area_error = kNaN;  ///< mean |best true area - area| over all rounds (not found: best), m^2
    double paper_area_error = kNaN;  ///< mean (best round - area) over found rounds, m^2
    double mean_area = kNaN;         ///< over found rounds, m^2
    double best_area = kNaN;         ///< mean ground-truth best area, m^2
    double outliers_median = kNaN, outliers_min = kNaN, outliers_max = kNaN;  ///< checked rounds
    double outlier_share_median = kNaN;                                       ///< outliers / points checked
    double time_median_ms = kNaN, time_p90_ms = kNaN;
    double truthRatePct() const { return n ? 100.0 * truth_success / n : kNaN; }
    double slackRatePct() const { return n ? 100.0 * slack_success / n : kNaN; }
    double paperRatePct() const { return n ? 100.0 * paper_success / n : kNaN; }
    double acceptedPct() const { return checked ? 100.0 * accepted / checked : kNaN; }
    double foundPct() const { return n ? 100.0 * found / n : kNaN; }
};
Summary summarize(const std::vector<const Trial *> &trials);
std::vector<const Trial *> select(const std::vector<Trial> &trials, const std::function<bool(const Trial &)> &keep);
/// Quantile q in [0, 1] (linear interpolation); NaN for an empty set.
double quantile(std::vector<double> values, double q);

/// A projector calibrated from simulated captures of the true one (paper 3.1).
struct CalibrationRun {
    unsigned seed = 0;
    bool ok = false;
    std::string message;
    Projector projector;           ///< estimated (the true one's resolution and FOV)
    double axis_error_deg = kNaN;  ///< estimated vs true direction
    double origin_error_m = kNaN;  ///< estimated vs true lens centre
    double max_residual_m = kNaN;  ///< worst centroid distance to the fitted axis
    double ms = 0.0;               ///< render + calibrate
};
CalibrationRun calibrateFromSimulation(const Projector &truth, const sim::SensorModel &sensor, int captures,
                                       unsigned seed);

/// Where a picture shown in `rect` lands: framebuffer corners computed with the `believed`
/// projector (eq. 7 + letterbox), cast through the `real` projector onto the scene.
struct WallPicture {
    bool ok = false;
    std::string problem;
    Corners2 framebuffer_px{};
    Corners3 corners{};         ///< on the scene, TL, TR, BR, BL
    ShapeErrors errors;         ///< eq. 8
    double overshoot_px = 0.0;  ///< how far the picture's corners leave the framebuffer (it is cut there)
};
/// `tolerance_px`: how far the rectangle may leave the believed framebuffer (computeKeystone);
/// the paper's detector can return rectangles a raster cell beyond it, which its correction
/// would show cut at the edge.
WallPicture pictureOnWall(const Projector &believed, const Projector &real, const sim::Scene &scene,
                          const Rectangle &rect, cv::Size picture, double tolerance_px = 0.5);
/// Framebuffer pixels cast through the `real` projector onto the scene (e.g. the whole
/// framebuffer, uncorrected); ok = false when a ray misses.
WallPicture framebufferOnWall(const Projector &real, const sim::Scene &scene, const Corners2 &framebuffer_px);

/// One Table 3 measurement.
struct KeystoneTrial {
    double distance = 0.0, angle_deg = 0.0;
    int round = 0;
    std::string method;
    bool found = false;
    bool shown = false;         ///< the picture could be put in the framebuffer and landed on the scene
    double overshoot_px = 0.0;  ///< the picture's corners beyond the framebuffer edge (cut), px
    std::string problem;
    ShapeErrors errors;
    double axis_error_deg = kNaN;  ///< of the calibration used
};

/// One pose of an experiment and the methods run on it.
struct PoseJob {
    std::string scenario;
    double distance = 0.0, angle_deg = 0.0;
    std::vector<MethodVariant> variants;
    bool keystone = false;  ///< Table 3: detect with the calibrated projector, measure eq. 8
};

struct EvalPlan {
    int rounds = 10;  ///< noise seeds per pose (paper: 10 detection rounds)
    unsigned seed = 1;
    int calibration_captures = 5;         ///< paper 3.1.1: 5 positions
    double truth_cell = 0.01;             ///< m, ground-truth raster (area error < 0.01 m^2 at 3 m)
    double keystone_tolerance_px = 40.0;  ///< Table 3: measure pictures cut at the edge by up to this
    std::vector<PoseJob> jobs;
};

/// The paper's section 4 as a plan: Tables 1-2 and Fig 15 poses (paper method with the concave
/// hull, the convex hull too on the plain wall, and the default method) and the Table 3 poses.
/// `quick`: 2 m only (Table 3: 2 m), for tests and CI.
EvalPlan paperEvalPlan(int rounds, bool quick, unsigned seed = 1);

struct EvalResults {
    std::vector<Trial> trials;
    std::vector<KeystoneTrial> keystone;
    std::vector<CalibrationRun> calibrations;  ///< one per round, used by the Table 3 jobs
    int rounds = 0;
    double seconds = 0.0;
};

/// Called after every frame: frames done, frames in all, what is being done.
using Progress = std::function<void(int done, int total, const std::string &what)>;

/// Runs the plan sequentially (per-core timings), deterministically for its seed.
EvalResults runEval(const EvalPlan &plan, const Progress &progress = nullptr);

}  // namespace projsurf::eval
