#include "projsurf/frontend/settings/gravity_choice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "projsurf/detection/gravity.hpp"
#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

GravityChoice gravityChoiceFrom(const std::string &what, const double *values, std::size_t count) {
    if (count != 3) throw InputError(what, "expected three numbers gx,gy,gz or 'auto'");
    const Eigen::Vector3d g(values[0], values[1], values[2]);
    if (!g.allFinite()) throw InputError(what, "the vector is not finite");
    if (g.norm() < 1e-9) throw InputError(what, "the vector is zero");
    GravityChoice c;
    c.gravity = g;
    return c;
}

GravityChoice parseGravityChoice(const std::string &what, const std::string &text) {
    GravityChoice c;
    if (text.empty()) return c;
    if (text == "auto") {
        c.from_floor = true;
        return c;
    }
    std::string spaced = text;
    std::replace(spaced.begin(), spaced.end(), ',', ' ');
    std::istringstream in(spaced);
    std::vector<double> v;
    std::string item;
    while (in >> item) {
        try {
            std::size_t used = 0;
            v.push_back(std::stod(item, &used));
            if (used != item.size()) throw std::invalid_argument(item);
        } catch (const std::exception &) {
            throw InputError(what, "expected three numbers gx,gy,gz or 'auto', got '" + text + "'");
        }
    }
    if (v.size() != 3) throw InputError(what, "expected three numbers gx,gy,gz or 'auto', got '" + text + "'");
    return gravityChoiceFrom(what, v.data(), v.size());
}

ResolvedGravity resolveGravity(const GravityChoice &choice, const Cloud &cloud) {
    ResolvedGravity r{choice.gravity, false};
    if (!choice.from_floor) return r;
    // No IMU: "down" from the floor when one is in view, else the fallback (a level camera).
    if (const auto g = estimateGravityFromFloor(cloud, choice.gravity)) {
        r.gravity = g->gravity;
        r.floor_found = true;
    }
    return r;
}

std::optional<double> floorTiltFromLevelDeg(const Cloud &cloud) {
    const Eigen::Vector3d level = SurfaceDetector::levelGravity();
    const auto floor = estimateGravityFromFloor(cloud, level);
    if (!floor) return std::nullopt;
    return std::acos(std::clamp(floor->gravity.dot(level), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace projsurf::frontend
