#include "projsurf/sim/scenes/scenarios_realistic.hpp"

#include <algorithm>
#include <stdexcept>

#include "projsurf/sim/scenes/palette.hpp"
#include "projsurf/sim/scenes/wall_frame.hpp"

namespace projsurf::sim {
namespace {

using palette::kCardboard, palette::kFloor, palette::kPoster, palette::kWood;
const cv::Vec3f kPaint = palette::kWallPaint;
const cv::Vec3f kWhite{0.92f, 0.92f, 0.92f};
const cv::Vec3f kBlack{0.04f, 0.04f, 0.04f};
const cv::Vec3f kGlass{0.75f, 0.70f, 0.60f};
const cv::Vec3f kFabric{0.30f, 0.30f, 0.50f};

constexpr double kSkirtingHeight = 0.10, kProud = 0.015;  // m

void setMaterial(Scene &scene, const std::array<int, 6> &faces, Material m) {
    for (int f : faces) scene.quads[f].material = m;
}

/// A flat sheet `out` m proud of the wall (posters, whiteboards): one quad, not a surface.
void sheet(Scene &scene, const WallFrame &w, double s0, double s1, double h0, double h1, double out,
           const cv::Vec3f &albedo, const std::string &label) {
    Quad q;
    q.corner = w.at(s0, h0, out);
    q.edge_a = (s1 - s0) * w.right;
    q.edge_b = (h1 - h0) * w.up;
    q.albedo = albedo;
    q.label = label;
    scene.quads.push_back(q);
}

void skirting(Scene &scene, const WallFrame &w, double s0 = -4.0, double s1 = 4.0) {
    wallBox(scene, w, s0, s1, 0.0, kSkirtingHeight, 0.0, kProud, kWhite, "skirting");
}
void switchAt(Scene &scene, const WallFrame &w, double s, double h) {
    wallBox(scene, w, s - 0.04, s + 0.04, h - 0.04, h + 0.04, 0.0, kProud, kWhite, "switch");
}
void frameAt(Scene &scene, const WallFrame &w, double s0, double s1, double h0, double h1) {
    wallBox(scene, w, s0, s1, h0, h1, 0.0, 0.03, kWood, "frame");
}
void tvAt(Scene &scene, const WallFrame &w, double s0, double h0) {
    const auto faces = wallBox(scene, w, s0, s0 + 1.0, h0, h0 + 0.6, 0.0, 0.05, kBlack, "tv");
    setMaterial(scene, faces, Material::Black);
    scene.quads[faces[5]].material = Material::Glossy;  // the screen
}

/// A window hole with glass in it and a building `behind` m behind the wall (not a surface).
void windowWithGlass(Scene &scene, const WallFrame &w, double s0, double s1, double h0, double h1, double behind) {
    Quad g;
    g.corner = w.at(s0, h0, -0.05);
    g.edge_a = (s1 - s0) * w.right;
    g.edge_b = (h1 - h0) * w.up;
    g.albedo = kGlass;
    g.label = "glass";
    g.material = Material::Glass;
    scene.quads.push_back(g);
    Quad b;
    b.corner = w.at(s0 - 3.0, 0.0, -behind);
    b.edge_a = (s1 - s0 + 6.0) * w.right;
    b.edge_b = 6.0 * w.up;
    b.albedo = kCardboard;
    b.label = "outside";
    scene.quads.push_back(b);
}

void addWallAndFloor(Scene &scene, const WallFrame &w, const std::vector<WallHole> &holes_s_h) {
    std::vector<WallHole> holes = holes_s_h;
    for (auto &h : holes) {
        h.x0 += 0.5 * kScenarioWallWidth;
        h.x1 += 0.5 * kScenarioWallWidth;
    }
    const Eigen::Vector3d corner = w.at(-0.5 * kScenarioWallWidth, 0.0, 0.0);
    addWall(scene, corner, w.right, w.up, kScenarioWallWidth, kScenarioWallHeight, holes, kPaint, "wall", 0);
    bowSurface(scene, 0, corner, w.right, w.up, kWallBowHalfWave, kScenarioWallHeight, kWallBowAmplitude);
    Quad q;
    q.corner = w.at(-5.0, 0.0, 0.0);
    q.edge_a = 10.0 * w.right;
    q.edge_b = 8.0 * w.normal;
    q.albedo = kFloor;
    q.label = "floor";
    scene.quads.push_back(q);
}

}  // namespace

const std::vector<std::string> &realisticScenarioNames() {
    static const std::vector<std::string> names{
        "plain_bowed",     "skirting_switches", "frames",      "tv",     "whiteboard",  "posters",     "window_glass",
        "black_furniture", "clutter",           "corner_room", "office", "living_room", "desk_clutter"};
    return names;
}

bool isRealisticScenario(const std::string &name) {
    const auto &n = realisticScenarioNames();
    return std::find(n.begin(), n.end(), name) != n.end();
}

namespace {

/// Throws unless the camera stands at least `out` m from the wall: the scenario's furniture
/// stands in front of it.
void requireCameraOut(const std::string &name, const WallFrame &w, double out) {
    if (w.cameraOut() < out)
        throw std::invalid_argument("scenario '" + name + "' needs the camera at least " +
                                    std::to_string(out).substr(0, 4) + " m from the wall");
}

/// What hangs on the wall: skirting, switches, frames, a TV, sheets, glass.
void hangOnWall(Scenario &sc, const std::string &name, const WallFrame &w) {
    Scene &scene = sc.scene;
    if (name == "plain_bowed") {
        sc.description = "a plain wall bowed by 4 mm, and the floor";
    } else if (name == "skirting_switches") {
        sc.description = "skirting board, two light switches beside the axis point, two sockets (1.5 cm proud)";
        skirting(scene, w);
        switchAt(scene, w, -0.35, 1.05);
        switchAt(scene, w, 0.45, 1.05);
        switchAt(scene, w, -0.6, 0.30);
        switchAt(scene, w, 0.7, 0.30);
    } else if (name == "frames") {
        sc.description = "two picture frames (3 cm) near the axis, skirting, a switch";
        skirting(scene, w);
        frameAt(scene, w, -0.75, -0.25, 1.1, 1.5);
        frameAt(scene, w, 0.35, 0.75, 0.8, 1.4);
        switchAt(scene, w, 1.0, 1.05);
    } else if (name == "tv") {
        sc.description = "a wall-mounted TV (1.0 x 0.6 m, 5 cm, black glossy) left of the axis, a socket";
        skirting(scene, w);
        tvAt(scene, w, -1.3, 0.8);
        switchAt(scene, w, -0.8, 0.3);
    } else if (name == "whiteboard") {
        sc.description = "a whiteboard (1.5 x 1.0 m, 3 mm proud) on the axis and a poster beside it";
        sheet(scene, w, -0.75, 0.75, 0.75, 1.75, 0.003, kWhite, "whiteboard");
        sheet(scene, w, 0.95, 1.55, 0.9, 1.75, 0.001, kPoster, "poster");
    } else if (name == "posters") {
        sc.description = "two A1 posters (1 mm proud) near the axis";
        sheet(scene, w, -0.70, -0.106, 0.7, 1.541, 0.001, kPoster, "poster");
        sheet(scene, w, 0.05, 0.644, 0.8, 1.641, 0.001, kFabric, "poster");
    } else if (name == "window_glass") {
        sc.description = "a window (1.2 x 1.0 m, sill 0.9 m) with glass left of the axis, a facade 1.5 m behind";
        skirting(scene, w);
    }
}

/// What stands in front of the wall: furniture, clutter, a side wall.
void furnishRoom(Scenario &sc, const std::string &name, const WallFrame &w) {
    Scene &scene = sc.scene;
    if (name == "black_furniture") {
        sc.description = "a black cabinet (1.0 wide, 1.2 tall, 0.5 m deep) against the wall right of the axis";
        requireCameraOut(name, w, 0.8);
        setMaterial(scene, wallBox(scene, w, 0.3, 1.3, 0.0, 1.2, 0.0, 0.5, kBlack, "cabinet"), Material::Black);
    } else if (name == "clutter") {
        sc.description = "boxes and a chair on the floor 0.3-1.0 m in front of the wall";
        requireCameraOut(name, w, 1.3);
        skirting(scene, w);
        wallBox(scene, w, -0.9, -0.4, 0.0, 0.45, 0.3, 0.7, kCardboard, "box");
        wallBox(scene, w, 0.2, 0.8, 0.0, 0.35, 0.5, 0.9, kCardboard, "box");
        wallBox(scene, w, -0.2, 0.2, 0.0, 0.45, 0.6, 1.0, kWood, "chair");   // seat
        wallBox(scene, w, -0.2, 0.2, 0.45, 0.9, 0.6, 0.64, kWood, "chair");  // back
    } else if (name == "corner_room") {
        sc.description = "a room corner: a side wall at right angles 1 m right of the axis, skirting";
        skirting(scene, w);
        const double s_side = std::max(1.0, -w.origin.dot(w.right) + 0.8);
        const Eigen::Vector3d c = w.at(s_side, 0.0, 0.0);
        addWall(scene, c, w.normal, w.up, 6.0, kScenarioWallHeight, {}, kPaint, "wall", 1);
        bowSurface(scene, 1, c, w.normal, w.up, kWallBowHalfWave, kScenarioWallHeight, kWallBowAmplitude);
    } else if (name == "office") {
        sc.description = "whiteboard, two frames, switches, a socket, skirting";
        skirting(scene, w);
        sheet(scene, w, -0.5, 0.7, 0.85, 1.75, 0.003, kWhite, "whiteboard");
        frameAt(scene, w, -1.4, -0.9, 1.1, 1.5);
        frameAt(scene, w, 1.0, 1.4, 1.2, 1.7);
        switchAt(scene, w, -0.7, 1.05);
        switchAt(scene, w, 0.9, 0.30);
    } else if (name == "living_room") {
        sc.description = "a TV right of the axis, a black sofa below it, a window with glass on the left";
        requireCameraOut(name, w, 1.3);
        skirting(scene, w);
        tvAt(scene, w, 0.5, 1.0);
        setMaterial(scene, wallBox(scene, w, -0.2, 1.8, 0.0, 0.8, 0.0, 0.9, kBlack, "sofa"), Material::Black);
    } else if (name == "desk_clutter") {
        sc.description = "a desk (1.2 x 0.75 x 0.6 m) with a black monitor and boxes on it, a switch above";
        requireCameraOut(name, w, 1.0);
        skirting(scene, w);
        wallBox(scene, w, -0.7, 0.5, 0.0, 0.75, 0.0, 0.6, kWood, "desk");
        setMaterial(scene, wallBox(scene, w, -0.4, 0.1, 0.75, 1.1, 0.2, 0.25, kBlack, "monitor"), Material::Black);
        wallBox(scene, w, 0.2, 0.45, 0.75, 0.95, 0.1, 0.4, kCardboard, "box");
        switchAt(scene, w, 0.8, 1.05);
    }
}

}  // namespace

Scenario makeRealisticScenario(const std::string &name, double distance, double angle_deg) {
    if (!isRealisticScenario(name)) throw std::invalid_argument("unknown scenario '" + name + "'");
    Scenario sc = makeScenario("wall", distance, angle_deg);  // checks the pose, sets wall and gravity
    sc.name = name;
    sc.scene = Scene{};
    Scene &scene = sc.scene;
    const WallFrame w(distance, angle_deg);
    if (name == "window_glass" || name == "living_room") {
        addWallAndFloor(scene, w, {{-1.5, 0.9, -0.3, 1.9}});
        windowWithGlass(scene, w, -1.5, -0.3, 0.9, 1.9, 1.5);
    } else {
        addWallAndFloor(scene, w, {});
    }
    hangOnWall(sc, name, w);
    furnishRoom(sc, name, w);
    return sc;
}

}  // namespace projsurf::sim
