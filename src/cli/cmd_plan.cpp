// projsurf plan: where the robot should stand so the projector shows the largest picture (or
// the shortest move showing --width), from one cloud (contract "Where to stand").
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/calibration_input.hpp"
#include "cli/colour_input.hpp"
#include "cli/commands.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/answer/plan_json.hpp"
#include "projsurf/frontend/render/plan_overlay.hpp"
#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/gravity_warnings.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/planning/stand_planner.hpp"

namespace projsurf::cli {
namespace {

struct PlanCliOptions {
    std::string cloud, depth, camera, rgb, calib, aspect, gravity, json, overlay, config_file;
    PlanOptions plan;
};

void validate(const PlanCliOptions &o) {
    if (o.cloud.empty() == o.depth.empty())
        throw InputError("arguments", "give exactly one of --cloud FILE or --depth FILE");
    if (!o.depth.empty() && o.camera.empty()) throw InputError("arguments", "--depth needs --camera camera.yaml");
    if (!(o.plan.max_move >= 0.0 && o.plan.max_move <= 10.0))
        throw InputError("--max-move", "must be between 0 and 10 m");
    if (!(o.plan.width >= 0.0 && o.plan.width <= 50.0)) throw InputError("--width", "must be between 0 and 50 m");
    for (const auto &out : {o.json, o.overlay})
        if (!out.empty()) requireWritableFile(out);
    if (!o.overlay.empty()) requireImageWriter(o.overlay);
}

void run(const PlanCliOptions &o) {
    validate(o);
    DetectorConfig cfg;
    if (!o.config_file.empty()) frontend::readDetectorConfig(o.config_file, cfg);
    if (!o.aspect.empty()) cfg.aspect = frontend::parseAspect("--aspect", o.aspect);
    const frontend::GravityChoice choice = frontend::parseGravityChoice("--gravity", o.gravity);
    const Projector projector = readCalibrationWarned(o.calib);
    std::unique_ptr<CameraIntrinsics> camera;
    if (!o.depth.empty()) camera = std::make_unique<CameraIntrinsics>(readCamera(o.camera));
    Cloud cloud = o.cloud.empty() ? readDepthCloud(o.depth, o.camera) : readCloud(o.cloud);
    // As detect --rgb: the colour judges today's surface and is the overlay's background.
    const cv::Mat colour = o.rgb.empty() ? cv::Mat() : attachColourFile(cloud, o.rgb, cfg.suitability.registration);
    // Today's answer is detect's, by the same call.
    SurfaceDetector detector(projector, cfg);
    const frontend::GravityDetection answer = frontend::detectWithGravity(
        detector, cloud, choice, frontend::defaultMinimumSize(cfg.method),
        (o.cloud.empty() ? o.depth : o.cloud) + withSettings(o.config_file));
    // detect's words on the gravity (only `auto` that found no floor: plan does not search the floor again).
    const frontend::GravityUsed used{choice, o.gravity.empty(), answer.gravity};
    for (const std::string &w : frontend::gravityUsedWarnings({"--gravity", "--gravity auto"}, used, cloud, false))
        std::fprintf(stderr, "projsurf: warning: %s\n", w.c_str());
    const Eigen::Vector3d gravity = answer.gravity.gravity;
    const Detection &today = answer.detection;
    const PlanResult r = planStand(cloud, projector, cfg, gravity, o.plan, today);
    const nlohmann::json j = frontend::planToJson(r);
    OutputGroup outputs;
    if (!o.json.empty()) outputs.addFile(o.json, j.dump(2) + "\n");
    if (!o.overlay.empty())
        outputs.addImage(o.overlay,
                         renderPlanOverlay(cloud, r, cfg, camera.get(), gravity, o.plan.robot_radius, colour));
    outputs.commit();
    if (o.json.empty())
        std::cout << j.dump(2) << "\n";
    else
        std::printf("%s\n", frontend::planSummary(r).c_str());
}

}  // namespace

void addPlanCommand(CLI::App &app) {
    auto o = std::make_shared<PlanCliOptions>();
    auto *sub = app.add_subcommand("plan", "Where the robot should stand for the largest picture (or for --width)");
    sub->add_option("--cloud", o->cloud, "Point cloud (PCD or PLY, camera optical frame, metres)");
    sub->add_option("--depth", o->depth, "16-bit depth PNG (0 = no reading); needs --camera");
    sub->add_option("--camera", o->camera, "Camera intrinsics YAML for --depth");
    sub->add_option(
        "--rgb", o->rgb,
        "Colour PNG registered to the cloud (checked, as detect --rgb): surface suitability and the overlay");
    sub->add_option("--calib", o->calib, "Projector calibration YAML")->required();
    sub->add_option("--aspect", o->aspect, "Picture aspect ratio W:H (default: the framebuffer's)");
    sub->add_option("--gravity", o->gravity,
                    "Gravity in the camera frame gx,gy,gz (default 0,1,0), or 'auto' (from the floor)");
    sub->add_option("--config", o->config_file,
                    "Detector settings YAML, as detect --config (--aspect overrides its aspect)");
    sub->add_option("--width", o->plan.width, "The shortest move that shows at least this width, m");
    sub->add_option("--max-move", o->plan.max_move, "Longest translation on the floor, m (default 2)");
    sub->add_option("--json", o->json, "Write the plan JSON here (else it goes to stdout)");
    sub->add_option("--overlay", o->overlay,
                    "Write a picture of the plan here (PNG): today's and the proposed rectangle on the frame, and a "
                    "top-down sketch of the robot now and after the move");
    sub->callback([o] { run(*o); });
}

}  // namespace projsurf::cli
