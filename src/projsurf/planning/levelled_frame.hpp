#pragma once
// The gravity-levelled robot frame: where a person or move_base says "forward", "left" and
// "turn left". Forward is the camera's optical axis laid on the floor (perpendicular to
// gravity), left is up x forward, up is -gravity; all in the camera's optical frame.
#include <Eigen/Core>
#include <string>

namespace projsurf {

struct LevelledFrame {
    Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d left = -Eigen::Vector3d::UnitX();
    Eigen::Vector3d up = -Eigen::Vector3d::UnitY();
};

/// The levelled frame of a camera whose down is `gravity` (camera frame). A camera looking
/// straight down or up has no forward of its own: its image "up" (-y) is taken instead.
LevelledFrame levelledFrame(const Eigen::Vector3d &gravity);

/// A rigid move on the floor in the levelled frame of where the robot stands now.
struct LevelledMove {
    double forward_m = 0.0;      ///< m, negative = back
    double left_m = 0.0;         ///< m, negative = right
    double turn_left_deg = 0.0;  ///< deg about up, negative = right; in (-180, 180]
};

/// The move of the camera pose P_today = rotation * P_moved + translation (camera frame), in
/// the levelled frame of `gravity`.
LevelledMove levelledMove(const Eigen::Matrix3d &rotation, const Eigen::Vector3d &translation,
                          const Eigen::Vector3d &gravity);

/// The camera rotation (camera frame) of a turn by `turn_left_rad` about up.
Eigen::Matrix3d turnAboutUp(const LevelledFrame &frame, double turn_left_rad);

/// "0.62 m back and 0.30 m left, turn 35 deg left", "stay where you are", ... (2 cm, 1 deg).
std::string moveInWords(const LevelledMove &move);

}  // namespace projsurf
