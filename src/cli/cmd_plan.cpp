// projsurf plan: where the robot should stand so the projector shows the largest picture (or
// the smallest move showing --width), from one cloud (contract "Where to stand").
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "projsurf/frontend/aspect.hpp"
#include "projsurf/frontend/gravity_choice.hpp"
#include "projsurf/io/cloud_io.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/yaml_files.hpp"
#include "projsurf/detection/detector.hpp"
#include "projsurf/planning/stand_planner.hpp"

namespace projsurf::cli {
namespace {

struct PlanCliOptions {
    std::string cloud, depth, camera, calib, aspect, gravity, json;
    PlanOptions plan;
};

nlohmann::json rectangleJson(const Rectangle &r) {
    nlohmann::json corners = nlohmann::json::array();
    for (const auto &c : r.corners) corners.push_back({c.x(), c.y(), c.z()});
    return {{"corners", corners}, {"width_m", r.width}, {"height_m", r.height}, {"area_m2", r.area()}};
}

void run(const PlanCliOptions &o) {
    if (o.cloud.empty() == o.depth.empty())
        throw InputError("arguments", "give exactly one of --cloud FILE or --depth FILE");
    if (!o.depth.empty() && o.camera.empty()) throw InputError("arguments", "--depth needs --camera camera.yaml");
    if (!(o.plan.max_move >= 0.0 && o.plan.max_move <= 10.0))
        throw InputError("--max-move", "must be between 0 and 10 m");
    if (!(o.plan.width >= 0.0 && o.plan.width <= 50.0)) throw InputError("--width", "must be between 0 and 50 m");
    if (!o.json.empty()) requireWritableFile(o.json);
    DetectorConfig cfg;
    if (!o.aspect.empty()) cfg.aspect = frontend::parseAspect("--aspect", o.aspect);
    const Projector projector = readCalibration(o.calib);
    const Cloud cloud = o.cloud.empty() ? readDepthCloud(o.depth, o.camera) : readCloud(o.cloud);
    const frontend::ResolvedGravity resolved =
        frontend::resolveGravity(frontend::parseGravityChoice("--gravity", o.gravity), cloud);
    if (o.gravity == "auto" && !resolved.floor_found)
        std::fprintf(stderr, "projsurf: warning: --gravity auto found no floor; assuming a level camera\n");
    const Eigen::Vector3d gravity = resolved.gravity;
    const PlanResult r = planStand(cloud, projector, cfg, gravity, o.plan);
    nlohmann::json j;
    j["found"] = r.found;
    j["reason"] = r.found ? nlohmann::json(nullptr) : nlohmann::json(r.reason);
    if (r.found) {
        nlohmann::json rot = nlohmann::json::array();
        for (int i = 0; i < 3; ++i) rot.push_back({r.rotation(i, 0), r.rotation(i, 1), r.rotation(i, 2)});
        j["camera_pose"] = {{"rotation", rot},
                            {"translation", {r.translation.x(), r.translation.y(), r.translation.z()}}};
        j["predicted"] = rectangleJson(r.predicted);
    } else {
        j["camera_pose"] = nullptr;
        j["predicted"] = nullptr;
    }
    j["today"] = r.today.area() > 0.0 ? rectangleJson(r.today) : nlohmann::json(nullptr);  // extension: without moving
    if (o.json.empty()) {
        std::cout << j.dump(2) << "\n";
        return;
    }
    OutputGroup outputs;
    outputs.addFile(o.json, j.dump(2) + "\n");
    outputs.commit();
    if (r.found)
        std::printf(
            "plan: move %.2f m and turn %.1f deg: %.2f x %.2f m (%.2f m^2; %.2f m^2 without moving)\n",
            r.translation.norm(),
            std::acos(std::max(-1.0, std::min(1.0, (r.rotation.trace() - 1.0) / 2.0))) * 180.0 / 3.14159265358979,
            r.predicted.width, r.predicted.height, r.predicted.area(), r.today.area());
    else
        std::printf("plan: not found: %s\n", r.reason.c_str());
}

}  // namespace

void addPlanCommand(CLI::App &app) {
    auto o = std::make_shared<PlanCliOptions>();
    auto *sub = app.add_subcommand("plan", "Where the robot should stand for the largest picture (or for --width)");
    sub->add_option("--cloud", o->cloud, "Point cloud (PCD or PLY, camera optical frame, metres)");
    sub->add_option("--depth", o->depth, "16-bit depth PNG (0 = no reading); needs --camera");
    sub->add_option("--camera", o->camera, "Camera intrinsics YAML for --depth");
    sub->add_option("--calib", o->calib, "Projector calibration YAML")->required();
    sub->add_option("--aspect", o->aspect, "Picture aspect ratio W:H (default: the framebuffer's)");
    sub->add_option("--gravity", o->gravity, "Gravity in the camera frame gx,gy,gz (default 0,1,0), or 'auto'");
    sub->add_option("--width", o->plan.width, "The smallest move that shows at least this width, m");
    sub->add_option("--max-move", o->plan.max_move, "Longest translation on the floor, m (default 2)");
    sub->add_option("--json", o->json, "Write the plan JSON here (else it goes to stdout)");
    sub->callback([o] { run(*o); });
}

}  // namespace projsurf::cli
