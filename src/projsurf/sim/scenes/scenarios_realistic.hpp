#pragma once
// Realistic world scenes for the realistic sensor models: the main wall of scenarios.hpp
// (same geometry conventions, camera 1.0 m above the floor) bowed by a few mm, with the things
// real walls carry. Sizes (field notes section 8): skirting boards, switches and sockets 1.5
// cm proud (1-2 cm); picture frames 3 cm and a TV 5 cm deep (2-5 cm, real obstacles);
// whiteboards 3 mm and posters 1 mm proud (flush: free); window glass (Material::Glass, not a
// surface); black furniture (Material::Black, no readings). See ground_truth.hpp for what is free.
//  plain_bowed       the bowed wall and the floor, nothing else
//  skirting_switches skirting board, two light switches beside the axis point, two sockets
//  frames            two picture frames near the axis, skirting, a switch
//  tv                a wall-mounted TV (1.0 x 0.6 m, 5 cm, black glossy screen) left of the axis, a socket
//  whiteboard        a whiteboard (1.5 x 1.0 m, 3 mm) on the axis and a poster beside it
//  posters           two A1 posters (1 mm) near the axis
//  window_glass      a window (1.2 x 1.0 m, sill 0.9 m) left of the axis with glass, a facade 1.5 m behind (in range)
//  black_furniture   a black cabinet (1.0 x 1.2 x 0.5 m) against the wall right of the axis
//  clutter           boxes and a chair on the floor 0.3-1.0 m in front of the wall
//  corner_room       a room corner: a side wall at right angles 1 m right of the axis, skirting
//  office            whiteboard, frames, switches, socket, skirting
//  living_room       TV, a black sofa, a window with glass
//  desk_clutter      a desk with a black monitor and boxes on it, a switch above
// Quad::surface: the main wall is 0, the corner's side wall 1; no other object is a projection surface.
#include <string>
#include <vector>

#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::sim {

/// The realistic scene names, in a stable order.
const std::vector<std::string> &realisticScenarioNames();
bool isRealisticScenario(const std::string &name);

/// Builds a realistic scene; throws std::invalid_argument like makeScenario.
Scenario makeRealisticScenario(const std::string &name, double distance, double angle_deg);

/// m, peak bow of the realistic main wall ("walls bow by several mm"), and the length of one bulge.
constexpr double kWallBowAmplitude = 0.004;
constexpr double kWallBowHalfWave = 2.5;

}  // namespace projsurf::sim
