#include "projsurf/frontend/settings/gravity_sanity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "projsurf/detection/gravity.hpp"
#include "projsurf/detection/planes/point_sampling.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"

namespace projsurf::frontend {
namespace {

std::string vec(const Eigen::Vector3d &v) {
    char buf[100];
    std::snprintf(buf, sizeof buf, "%g,%g,%g", v.x() + 0.0, v.y() + 0.0, v.z() + 0.0);  // no "-0"
    return buf;
}

}  // namespace

std::vector<std::string> gravityWarnings(const std::string &what, const Eigen::Vector3d &gravity, const Cloud &cloud) {
    std::vector<std::string> out;
    const Eigen::Vector3d g = gravity.normalized();
    const double to_axis_deg = std::acos(std::min(1.0, std::abs(g.z()))) * 180.0 / M_PI;
    if (to_axis_deg < kOpticalAxisWarningDeg) {
        out.push_back(what + " " + vec(gravity) +
                      " points along the camera's optical axis (a camera looking straight " +
                      (g.z() > 0 ? "down" : "up") +
                      "); gravity is in the camera's optical frame (x right, y down, z forward), where a level "
                      "camera's is 0,1,0 (a z-up world's 0,0,-1 is not this frame), or auto");
        return out;
    }
    // The floor: the biggest near-horizontal plane on the far side of the camera along a prior.
    // Found along -g but not along g (or with far more points): the floor is above the camera.
    const auto along = estimateGravityFromFloor(cloud, g);
    const auto against = estimateGravityFromFloor(cloud, -g);
    if (against && (!along || against->floor_points > 2 * along->floor_points))
        out.push_back(what + " " + vec(gravity) +
                      " puts the floor above the camera: gravity points down, towards the floor (a raw "
                      "accelerometer reading points up; give " +
                      vec(-gravity) + ", or auto)");
    return out;
}

std::vector<double> largestPlanesToLevelDeg(const Cloud &cloud) {
    constexpr int kSample = 6000, kPlanes = 3, kIterations = 400;
    constexpr double kBand = 0.03, kMinShare = 0.10;  // m: a Kinect v1's noise at 4 m; share of the sample
    const std::vector<int> sample = samplePoints(cloud, kSample);
    std::vector<Eigen::Vector3d> pts;
    for (int i : sample) pts.push_back(cloud.points[i].cast<double>());
    const std::size_t total = pts.size();
    std::vector<double> out;
    std::mt19937 rng(7);
    while (static_cast<int>(out.size()) < kPlanes && pts.size() >= 50) {
        std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
        Eigen::Vector3d best_n = Eigen::Vector3d::Zero();
        double best_d = 0;
        std::size_t best = 0;
        for (int it = 0; it < kIterations; ++it) {
            const Eigen::Vector3d &a = pts[pick(rng)], &b = pts[pick(rng)], &c = pts[pick(rng)];
            const Eigen::Vector3d n = (b - a).cross(c - a);
            if (!(n.norm() > 1e-9)) continue;
            const Eigen::Vector3d u = n.normalized();
            const double d = -u.dot(a);
            std::size_t in = 0;
            for (const Eigen::Vector3d &p : pts) in += std::abs(u.dot(p) + d) <= kBand ? 1 : 0;
            if (in > best) best = in, best_n = u, best_d = d;
        }
        if (static_cast<double>(best) < kMinShare * static_cast<double>(total)) break;
        out.push_back(std::acos(std::min(1.0, std::abs(best_n.y()))) * 180.0 / M_PI);
        std::vector<Eigen::Vector3d> rest;
        for (const Eigen::Vector3d &p : pts)
            if (std::abs(best_n.dot(p) + best_d) > kBand) rest.push_back(p);
        pts.swap(rest);
    }
    return out;
}

std::optional<std::string> levelCameraWarning(const std::string &how_auto, const Cloud &cloud) {
    const auto deg = floorTiltFromLevelDeg(cloud);
    const bool tilted = deg && *deg > kTiltWarningDeg;
    char buf[160];
    if (tilted) std::snprintf(buf, sizeof buf, "%.0f", *deg);
    const std::string floor_says = tilted ? std::string("the floor says the camera is tilted ") + buf + " deg from level" : "";
    if (cloud.organized()) {
        if (!tilted) return std::nullopt;
        return floor_says + "; give " + how_auto + " (or the robot's gravity) so that the picture stands upright";
    }
    // An unorganized cloud: no image tells the floor's readings from the wall's, so the floor
    // and the walls are checked against each other. Its largest planes, against level:
    const std::vector<double> planes = largestPlanesToLevelDeg(cloud);
    auto off = [](double a) { return std::min(a, 90.0 - a); };  // from level (a floor) or vertical (a wall)
    if (tilted) {
        if (!planes.empty() && off(planes.front()) <= kTiltWarningDeg) {
            std::snprintf(buf, sizeof buf, "%.0f", planes.front());
            return floor_says + ", but the cloud's largest plane lies " + buf + " deg from horizontal, " +
                   (planes.front() > 45 ? "a wall" : "a floor") +
                   " of a level camera: the two disagree (in an unorganized cloud the floor search can take a plane "
                   "across the floor and the foot of a wall); give the robot's gravity, or check " + how_auto;
        }
        return floor_says + "; give " + how_auto + " (or the robot's gravity) so that the picture stands upright";
    }
    if (planes.empty()) return std::nullopt;
    double lo = 90, hi = 0;
    for (const double a : planes) {
        if (!(off(a) > kObliquePlanesWarningDeg)) return std::nullopt;
        lo = std::min(lo, a), hi = std::max(hi, a);
    }
    if (planes.size() == 1)
        std::snprintf(buf, sizeof buf, "its largest plane lies %.0f deg", hi);
    else
        std::snprintf(buf, sizeof buf, "its %zu largest planes lie %.0f-%.0f deg", planes.size(), lo, hi);
    return std::string("this unorganized cloud does not look like a level camera's view: ") + buf +
           " from horizontal, neither floor nor wall; is it in the camera's optical frame (x right, y down, z "
           "forward), and the camera level? give " +
           how_auto + " or the robot's gravity";
}

}  // namespace projsurf::frontend
