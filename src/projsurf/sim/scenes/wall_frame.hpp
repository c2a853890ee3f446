#pragma once
// Placing things relative to a scenario's main wall (see scenarios.hpp): s metres along the
// wall to the right of the point where the optical axis meets it, h metres above the floor,
// out metres from the wall towards the camera. Shared by the paper's and the realistic scenes.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>

#include "projsurf/sim/scenes/scene.hpp"

namespace projsurf::sim {

constexpr double kScenarioCameraHeight = 1.0;  ///< m above the floor (robot 1.15 m tall, paper section 5)
constexpr double kScenarioWallWidth = 8.0;     ///< m
constexpr double kScenarioWallHeight = 2.6;    ///< m

struct WallFrame {
    Eigen::Vector3d origin, right, up, normal;
    WallFrame(double distance, double angle_deg) {
        const double a = angle_deg * (3.14159265358979323846 / 180.0);   // as kDeg in scenarios.cpp
        origin = Eigen::Vector3d(0.0, kScenarioCameraHeight, distance);  // on the floor below the axis point
        right = Eigen::Vector3d(std::cos(a), 0.0, std::sin(a));
        up = Eigen::Vector3d(0.0, -1.0, 0.0);
        normal = Eigen::Vector3d(std::sin(a), 0.0, -std::cos(a));
    }
    Eigen::Vector3d at(double s, double h, double out) const { return origin + s * right + h * up + out * normal; }
    /// Perpendicular distance from the camera to the wall.
    double cameraOut() const { return -origin.dot(normal); }
};

/// A box against / in front of the wall: s in [s0, s1], h in [h0, h1], out in [o0, o1].
inline std::array<int, 6> wallBox(Scene &scene, const WallFrame &w, double s0, double s1, double h0, double h1,
                                  double o0, double o1, const cv::Vec3f &albedo, const std::string &label) {
    return addBox(scene, w.at(s0, h0, o0), (s1 - s0) * w.right, (h1 - h0) * w.up, (o1 - o0) * w.normal, albedo, label);
}

}  // namespace projsurf::sim
