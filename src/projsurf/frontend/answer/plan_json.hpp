#pragma once
// A plan as every front end reports it: the contract's JSON (found, reason, camera_pose,
// predicted) with the extensions (today = detect's answer, the move in the gravity-levelled
// robot frame, what limits the picture, whether it relies on wall not seen), and the one-line
// summary in words.
#include <nlohmann/json.hpp>
#include <string>

#include "projsurf/planning/stand_planner.hpp"

namespace projsurf::frontend {

nlohmann::json planToJson(const PlanResult &plan);

/// "plan: move 0.62 m back and 0.30 m left, then turn 35 deg left: 1.60 x 1.00 m (1.60 m^2;
/// 0.27 m^2 without moving); limit: ..."
std::string planSummary(const PlanResult &plan);

}  // namespace projsurf::frontend
