#pragma once
// The paper's test scenes (section 4, Figs 11, 12, 14) and a few more, built around a robot
// whose camera is 1.0 m above the floor (the paper's Mbot is 1.15 m tall, section 5).
//
// Geometry of every scenario, before any camera roll:
//  - The camera is level at the origin (gravity [0, 1, 0]); the floor is the plane y = 1.0.
//  - The main wall is 8 m wide and 2.6 m tall. `distance` is measured from the camera along
//    its optical axis to the wall; `angle_deg` is the angle between the wall normal and the
//    camera's z axis (the paper's orientation, 3.2.1), a turn about the vertical: positive
//    angles put the wall's right-hand side (as the camera sees it) farther away.
//  - Wall-relative placement: s = metres along the wall to the right of the point where the
//    optical axis meets it, h = metres above the floor, out = metres from the wall towards
//    the camera.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::sim {

struct Scenario {
    std::string name;
    std::string description;
    double distance = 2.0;                   ///< m, camera to the main wall along the optical axis
    double angle_deg = 0.0;                  ///< wall normal vs camera z, about the vertical
    double roll_deg = 0.0;                   ///< camera (and projector) roll about the optical axis
    double pitch_deg = 0.0;                  ///< camera (and projector) pitch, positive looking down
    Scene scene;                             ///< camera frame
    Eigen::Vector3d gravity{0.0, 1.0, 0.0};  ///< camera frame, unit
    Plane wall;                              ///< the main wall, camera frame (normal towards the camera, d > 0)
};

/// Names accepted by makeScenario, in a stable order.
const std::vector<std::string> &scenarioNames();

/// Builds a scenario; throws std::invalid_argument for an unknown name or a distance or angle
/// that does not leave the camera in front of the wall (distance 0.5-10 m, |angle| < 75 deg).
///  wall             plain wall and floor (paper 4.1, uncluttered; 4.3 "NO")
///  small_obstacles  three small boxes on the wall (paper 4.3 "SO")
///  big_obstacle     a big cardboard box (0.6 wide, 1.05 tall, 0.45 m deep) standing against
///                   the wall, a little left of the axis (paper 4.3 "BO")
///  closet           a 1.0 m wide, 0.6 m deep, 2.0 m tall closet against the wall, slightly
///                   left of the axis (paper 4.2, cluttered)
///  door             an open doorway right of the axis, a room behind it
///  window           a window hole left of the axis, nothing behind it in range
///  poster           an A1 poster 3 mm proud of the wall (flat: not an obstacle)
///  person           a person standing between the robot and the wall
///  rolled           the plain wall seen by a camera rolled by 4 degrees
///  corner           a room corner: a second wall at right angles, at least 1 m right of the axis
///  desk             a desk (1.2 x 0.75 x 0.6 m, solid) against the wall, hiding its lower part
/// The wall is projection surface 0 (the corner's side wall and the room behind the door are
/// surface 1); the vertical faces of the closet and the desk (front and sides) are projection
/// surfaces of their own; the big box (an object standing free before the wall), small boxes,
/// the person, the poster and the floor are not (Quad::surface).
Scenario makeScenario(const std::string &name, double distance, double angle_deg);

/// Rolls the camera (and the projector mounted on it) by `roll_deg` about its optical axis:
/// the scene and gravity are rotated into the rolled camera's frame.
void rollCamera(Scenario &scenario, double roll_deg);
/// Pitches the camera (and the projector) by `pitch_deg` about its x axis; positive looks
/// down (a robot head tilted towards the floor). The camera stays where it is.
void pitchCamera(Scenario &scenario, double pitch_deg);

/// The projector of the contract's example calibration (1280x800, 39.3 x 24.0 deg, origin
/// [0, 0.12, 0], direction [0, -0.05, 1]): just below the camera, tilted slightly up.
Projector exampleProjector();

/// One of the paper's experiments: a scenario over distances x angles.
struct PaperExperiment {
    std::string scenario;
    std::vector<double> distances;  ///< m
    std::vector<double> angles_deg;
    std::string source;  ///< where in the paper
};
/// Sections 4.1-4.4 (Tables 1-3, Figs 11, 12, 14, 15).
std::vector<PaperExperiment> paperExperiments();

}  // namespace projsurf::sim
