#include "projsurf/frontend/answer/plan_json.hpp"

#include <cstdio>

namespace projsurf::frontend {
namespace {

nlohmann::json rectangleJson(const Rectangle &r) {
    nlohmann::json corners = nlohmann::json::array();
    for (const auto &c : r.corners) corners.push_back({c.x(), c.y(), c.z()});
    return {{"corners", corners}, {"width_m", r.width}, {"height_m", r.height}, {"area_m2", r.area()}};
}

}  // namespace

nlohmann::json planToJson(const PlanResult &r) {
    nlohmann::json j;
    j["found"] = r.found;
    j["reason"] = r.found ? nlohmann::json(nullptr) : nlohmann::json(r.reason);
    if (r.found) {
        nlohmann::json rot = nlohmann::json::array();
        for (int i = 0; i < 3; ++i) rot.push_back({r.rotation(i, 0), r.rotation(i, 1), r.rotation(i, 2)});
        j["camera_pose"] = {{"rotation", rot},
                            {"translation", {r.translation.x(), r.translation.y(), r.translation.z()}}};
        j["predicted"] = rectangleJson(r.predicted);
        // Extension: the same move in the gravity-levelled robot frame (forward = the optical
        // axis on the floor, left, turn about up), and in words.
        j["move"] = {{"forward_m", r.move.forward_m},
                     {"left_m", r.move.left_m},
                     {"turn_left_deg", r.move.turn_left_deg},
                     {"words", moveInWords(r.move)}};
    } else {
        j["camera_pose"] = nullptr;
        j["predicted"] = nullptr;
        j["move"] = nullptr;
    }
    // Extensions: detect's answer where the robot stands, and what keeps the picture from being larger.
    j["today"] = r.today.found ? rectangleJson(r.today.rectangle) : nlohmann::json(nullptr);
    j["today_reason"] = r.today.found ? nlohmann::json(nullptr) : nlohmann::json(r.today.reason);
    j["limit"] = r.limit;
    // Extension: the proposed picture relies on wall assumed beyond the camera's view (not
    // seen), and on how much of it.
    j["assumed"] = r.assumed();
    j["assumed_share"] = r.found ? r.assumed_share : 0.0;
    j["search"] = {{"surfaces", r.surfaces},
                   {"poses_tried", r.poses_tried},
                   {"poses_occupied", r.poses_occupied},
                   {"pictures", r.pictures_evaluated}};
    return j;
}

std::string planSummary(const PlanResult &r) {
    char buf[600];
    if (!r.found) {
        std::snprintf(buf, sizeof buf, "plan: not found: %s", r.reason.c_str());
        return buf;
    }
    std::snprintf(buf, sizeof buf, "plan: %s: %.2f x %.2f m (%.2f m^2; %.2f m^2 without moving); limit: %s",
                  moveInWords(r.move).c_str(), r.predicted.width, r.predicted.height, r.predicted.area(),
                  r.todayArea(), r.limit.c_str());
    return buf;
}

}  // namespace projsurf::frontend
