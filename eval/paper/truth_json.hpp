#pragma once
// The simulator's ground truth as JSON (`projsurf simulate` writes truth.json): the true
// plane and the true largest free upright rectangle, with the same key names and corner
// order (TL, TR, BR, BL) as the contract's detection JSON, plus the scenario that made it.
#include <nlohmann/json.hpp>
#include <string>

#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

/// Keys: found, aspect, cell_m, scenario{name, description, distance_m, angle_deg, roll_deg, pitch_deg,
/// gravity, seed, noise}, plane{coefficients, orientation_deg, surface}, rectangle{corners,
/// width_m, height_m, area_m2} (null when not found), footprint (4 corners or null),
/// wall_plane{coefficients, orientation_deg}, surfaces[{surface, coefficients, found,
/// area_m2, free_area_m2}].
nlohmann::json truthToJson(const sim::GroundTruth &truth, const sim::Scenario &scenario, unsigned seed, bool noise);

/// Writes truthToJson atomically, pretty-printed.
void writeTruthJson(const std::string &path, const sim::GroundTruth &truth, const sim::Scenario &scenario,
                    unsigned seed, bool noise);

}  // namespace projsurf::eval
