#pragma once
// A point cloud in the camera's optical frame (x right, y down, z forward; metres).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace projsurf {

using Point = Eigen::Vector3f;

/// Points in the camera frame. Organized clouds keep the sensor's pixel grid
/// (row-major, width x height) and mark missing readings with NaN.
struct Cloud {
    std::vector<Point> points;
    int width = 0;   ///< pixels per row when organized, else points.size()
    int height = 1;  ///< rows when organized, else 1
    /// Optional colour of each point (B, G, R, 8 bit), registered to it: empty, or one per
    /// point. Only colour checked as registered belongs here (detection/colour/colour_registration.hpp).
    std::vector<std::array<std::uint8_t, 3>> colours;

    bool organized() const { return height > 1 && static_cast<std::size_t>(width) * height == points.size(); }
    std::size_t size() const { return points.size(); }
    bool hasColour() const { return !colours.empty() && colours.size() == points.size(); }
};

inline bool isFinite(const Point &p) { return p.allFinite(); }

/// Number of finite points.
std::size_t countFinite(const Cloud &cloud);

}  // namespace projsurf
