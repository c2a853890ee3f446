#pragma once
// The search of the stance space: every turn about gravity (all the way round, in coarse
// steps) at every position of a grid on the free floor within the longest move, on every
// surface; the stances ranked by an upper bound of their picture and looked at best first,
// until no unseen one could be better; then the best few refined by a local search in finer
// steps. With a width wanted: the stances in order of their move (then their turn), the
// first that shows a picture that wide, refined towards a shorter move.
#include <optional>
#include <vector>

#include "projsurf/planning/floor_occupancy.hpp"
#include "projsurf/planning/plan_surfaces.hpp"
#include "projsurf/planning/stance_view.hpp"

namespace projsurf {

struct StanceSearchOptions {
    double max_move = 2.0;      ///< m
    double width = 0.0;         ///< m; > 0: the shortest move showing at least this width
    double step = 0.25;         ///< m, the coarse grid of positions (at least max_move / 8)
    double turn_step_deg = 15;  ///< deg, the coarse turns
    double fine_step = 0.025;   ///< m, the refinement stops below this step
    int refine = 6;             ///< best distinct stances refined
    /// What a m^2 of wall assumed beyond the camera's view counts for against a m^2 seen, when
    /// pictures are ranked (our choice, docs/planning.md: the wall may end just out of view, so
    /// a picture on seen wall wins over one of similar size that relies on unseen wall).
    double assumed_weight = 0.75;
    /// A picture more than this share of which is on assumed wall is no proposal: it would be a
    /// guess at what the camera has not seen, not a plan (our choice, docs/planning.md).
    double max_assumed_share = 0.5;
};

struct StanceCandidate {
    int surface = -1;
    Stance stance;
    Rectangle picture;  ///< today's camera frame
    double assumed = 0.0;  ///< the share of the picture on wall assumed, not seen (plan_surfaces.hpp)
    /// m^2, what the picture is ranked by: its area with the assumed part weighted down.
    double score(double assumed_weight) const { return picture.area() * (1.0 - (1.0 - assumed_weight) * assumed); }
};

struct StanceSearch {
    std::optional<StanceCandidate> best;
    double blocked_area = 0.0;   ///< m^2, the largest picture seen from stances the floor refuses
    double widest = 0.0;         ///< m, the widest picture seen (with a width wanted)
    int tried = 0;      ///< positions x turns looked at
    int positions = 0;  ///< positions of the grid (today's included)
    int occupied = 0;   ///< of them, those the floor refuses
    int evaluated = 0;           ///< pictures computed
};

StanceSearch searchStances(const std::vector<PlanSurface> &surfaces, const Projector &projector,
                           const FloorOccupancy &floor, const StanceLimits &limits, double robot_radius,
                           const StanceSearchOptions &options);

}  // namespace projsurf
