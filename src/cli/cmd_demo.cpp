// projsurf demo: from nothing, a simulated robot calibrates its projector, finds where to
// project on a wall, corrects a bundled picture and shows it; writes the pictures to one folder
// and prints the numbers. Deterministic for a seed, a few seconds.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "cli/commands.hpp"
#include "eval/demo/demo.hpp"
#include "eval/demo/lens_offset_demo.hpp"
#include "eval/demo/plan_demo.hpp"
#include "eval/demo/walk_in.hpp"
#include "eval/plot/plot.hpp"
#include "projsurf/frontend/render/overlay.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

struct DemoCliOptions {
    std::string out = "out/demo";
    unsigned seed = 1;
    std::string scenario = "wall";
    double distance = 2.0;     // m (paper 4.1: 1-3 m)
    double angle_deg = 17.19;  // deg (paper 4.1)
};

/// A person walking into the beam of the placed picture (blanking), frame by frame, and the
/// last frame with and without blanking side by side.
struct WalkInPictures {
    std::vector<eval::WalkInShot> shots;  ///< empty when the demo did not walk in
    cv::Mat row, compare;
};

/// Where the robot should stand for a bigger picture, and the picture shown from there.
struct PlanPictures {
    eval::PlanShot planned;
    cv::Mat views;  ///< before and after the move; empty when nothing was found after it
};

/// Everything the demo writes, composed before anything is written.
struct DemoPictures {
    cv::Mat overlay;
    cv::Mat audience;  ///< uncorrected and corrected, side by side
    WalkInPictures walk;
    PlanPictures plan;
    eval::LensOffsetDemo lens;
    cv::Mat lens_views;
};

void printErrors(const char *what, const eval::WallPicture &w) {
    if (!w.ok) {
        std::printf("  %-28s (not on the wall: %s)\n", what, w.problem.c_str());
        return;
    }
    std::printf("  %-28s horizontal %.2f %%, vertical %.2f %%, diagonals %.2f %%\n", what, w.errors.horizontal_pct,
                w.errors.vertical_pct, w.errors.diagonal_pct);
}

/// The projector the robot believes it has: the calibrated one, the true one when calibration failed.
const Projector &believedProjector(const eval::DemoResult &r) {
    return r.calibration.ok ? r.calibration.projector : r.true_projector;
}

/// Refuses a pose outside the simulation's range and an --out that is a file.
void checkDemoOptions(const DemoCliOptions &o) {
    if (!(o.distance >= 0.5 && o.distance <= 10.0)) throw InputError("--distance", "must be between 0.5 and 10 m");
    if (!(std::abs(o.angle_deg) < 75.0)) throw InputError("--angle-deg", "must be within +-75 degrees");
    std::error_code ec;
    const fs::path out(o.out);
    if (fs::exists(out, ec) && !fs::is_directory(out, ec)) throw InputError(o.out, "exists and is not a directory");
}

eval::DemoOptions demoOptions(const DemoCliOptions &o) {
    eval::DemoOptions d;
    d.scenario = o.scenario;
    d.distance = o.distance;
    d.angle_deg = o.angle_deg;
    d.seed = o.seed;
    return d;
}

/// Runs the demo; an unknown scenario is the --scenario option's error.
eval::DemoResult runDemoNamingTheScenario(const eval::DemoOptions &d) {
    try {
        return eval::runDemo(d);
    } catch (const std::invalid_argument &e) {
        throw InputError("--scenario", e.what());
    }
}

WalkInPictures walkInPictures(const eval::DemoResult &r, const DemoCliOptions &o) {
    WalkInPictures p;
    if (!(r.keystone && o.distance >= 1.2)) return p;
    p.shots =
        eval::walkInShots(r.scenario.scene, r.scenario.wall, r.true_projector, believedProjector(r), r.detection.plane,
                          r.framebuffer, r.audience_view, r.audience_light, 0.55 * o.distance, o.seed);
    std::vector<cv::Mat> row;
    for (std::size_t k = 0; k < p.shots.size(); ++k) {
        char caption[160];
        std::snprintf(caption, sizeof caption, "(%zu) walking in: %d px blanked, %ld lit px on the person", k + 1,
                      p.shots[k].blanked_pixels, p.shots[k].score.lit_on_person);
        row.push_back(eval::withCaption(p.shots[k].view, caption));
    }
    cv::hconcat(row, p.row);
    cv::hconcat(
        eval::withCaption(p.shots.back().view_unblanked, "(a) without blanking: the picture lands on the person"),
        eval::withCaption(p.shots.back().view, "(b) blanked by projsurf"), p.compare);
    return p;
}

PlanPictures planPictures(const eval::DemoResult &r, unsigned seed) {
    PlanPictures p;
    if (!r.detection.found) return p;
    p.planned = eval::planShot(r.scenario, r.true_projector, believedProjector(r), r.frame.cloud, r.config, r.picture,
                               r.audience_view, r.audience_light, seed);
    if (p.planned.view_after.empty()) return p;
    char before[120], after[160];
    std::snprintf(before, sizeof before, "(a) where the robot stands: %.2f m^2", r.detection.rectangle.area());
    std::snprintf(after, sizeof after, "(b) after the planned move (%.2f m): %.2f m^2 (%.2f predicted)",
                  p.planned.plan.translation.norm(), p.planned.after.rectangle.area(), p.planned.plan.predicted.area());
    cv::hconcat(eval::withCaption(r.audience_corrected, before), eval::withCaption(p.planned.view_after, after),
                p.views);
    return p;
}

std::string lensCaption(const std::string &what, const eval::LensOffsetShot &s) {
    char buf[240];
    if (s.ok)
        std::snprintf(buf, sizeof buf, "%s: eq. 8 worst %.2f %%", what.c_str(), s.on_wall.errors.worst_pct());
    else
        std::snprintf(buf, sizeof buf, "%s: %s", what.c_str(), s.problem.c_str());
    return std::string(buf);
}

/// A real projector (lens offset and roll) calibrated by the paper's disc and by structured
/// light, the picture through each side by side.
cv::Mat lensOffsetViews(const eval::LensOffsetDemo &lens) {
    cv::Mat views;
    cv::hconcat(eval::withCaption(lens.disc.audience,
                                  lensCaption("(a) lens offset 100 %, roll 1 deg; disc calibration", lens.disc)),
                eval::withCaption(lens.structured.audience,
                                  lensCaption("(b) the same projector; structured-light calibration", lens.structured)),
                views);
    return views;
}

DemoPictures demoPictures(const eval::DemoResult &r, const DemoCliOptions &o) {
    DemoPictures p;
    const CameraIntrinsics camera = sim::SensorModel().camera;
    p.overlay = renderOverlay(r.frame.cloud, r.detection, r.config, &camera, r.frame.rgb);
    cv::hconcat(eval::withCaption(r.audience_uncorrected, "(a) projected as is: keystoned"),
                eval::withCaption(r.audience_corrected, "(b) corrected by projsurf"), p.audience);
    p.walk = walkInPictures(r, o);
    p.plan = planPictures(r, o.seed);
    // A real projector: its lens throws the picture above its axis and it is mounted with a little roll.
    p.lens = eval::runLensOffsetDemo(r.scenario, r.picture, r.audience_view, r.audience_light, o.seed);
    p.lens_views = lensOffsetViews(p.lens);
    return p;
}

void writeDemoFolder(const std::string &folder, const eval::DemoResult &r, const DemoPictures &p) {
    const fs::path out(folder);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw InputError(folder, "cannot create the directory: " + ec.message());
    writeImageAtomic((out / "lens_offset.png").string(), p.lens_views);
    writeImageAtomic((out / "overlay.png").string(), p.overlay);
    writeImageAtomic((out / "framebuffer.png").string(), r.framebuffer);
    writeImageAtomic((out / "audience.png").string(), p.audience);
    writeImageAtomic((out / "camera_rgb.png").string(), r.frame.rgb);
    writeImageAtomic((out / "picture.png").string(), r.picture);
    const Projector &believed = believedProjector(r);
    writeCalibration((out / "calib.yaml").string(), believed);
    if (!p.plan.views.empty()) writeImageAtomic((out / "plan.png").string(), p.plan.views);
    if (!p.walk.shots.empty()) {
        writeImageAtomic((out / "walk_in.png").string(), p.walk.row);
        writeImageAtomic((out / "walk_in_compare.png").string(), p.walk.compare);
    }
    writeFileAtomic((out / "detection.json").string(),
                    detectionToJson(r.detection, r.config, &believed).dump(2) + "\n");
}

void printCalibrationAndDetection(const DemoCliOptions &o, int captures, const eval::DemoResult &r) {
    std::printf("projsurf demo: scenario '%s', wall %.2f m away at %.2f deg, seed %u\n", r.scenario.name.c_str(),
                o.distance, o.angle_deg, o.seed);
    if (r.calibration.ok)
        std::printf(
            "calibration from %d simulated captures: axis off by %.2f deg, lens centre off by %.1f mm "
            "(worst centroid %.1f mm from the axis)\n",
            captures, r.calibration.axis_error_deg, 1000.0 * r.calibration.origin_error_m,
            1000.0 * r.calibration.max_residual_m);
    else
        std::printf("calibration failed (%s); using the true projector\n", r.calibration.message.c_str());
    if (r.detection.found)
        std::printf("detected: %.2f x %.2f m = %.3f m^2 on a plane at %.1f deg (%d inliers)\n",
                    r.detection.rectangle.width, r.detection.rectangle.height, r.detection.rectangle.area(),
                    r.detection.orientation_deg, r.detection.inliers);
    else
        std::printf("not detected: %s\n", r.detection.reason.c_str());
    if (r.truth.found)
        std::printf("ground truth: %.2f x %.2f m = %.3f m^2 on the %s -> %s%s%s\n", r.truth.best.rectangle.width,
                    r.truth.best.rectangle.height, r.truth.best.rectangle.area(), r.truth.best.label.c_str(),
                    r.score.success ? "success" : "FAIL", r.score.why.empty() ? "" : ": ", r.score.why.c_str());
}

void printPictureOnTheWall(const eval::DemoResult &r) {
    std::printf("eq. 8 errors of the picture on the wall (cast through the true projector):\n");
    printErrors("corrected:", r.corrected_on_wall);
    printErrors("uncorrected (as is):", r.uncorrected_on_wall);
    if (!r.keystone_problem.empty()) std::printf("  (no correction: %s)\n", r.keystone_problem.c_str());
}

void printWalkInAndPlan(const eval::DemoResult &r, const DemoPictures &p) {
    const std::vector<eval::WalkInShot> &walk = p.walk.shots;
    for (std::size_t k = 0; k < walk.size(); ++k)
        std::printf(
            "walk-in frame %zu (person at x = %.2f m): %d px blanked in %.2f ms; %ld of %ld px on the person "
            "lit; %.1f %% of the picture 10 cm clear of them lit\n",
            k + 1, walk[k].person_x, walk[k].blanked_pixels, walk[k].mask_ms, walk[k].score.lit_on_person,
            walk[k].score.on_person, 100.0 * walk[k].score.farLitShare());
    const eval::PlanShot &planned = p.plan.planned;
    if (planned.plan.found)
        std::printf("plan: move %.2f m: predicted %.3f m^2, found there %.3f m^2 (%.3f m^2 where it stands)\n",
                    planned.plan.translation.norm(), planned.plan.predicted.area(),
                    planned.after.found ? planned.after.rectangle.area() : 0.0, r.detection.rectangle.area());
    else if (r.detection.found)
        std::printf("plan: %s\n", planned.plan.reason.c_str());
}

void printLensShot(const char *what, const eval::LensOffsetShot &s) {
    if (s.ok)
        std::printf("  %-22s eq. 8 h %.2f %%, v %.2f %%, diag %.2f %% (%.2f x %.2f m found)\n", what,
                    s.on_wall.errors.horizontal_pct, s.on_wall.errors.vertical_pct, s.on_wall.errors.diagonal_pct,
                    s.detection.rectangle.width, s.detection.rectangle.height);
    else
        std::printf("  %-22s %s\n", what, s.problem.c_str());
}

void printLensOffset(const eval::LensOffsetDemo &lens) {
    std::printf("lens-offset projector (%s), the picture on the wall through it:\n", lens.rig.name().c_str());
    printLensShot("disc calibration:", lens.disc);
    printLensShot("structured light:", lens.structured);
}

void printStageTimesAndFiles(const std::string &folder, const eval::DemoResult &r, const DemoPictures &p) {
    std::printf("time per stage (ms):");
    for (const auto &[stage, ms] : r.stage_ms) std::printf("\n  %-58s %8.1f", stage.c_str(), ms);
    std::printf(
        "\nwrote %s/: audience.png overlay.png framebuffer.png camera_rgb.png picture.png lens_offset.png calib.yaml "
        "detection.json%s\n",
        folder.c_str(),
        (std::string(p.walk.shots.empty() ? "" : " walk_in.png walk_in_compare.png") +
         (p.plan.views.empty() ? "" : " plan.png"))
            .c_str());
    std::fflush(stdout);
}

void run(const DemoCliOptions &o) {
    checkDemoOptions(o);
    const eval::DemoOptions d = demoOptions(o);
    const eval::DemoResult r = runDemoNamingTheScenario(d);
    const DemoPictures pictures = demoPictures(r, o);
    writeDemoFolder(o.out, r, pictures);
    printCalibrationAndDetection(o, d.captures, r);
    printPictureOnTheWall(r);
    printWalkInAndPlan(r, pictures);
    printLensOffset(pictures.lens);
    printStageTimesAndFiles(o.out, r, pictures);
}

}  // namespace

void addDemoCommand(CLI::App &app) {
    auto o = std::make_shared<DemoCliOptions>();
    auto *sub = app.add_subcommand(
        "demo", "Simulate a robot: calibrate, detect, correct a picture, and show it with and without correction");
    sub->add_option("--out", o->out, "Output directory (default out/demo, created if missing)");
    sub->add_option("--seed", o->seed, "Noise and RANSAC seed (default 1)");
    sub->add_option("--scenario", o->scenario, "Scene (see projsurf simulate --list; default wall)");
    sub->add_option("--distance", o->distance, "Camera to wall along the optical axis, m (default 2)");
    sub->add_option("--angle-deg", o->angle_deg, "Wall normal vs camera z, deg (default 17.19, paper 4.1)");
    sub->callback([o] { run(*o); });
}

}  // namespace projsurf::cli
