#include "projsurf/planning/stand_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/planning/floor_occupancy.hpp"
#include "projsurf/planning/plan_surfaces.hpp"
#include "projsurf/planning/stance_search.hpp"
#include "projsurf/types/formatted.hpp"

namespace projsurf {
namespace {

/// What keeps the best picture from being larger.
std::string limitOf(const PlanOptions &o, const StanceSearch &s, const Rectangle &picture, const Stance &stance) {
    double far = 0.0;
    for (const auto &c : picture.corners) far = std::max(far, (c - stance.translation).norm());
    if (far >= o.max_distance - 2.0 * o.cell)
        return formatted("range: the picture's far corner is at the depth camera's %.1f m", o.max_distance);
    if (s.blocked_area > 1.05 * picture.area())
        return formatted("floor space: stances the floor refuses would show %.2f m^2", s.blocked_area);
    if (stance.move() >= o.max_move - 0.5 * std::max(o.step, o.max_move / 8.0))
        return formatted("--max-move: the move is %.2f m long", stance.move());
    return "the wall's extent: the free surface seen holds no larger picture";
}

/// What the picture assumes when it relies on wall not seen (empty when it does not).
std::string assumedWords(const PlanResult &r) {
    if (!r.assumed()) return "";
    return formatted("; assumed: %.0f %% of the picture is on wall not seen", 100.0 * r.assumed_share) +
           " (assumed to go on beyond the camera's view: look there first)";
}

/// Why nothing was found.
std::string reasonOf(const PlanOptions &o, const StanceSearch &s, int surfaces) {
    if (surfaces == 0) return "no free vertical surface seen";
    if (s.positions > 1 && s.occupied == s.positions - 1)
        return "floor space: every position within --max-move but today's is occupied";
    if (o.width > 0.0)
        return formatted("no stance within --max-move shows a picture %.2f m wide", o.width) +
               formatted(" (the widest is %.2f m)", s.widest);
    return "no reachable stance shows a picture on a surface seen";
}

/// Today's answer stands: no move (the width is there, or a move gains too little).
bool staysToday(const PlanOptions &o, const PlanResult &r, const StanceSearch &s) {
    if (!r.today.found) return false;
    if (o.width > 0.0) return r.today.rectangle.width + 1e-9 >= o.width;
    return !s.best || s.best->score(o.assumed_weight) <= o.min_gain * r.todayArea();
}

}  // namespace

PlanResult planStand(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                     const Eigen::Vector3d &gravity, const PlanOptions &o, const Detection &today) {
    PlanResult out;
    out.today = today;
    const FloorOccupancy floor(cloud, gravity, o.max_move + o.robot_radius + 0.2, o.obstacle_height);
    DefaultScratch scratch;
    const SeenSurfaces seen = seeVerticalSurfaces(cloud, config, gravity, o.cell, o.max_move + o.max_distance, scratch);
    PlanSurfaceOptions so;
    so.beyond_view = o.beyond_view;
    so.obstacle_height = o.obstacle_height;
    const std::vector<PlanSurface> surfaces = planSurfaces(cloud, seen, floor, so);
    out.surfaces = static_cast<int>(surfaces.size());
    StanceLimits limits;
    limits.robot_radius = o.robot_radius;
    limits.max_distance = o.max_distance;
    limits.aspect = config.aspect > 0.0 ? config.aspect : projector.aspect();
    StanceSearchOptions so2;
    so2.max_move = o.max_move;
    so2.width = o.width;
    so2.step = o.step;
    so2.turn_step_deg = o.turn_step_deg;
    so2.assumed_weight = o.assumed_weight;
    so2.max_assumed_share = o.max_assumed_share;
    const StanceSearch s = searchStances(surfaces, projector, floor, limits, o.robot_radius, so2);
    out.poses_tried = s.tried;
    out.poses_occupied = s.occupied;
    out.pictures_evaluated = s.evaluated;
    if (staysToday(o, out, s)) {
        out.found = true;
        out.predicted = today.rectangle;
        out.limit = s.best ? limitOf(o, s, s.best->picture, s.best->stance) : "no better stance seen";
        return out;
    }
    if (!s.best) {
        out.reason = reasonOf(o, s, out.surfaces);
        out.limit = out.reason;
        return out;
    }
    out.found = true;
    out.rotation = s.best->stance.rotation;
    out.translation = s.best->stance.translation;
    out.move = levelledMove(out.rotation, out.translation, gravity);
    out.predicted = s.best->picture;
    out.assumed_share = s.best->assumed;
    out.limit = limitOf(o, s, s.best->picture, s.best->stance) + assumedWords(out);
    return out;
}

PlanResult planStand(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                     const Eigen::Vector3d &gravity, const PlanOptions &options) {
    return planStand(cloud, projector, config, gravity, options, detectSurface(cloud, projector, config, gravity));
}

}  // namespace projsurf
