#include "projsurf/sim/scenes/palette.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

#include "projsurf/sim/scenes/wall_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace projsurf::sim {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kWallWidth = kScenarioWallWidth;
constexpr double kWallHeight = kScenarioWallHeight;

// Colours, BGR reflectance.
using palette::kCardboard, palette::kFloor, palette::kPoster, palette::kWallPaint, palette::kWood;
const cv::Vec3f kClothes{0.45f, 0.25f, 0.15f};
const cv::Vec3f kSkin{0.55f, 0.65f, 0.85f};

/// The visible vertical faces of a piece of furniture (front and both sides) are flat
/// vertical surfaces a picture could go on, like the wall: each becomes a surface of its own.
void markVerticalFaces(Scene &scene, const std::array<int, 6> &faces) {
    for (int slot : {0, 1, 5}) scene.quads[faces[slot]].surface = nextSurfaceId(scene);
}

void addFloor(Scene &scene, const WallFrame &w, double out0, double out1) {
    Quad q;
    q.corner = w.at(-5.0, 0.0, out0);
    q.edge_a = 10.0 * w.right;
    q.edge_b = (out1 - out0) * w.normal;
    q.albedo = kFloor;
    q.label = "floor";
    scene.quads.push_back(q);
}

void addMainWall(Scene &scene, const WallFrame &w, std::vector<WallHole> holes_s_h) {
    for (auto &h : holes_s_h) {  // from (s, h) to the wall's own coordinates
        h.x0 += 0.5 * kWallWidth;
        h.x1 += 0.5 * kWallWidth;
    }
    addWall(scene, w.at(-0.5 * kWallWidth, 0.0, 0.0), w.right, w.up, kWallWidth, kWallHeight, holes_s_h, kWallPaint,
            "wall", 0);
}

void requireRoom(const std::string &name, const WallFrame &w, double needed_out) {
    if (w.cameraOut() < needed_out)
        throw std::invalid_argument("scenario '" + name + "' needs the camera at least " +
                                    std::to_string(needed_out).substr(0, 4) +
                                    " m from the wall (perpendicular distance = distance * cos(angle))");
}

}  // namespace

const std::vector<std::string> &scenarioNames() {
    static const std::vector<std::string> names{"wall",   "small_obstacles", "big_obstacle", "closet", "door", "window",
                                                "poster", "person",          "rolled",       "corner", "desk"};
    return names;
}

Projector exampleProjector() {
    Projector p;  // 1280x800, 39.3 x 24.0 deg (paper 3.1.2)
    p.origin = Eigen::Vector3d(0.0, 0.12, 0.0);
    p.direction = Eigen::Vector3d(0.0, -0.05, 1.0).normalized();
    return p;
}

namespace {

/// The camera turns by `r` (its new axes in the old camera frame); a point's coordinates turn by r^T.
void turnCamera(Scenario &s, const Eigen::Matrix3d &r) {
    const Eigen::Matrix3d r_t = r.transpose();
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = r_t;
    s.scene = transformed(s.scene, t);
    s.gravity = (r_t * s.gravity).normalized();
    s.wall = makePlane(r_t * s.wall.normal, s.wall.d);
}

}  // namespace

void rollCamera(Scenario &s, double roll_deg) {
    turnCamera(s, Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    s.roll_deg += roll_deg;
}

void pitchCamera(Scenario &s, double pitch_deg) {
    // Looking down turns z towards +y (down): a rotation about x by -pitch.
    turnCamera(s, Eigen::AngleAxisd(-pitch_deg * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix());
    s.pitch_deg += pitch_deg;
}

namespace {

/// The paper's scenes (4.1-4.3) on the wall `w`; false for another name.
bool buildPaperScene(Scenario &sc, const std::string &name, const WallFrame &w) {
    Scene &scene = sc.scene;
    if (name == "wall" || name == "rolled") {
        sc.description = "plain wall and floor";
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        if (name == "rolled") {
            sc.description = "plain wall seen by a camera rolled 4 degrees";
            rollCamera(sc, 4.0);
        }
    } else if (name == "small_obstacles") {
        sc.description = "three small boxes on the wall (paper 4.3, SO)";
        requireRoom(name, w, 0.5);
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        wallBox(scene, w, -0.27, -0.13, 0.94, 1.06, 0.0, 0.10, kCardboard, "box");
        wallBox(scene, w, 0.06, 0.24, 0.77, 0.87, 0.0, 0.12, kCardboard, "box");
        wallBox(scene, w, 0.24, 0.36, 1.01, 1.15, 0.0, 0.08, kCardboard, "box");
    } else if (name == "big_obstacle") {
        sc.description = "a big cardboard box (0.6 x 1.05 x 0.45 m) against the wall (paper 4.3, BO)";
        requireRoom(name, w, 0.75);
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        // A box standing in front of the wall, open space above and beside it, is an object on
        // the scene, not a projection surface (detection/default/face_surround.hpp).
        wallBox(scene, w, -0.45, 0.15, 0.0, 1.05, 0.0, 0.45, kCardboard, "box");
    } else if (name == "closet") {
        sc.description = "a closet (1.0 wide, 0.6 deep, 2.0 m tall) against the wall (paper 4.2, cluttered)";
        requireRoom(name, w, 0.9);
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        markVerticalFaces(scene, wallBox(scene, w, -0.8, 0.2, 0.0, 2.0, 0.0, 0.6, kWood, "closet"));
    } else {
        return false;
    }
    return true;
}

/// The scenes beyond the paper's (openings, a poster, a person, a corner, a desk); false for
/// another name.
bool buildRoomScene(Scenario &sc, const std::string &name, const WallFrame &w) {
    Scene &scene = sc.scene;
    if (name == "door") {
        sc.description = "an open doorway (0.9 x 2.05 m) right of the axis, a room 3.5 m deep behind";
        addMainWall(scene, w, {{0.35, 0.0, 1.25, 2.05}});
        addFloor(scene, w, -3.5, 8.0);
        addWall(scene, w.at(-5.0, 0.0, -3.5), w.right, w.up, 10.0, kWallHeight, {}, kWallPaint, "wall", 1);
    } else if (name == "window") {
        sc.description = "a window hole (1.2 x 1.0 m, sill at 0.9 m) left of the axis, nothing in range behind";
        addMainWall(scene, w, {{-1.1, 0.9, 0.1, 1.9}});
        addFloor(scene, w, 0.0, 8.0);
    } else if (name == "poster") {
        sc.description = "an A1 poster 3 mm proud of the wall (flat: still a projection surface)";
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        Quad q;
        q.corner = w.at(-0.45, 0.75, 0.003);
        q.edge_a = 0.594 * w.right;
        q.edge_b = 0.841 * w.up;
        q.albedo = kPoster;
        q.label = "poster";
        scene.quads.push_back(q);
    } else if (name == "person") {
        sc.description = "a person (1.7 m) standing between the robot and the wall, right of the axis";
        requireRoom(name, w, 0.8);
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        const double out = std::min(0.8, 0.45 * w.cameraOut());
        wallBox(scene, w, 0.10, 0.55, 0.0, 1.45, out, out + 0.25, kClothes, "person");
        wallBox(scene, w, 0.22, 0.42, 1.45, 1.70, out + 0.02, out + 0.24, kSkin, "person");
    } else if (name == "corner") {
        sc.description = "a room corner: a side wall at right angles, right of the axis, coming towards the robot";
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        // At least 1 m right of the axis point and 0.8 m right of the camera.
        const double s_side = std::max(1.0, -w.origin.dot(w.right) + 0.8);
        addWall(scene, w.at(s_side, 0.0, 0.0), w.normal, w.up, 6.0, kWallHeight, {}, kWallPaint, "wall", 1);
    } else if (name == "desk") {
        sc.description = "a desk (1.2 wide, 0.75 tall, 0.6 m deep, modelled solid) against the wall below the axis";
        requireRoom(name, w, 0.9);
        addMainWall(scene, w, {});
        addFloor(scene, w, 0.0, 8.0);
        markVerticalFaces(scene, wallBox(scene, w, -0.7, 0.5, 0.0, 0.75, 0.0, 0.6, kWood, "desk"));
    } else {
        return false;
    }
    return true;
}

}  // namespace

Scenario makeScenario(const std::string &name, double distance, double angle_deg) {
    if (!(distance >= 0.5 && distance <= 10.0))
        throw std::invalid_argument("scenario distance must be between 0.5 and 10 m");
    if (!(std::abs(angle_deg) < 75.0)) throw std::invalid_argument("scenario angle must be within +-75 degrees");
    Scenario sc;
    sc.name = name;
    sc.distance = distance;
    sc.angle_deg = angle_deg;
    const WallFrame w(distance, angle_deg);
    sc.wall = makePlane(w.normal, -w.normal.dot(w.origin));
    if (!buildPaperScene(sc, name, w) && !buildRoomScene(sc, name, w))
        throw std::invalid_argument("unknown scenario '" + name + "'");
    return sc;
}

std::vector<PaperExperiment> paperExperiments() {
    const std::vector<double> d5{1.0, 1.5, 2.0, 2.5, 3.0};
    return {
        {"wall", d5, {27.5, 17.19}, "4.1-4.2, uncluttered (Fig 12a, Tables 1-2)"},
        {"closet", {1.5, 2.0, 2.5, 3.0}, {-26.01, -16.62}, "4.2, cluttered (Fig 12b, Table 2)"},
        {"wall", d5, {27.5, 17.19}, "4.3, no obstacle NO (Figs 14a, 15)"},
        {"small_obstacles", d5, {27.5, 17.19}, "4.3, small obstacles SO (Figs 14b, 15)"},
        {"big_obstacle", d5, {27.5, 17.19}, "4.3, big obstacle BO (Figs 14c, 15)"},
        {"wall", {1.0, 2.0, 3.0}, {27.5, 17.19, -12.06}, "4.4, image correction (Table 3)"},
    };
}

}  // namespace projsurf::sim
