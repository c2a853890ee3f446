#include "projsurf/planning/stand_planner.hpp"

#include "projsurf/types/clamp_to_int.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/detection/projector_footprint.hpp"
#include "projsurf/detection/rectangle_search.hpp"

namespace projsurf {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Floor cells (5 cm, in the plane perpendicular to gravity, around the camera) that the
/// cloud shows occupied: two points or more above the floor, below 2 m over it.
class Occupancy {
public:
    Occupancy(const Cloud &cloud, const Eigen::Vector3d &gravity, double reach, double obstacle_height)
        : g_(gravity.normalized()) {
        e1_ = Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(g_) * g_;
        if (e1_.norm() < 1e-6) e1_ = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(g_) * g_;
        e1_.normalize();
        e2_ = g_.cross(e1_);
        half_ = static_cast<int>(std::ceil(reach / kCell));
        side_ = 2 * half_ + 1;
        count_.assign(static_cast<std::size_t>(side_) * side_, 0);
        // The floor: the lowest points seen (99th percentile along gravity).
        std::vector<float> down;
        for (std::size_t i = 0; i < cloud.points.size(); i += 7)
            if (isFinite(cloud.points[i])) down.push_back(static_cast<float>(cloud.points[i].cast<double>().dot(g_)));
        if (down.empty()) return;
        const std::size_t k = static_cast<std::size_t>(0.99 * (down.size() - 1));
        std::nth_element(down.begin(), down.begin() + k, down.end());
        const double floor = down[k];
        for (const Point &pf : cloud.points) {
            if (!isFinite(pf)) continue;
            const Eigen::Vector3d p = pf.cast<double>();
            const double above = floor - p.dot(g_);
            if (above < obstacle_height || above > 2.0) continue;
            const int i = index(p);
            if (i >= 0) ++count_[i];
        }
    }
    /// Whether the robot's disc of `radius` at floor position of `p` meets an occupied cell.
    bool occupied(const Eigen::Vector3d &p, double radius) const {
        const int r = static_cast<int>(std::ceil(radius / kCell));
        const int cx = cellOf(p.dot(e1_)), cy = cellOf(p.dot(e2_));
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                if ((dx * dx + dy * dy) * kCell * kCell > radius * radius) continue;
                const int x = cx + dx + half_, y = cy + dy + half_;
                if (x < 0 || y < 0 || x >= side_ || y >= side_) continue;
                if (count_[static_cast<std::size_t>(y) * side_ + x] >= 2) return true;
            }
        return false;
    }
    const Eigen::Vector3d &e1() const { return e1_; }
    const Eigen::Vector3d &e2() const { return e2_; }

private:
    static constexpr double kCell = 0.05;
    // Clamped far outside any raster (its side is bounded), so a point at 1e20 m is just off it.
    static int cellOf(double v) { return clampToInt(std::floor(v / kCell + 0.5), -(1 << 28), 1 << 28); }
    int index(const Eigen::Vector3d &p) const {
        const int x = cellOf(p.dot(e1_)) + half_, y = cellOf(p.dot(e2_)) + half_;
        if (x < 0 || y < 0 || x >= side_ || y >= side_) return -1;
        return y * side_ + x;
    }
    Eigen::Vector3d g_, e1_, e2_;
    int half_ = 0, side_ = 1;
    std::vector<int> count_;
};

}  // namespace

PlanResult planStand(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                     const Eigen::Vector3d &gravity, const PlanOptions &o) {
    PlanResult out;
    const double aspect = config.aspect > 0.0 ? config.aspect : projector.aspect();
    // The free surface the camera saw: one detection through a projector that lights all of it.
    Projector wide = projector;
    wide.fov_h = 90.0 * kPi / 180.0;
    wide.fov_v = 70.0 * kPi / 180.0;
    wide.width = 1280;
    wide.height = static_cast<int>(std::lround(1280 * std::tan(wide.fov_v / 2) / std::tan(wide.fov_h / 2)));
    DetectorConfig cfg = config;
    cfg.aspect = aspect;
    cfg.free_space.cell = o.cell;
    const Detection seen = detectSurface(cloud, wide, cfg, gravity);
    if (!seen.found || seen.debug.free_space.empty()) {
        out.reason = "no free surface seen: " + (seen.reason.empty() ? std::string("none") : seen.reason);
        return out;
    }
    const cv::Mat &surface = seen.debug.free_space;
    RasterFrame raster;
    raster.top_left = seen.debug.grid_origin;
    raster.cell = seen.debug.grid_cell;
    raster.cols = surface.cols;
    raster.rows = surface.rows;
    const PlaneFrame &frame = seen.debug.frame;
    const Plane &plane = seen.plane;
    const auto rays = projector.cornerRays();
    cv::Mat cells;
    auto evaluate = [&](const Eigen::Matrix3d &r, const Eigen::Vector3d &t) -> std::optional<Rectangle> {
        const Eigen::Vector3d origin = r * projector.origin + t;
        if (plane.signedDistance(origin) < o.robot_radius) return std::nullopt;
        std::array<Eigen::Vector3d, 4> moved;
        for (int i = 0; i < 4; ++i) moved[i] = r * rays[i];
        const auto fp = footprintOnPlane(plane, frame, origin, moved);
        if (!fp) return std::nullopt;
        cells = surface & footprintCells(raster, fp->uv);
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (const auto &w : fp->uv) centre += 0.25 * w;
        auto rect = largestFreeRectangle(cells, raster, frame, aspect, centre);
        if (rect)
            for (const auto &c : rect->corners)
                if ((c - t).norm() > o.max_distance) return std::nullopt;
        return rect;
    };
    const Eigen::Vector3d g = gravity.normalized();
    if (const auto r = evaluate(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero())) out.today = *r;

    const Occupancy occupancy(cloud, g, o.max_move + o.robot_radius + 0.2, o.obstacle_height);
    const double step = std::max(o.step, o.max_move / 20.0);  // at most 41 x 41 translations
    const int steps = static_cast<int>(std::floor(o.max_move / step + 1e-9));
    const int yaws = static_cast<int>(std::floor(o.max_yaw_deg / o.yaw_step_deg + 1e-9));
    struct Best {
        bool any = false;
        double area = 0, move = 0, yaw = 0;
    } best;
    for (int j = -steps; j <= steps; ++j) {
        for (int i = -steps; i <= steps; ++i) {
            const Eigen::Vector3d t = (i * occupancy.e1() + j * occupancy.e2()) * step;
            const double move = t.norm();
            if (move > o.max_move + 1e-9) continue;
            // The robot must get there: its disc along the straight way, and at the end.
            bool blocked = false;
            const int samples = std::max(1, static_cast<int>(std::ceil(move / 0.05)));
            for (int s = 1; s <= samples && !blocked; ++s)
                blocked = occupancy.occupied(t * (double(s) / samples), o.robot_radius);
            if (blocked) {
                ++out.poses_occupied;
                continue;
            }
            for (int k = -yaws; k <= yaws; ++k) {
                const double yaw = k * o.yaw_step_deg * kPi / 180.0;
                const Eigen::Matrix3d r = Eigen::AngleAxisd(yaw, g).toRotationMatrix();
                ++out.poses_tried;
                const auto rect = evaluate(r, t);
                if (!rect) continue;
                const double area = rect->area();
                bool better;
                if (o.width > 0.0) {
                    if (rect->width + 1e-9 < o.width) continue;
                    better = !best.any || move < best.move - 1e-9 ||
                             (std::abs(move - best.move) <= 1e-9 && std::abs(yaw) < std::abs(best.yaw) - 1e-9);
                } else {
                    // Larger by more than 1 %, or as large with a shorter move / smaller turn.
                    better = !best.any || area > 1.01 * best.area ||
                             (area >= 0.99 * best.area &&
                              (move < best.move - 1e-9 ||
                               (std::abs(move - best.move) <= 1e-9 && std::abs(yaw) < std::abs(best.yaw) - 1e-9)));
                }
                if (!better) continue;
                best = {true, area, move, yaw};
                out.rotation = r;
                out.translation = t;
                out.predicted = *rect;
            }
        }
    }
    if (!best.any) {
        out.reason = o.width > 0.0 ? "no move within --max-move shows a picture that wide"
                                   : "no reachable pose shows a picture on the surface";
        return out;
    }
    out.found = true;
    return out;
}

}  // namespace projsurf
