#include "projsurf/planning/levelled_frame.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

namespace projsurf {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

LevelledFrame levelledFrame(const Eigen::Vector3d &gravity) {
    LevelledFrame f;
    const Eigen::Vector3d g = gravity.normalized();
    f.up = -g;
    Eigen::Vector3d forward = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(g) * g;
    if (forward.norm() < 1e-6) forward = -Eigen::Vector3d::UnitY() - (-Eigen::Vector3d::UnitY()).dot(g) * g;
    f.forward = forward.normalized();
    f.left = f.up.cross(f.forward);
    return f;
}

LevelledMove levelledMove(const Eigen::Matrix3d &rotation, const Eigen::Vector3d &translation,
                          const Eigen::Vector3d &gravity) {
    const LevelledFrame f = levelledFrame(gravity);
    LevelledMove m;
    m.forward_m = translation.dot(f.forward);
    m.left_m = translation.dot(f.left);
    // Where the robot's forward points after the move, seen from above.
    const Eigen::Vector3d turned = rotation * f.forward;
    m.turn_left_deg = std::atan2(turned.dot(f.left), turned.dot(f.forward)) * 180.0 / kPi;
    return m;
}

Eigen::Matrix3d turnAboutUp(const LevelledFrame &frame, double turn_left_rad) {
    return Eigen::AngleAxisd(turn_left_rad, frame.up).toRotationMatrix();
}

std::string moveInWords(const LevelledMove &m) {
    std::string steps;
    char buf[64];
    if (std::abs(m.forward_m) >= 0.02) {
        std::snprintf(buf, sizeof buf, "%.2f m %s", std::abs(m.forward_m), m.forward_m > 0 ? "forward" : "back");
        steps = buf;
    }
    if (std::abs(m.left_m) >= 0.02) {
        std::snprintf(buf, sizeof buf, "%.2f m %s", std::abs(m.left_m), m.left_m > 0 ? "left" : "right");
        steps += (steps.empty() ? "" : " and ") + std::string(buf);
    }
    std::string turn;
    if (std::abs(m.turn_left_deg) >= 0.5) {
        std::snprintf(buf, sizeof buf, "turn %.0f deg %s", std::abs(m.turn_left_deg),
                      m.turn_left_deg > 0 ? "left" : "right");
        turn = buf;
    }
    if (steps.empty() && turn.empty()) return "stay where you are";
    if (steps.empty()) return turn;
    return turn.empty() ? "move " + steps : "move " + steps + ", then " + turn;
}

}  // namespace projsurf
