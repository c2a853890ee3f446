#pragma once
// A simulated scene: planar patches (parallelograms) in the camera's optical frame
// (x right, y down, z forward; metres). Walls, floors, boxes and people are all patches.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace projsurf::sim {

/// How a surface answers an active depth sensor (sensor models react; the old independent-
/// noise SensorModel ignores it). Ground truth: glass is not a surface and blocks nothing.
enum class Material {
    Matte,   ///< paint, paper, wood, cardboard: a normal reading
    Black,   ///< black / very dark (absorbs near infrared): no or few readings
    Glossy,  ///< glossy / specular (lacquer, screens): the pattern is mirrored away, holes
    Glass,   ///< transparent: the sensor reads through it (or not at all)
};

/// A smooth out-of-plane deviation of a quad (a wall that is not flat): a point p of the quad
/// is displaced by amplitude * sin(pi x) * sin(pi y) along `towards` (unit, towards the
/// camera side), x = (p - origin).dot(axis_x), y = (p - origin).dot(axis_y): axis_x and
/// axis_y are scaled so that one half-wave (one bulge) spans 1.
struct Bow {
    double amplitude = 0.0;  ///< m; 0 = flat
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis_x = Eigen::Vector3d::Zero(), axis_y = Eigen::Vector3d::Zero();  ///< 1/m
    Eigen::Vector3d towards = Eigen::Vector3d::Zero();
    /// Displacement (m, along `towards`) at a point of the flat quad.
    double at(const Eigen::Vector3d &p) const;
};

/// The parallelogram corner + a * edge_a + b * edge_b, a, b in [0, 1].
struct Quad {
    Eigen::Vector3d corner = Eigen::Vector3d::Zero();
    Eigen::Vector3d edge_a = Eigen::Vector3d::UnitX();
    Eigen::Vector3d edge_b = Eigen::Vector3d::UnitY();
    cv::Vec3f albedo{0.8f, 0.8f, 0.8f};  ///< BGR reflectance in [0, 1]
    std::string label = "wall";          ///< "wall", "floor", "closet", "box", "poster", "person", ...
    /// Quads with the same id >= 0 lie on one plane and form one projection surface (a wall
    /// with a hole is several quads of one surface); -1 = not a place to project on.
    int surface = -1;
    Material material = Material::Matte;
    Bow bow;  ///< flat by default; the renderer and the sensor models see the bowed surface
    /// Colour only (the depth sensors ignore both): a reflectance image (CV_32FC3 BGR, 0-1)
    /// over the quad, column ~ a, row ~ b, that replaces `albedo` (a picture, a poster); and
    /// light the surface gives off itself, as a fraction of white (a window pane, a screen).
    cv::Mat texture;
    float emission = 0.0f;

    Eigen::Vector3d normal() const { return edge_a.cross(edge_b).normalized(); }
    Eigen::Vector3d center() const { return corner + 0.5 * (edge_a + edge_b); }
    std::array<Eigen::Vector3d, 4> corners() const {
        return {corner, corner + edge_a, corner + edge_a + edge_b, corner + edge_b};
    }
};

struct Scene {
    std::vector<Quad> quads;
};

/// Nearest intersection of a ray with the scene.
struct Hit {
    double t = 0.0;  ///< ray parameter: point = origin + t * direction
    int quad = -1;   ///< index into Scene::quads
};

/// Parameter t of the ray origin + t * direction on the quad (t > t_min), nullopt on a miss.
std::optional<double> intersectQuad(const Quad &quad, const Eigen::Vector3d &origin, const Eigen::Vector3d &direction,
                                    double t_min = 1e-9);
/// Nearest hit with t in (t_min, t_max); nullopt when the ray meets nothing.
std::optional<Hit> castRay(const Scene &scene, const Eigen::Vector3d &origin, const Eigen::Vector3d &direction,
                           double t_min = 1e-9, double t_max = 1e30);

/// Adds a box with corner `corner` and edges ex, ey, ez (any right-handed or left-handed
/// set of perpendicular vectors). Returns the indices of its six faces in the order
/// -ex, +ex, -ey, +ey, -ez, +ez (the face at corner, the face at corner + e, per axis).
std::array<int, 6> addBox(Scene &scene, const Eigen::Vector3d &corner, const Eigen::Vector3d &ex,
                          const Eigen::Vector3d &ey, const Eigen::Vector3d &ez, const cv::Vec3f &albedo,
                          const std::string &label);

/// Rectangle [x0, x1] x [y0, y1] in a wall's own 2-D coordinates.
struct WallHole {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// Adds the rectangle origin + x * right + y * up, x in [0, width], y in [0, height], minus
/// the holes (doors, windows), as few quads. All quads get `surface`. Returns their indices.
std::vector<int> addWall(Scene &scene, const Eigen::Vector3d &origin, const Eigen::Vector3d &right,
                         const Eigen::Vector3d &up, double width, double height, const std::vector<WallHole> &holes,
                         const cv::Vec3f &albedo, const std::string &label, int surface);

/// Sets a bow on every quad of `surface`: one bulge every `half_wave` m along `right` and one
/// over `height` along `up`, starting at `origin` (the wall's lower-left corner).
void bowSurface(Scene &scene, int surface, const Eigen::Vector3d &origin, const Eigen::Vector3d &right,
                const Eigen::Vector3d &up, double half_wave, double height, double amplitude);

/// The scene moved by a rigid transform (e.g. into a rolled camera's frame).
Scene transformed(const Scene &scene, const Eigen::Isometry3d &transform);

/// A surface id not used yet in the scene.
int nextSurfaceId(const Scene &scene);

}  // namespace projsurf::sim
