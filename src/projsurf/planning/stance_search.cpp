#include "projsurf/planning/stance_search.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A stance on a surface with its bounds, before its picture is computed.
struct Bounded {
    double area = 0.0, width = 0.0;
    int surface = 0;
    Stance stance;
    StanceFootprint footprint;
    bool blocked = false;
};

/// What the search shares: the surfaces, the projector, the floor and the limits.
struct Context {
    const std::vector<PlanSurface> &surfaces;
    const Projector &projector;
    const FloorOccupancy &floor;
    const StanceLimits &limits;
    double radius;
    const StanceSearchOptions &o;
    std::array<Eigen::Vector3d, 4> rays;
    cv::Mat mask;
    StanceSearch out;
};

bool reachable(Context &x, const Stance &s) {
    if (s.move() > x.o.max_move + 1e-9) return false;
    return !x.floor.occupied(s.translation, x.radius) && !x.floor.pathBlocked(s.translation, x.radius);
}

/// The picture from a stance; nullopt when none, or when it could not reach `min_area` (or the width wanted).
std::optional<StanceCandidate> evaluate(Context &x, int surface, const Stance &s, const StanceFootprint &fp,
                                        double min_area) {
    ++x.out.evaluated;
    const auto pic = pictureFromStance(x.surfaces[surface], x.projector, fp, s, x.limits, x.mask, min_area);
    if (!pic) return std::nullopt;
    const double assumed = assumedShare(x.surfaces[surface], *pic);
    if (assumed > x.o.max_assumed_share) return std::nullopt;
    if (x.o.width > 0.0) x.out.widest = std::max(x.out.widest, pic->width);
    return StanceCandidate{surface, s, *pic, assumed};
}

/// a is better than b: larger by more than 1 % (its area with the assumed part weighted down),
/// or as large (1 %) with a shorter move or a smaller turn; with a width wanted: wide enough,
/// and a shorter move, then a smaller turn.
bool better(const StanceSearchOptions &o, const StanceCandidate &a, const std::optional<StanceCandidate> &b) {
    if (o.width > 0.0 && a.picture.width + 1e-9 < o.width) return false;
    if (!b) return true;
    const double ma = a.stance.move(), mb = b->stance.move();
    const bool shorter = ma < mb - 1e-9 || (std::abs(ma - mb) <= 1e-9 && std::abs(a.stance.turn) < std::abs(b->stance.turn) - 1e-9);
    if (o.width > 0.0) return shorter;
    const double aa = a.score(o.assumed_weight), ab = b->score(o.assumed_weight);
    return aa > 1.01 * ab || (aa >= 0.99 * ab && shorter);
}

/// Every position of the coarse grid times every coarse turn times every surface, bounded.
std::vector<Bounded> boundStances(Context &x) {
    const double step = std::max(x.o.step, x.o.max_move / 8.0);
    const int n = static_cast<int>(std::floor(x.o.max_move / step + 1e-9));
    const int turns = std::max(1, static_cast<int>(std::lround(360.0 / x.o.turn_step_deg)));
    std::vector<Bounded> out;
    for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) {
            const double f = i * step, l = j * step;
            if (std::hypot(f, l) > x.o.max_move + 1e-9) continue;
            const Stance at = makeStance(x.floor.frame(), f, l, 0.0);
            const bool blocked = (i != 0 || j != 0) && !reachable(x, at);
            ++x.out.positions;
            x.out.occupied += blocked ? 1 : 0;
            for (int k = 0; k < turns; ++k) {
                const Stance s = makeStance(x.floor.frame(), f, l, (k - turns / 2) * 2.0 * kPi / turns);
                ++x.out.tried;
                for (int m = 0; m < static_cast<int>(x.surfaces.size()); ++m) {
                    const auto fp = stanceFootprint(x.surfaces[m], x.projector, x.rays, s, x.limits);
                    if (!fp || fp->bound_area <= 0.0) continue;
                    out.push_back({fp->bound_area, fp->bound_width, m, s, *fp, blocked});
                }
            }
        }
    return out;
}

/// Best first by their bound, until none left could beat the best; the seeds of the refinement.
std::vector<StanceCandidate> bestByArea(Context &x, std::vector<Bounded> &all) {
    std::sort(all.begin(), all.end(), [](const Bounded &a, const Bounded &b) { return a.area > b.area; });
    std::vector<StanceCandidate> seen;
    std::optional<StanceCandidate> best;
    const double w = x.o.assumed_weight;
    // A picture's area bounds its score: none whose bound is below the best's score can win.
    for (const Bounded &b : all) {
        if (b.blocked) continue;
        if (best && b.area < 0.99 * best->score(w)) break;
        const auto c = evaluate(x, b.surface, b.stance, b.footprint, best ? 0.99 * best->score(w) : 0.0);
        if (!c) continue;
        seen.push_back(*c);
        if (better(x.o, *c, best)) best = c;
    }
    std::sort(seen.begin(), seen.end(),
              [w](const StanceCandidate &a, const StanceCandidate &b) { return a.score(w) > b.score(w); });
    // Distinct seeds: another surface, or a stance a coarse step or turn away from those kept.
    std::vector<StanceCandidate> seeds;
    if (best) seeds.push_back(*best);
    for (const StanceCandidate &c : seen) {
        if (static_cast<int>(seeds.size()) >= x.o.refine) break;
        bool distinct = true;
        for (const StanceCandidate &s : seeds)
            distinct &= c.surface != s.surface || std::hypot(c.stance.forward - s.stance.forward, c.stance.left - s.stance.left) > 1.5 * x.o.step ||
                        std::abs(c.stance.turn - s.stance.turn) > 1.5 * x.o.turn_step_deg * kPi / 180.0;
        if (distinct) seeds.push_back(c);
    }
    return seeds;
}

/// The shortest move (then the smallest turn) that shows the width: the seed of the refinement.
std::vector<StanceCandidate> firstWideEnough(Context &x, std::vector<Bounded> &all) {
    std::sort(all.begin(), all.end(), [](const Bounded &a, const Bounded &b) {
        const double ma = a.stance.move(), mb = b.stance.move();
        return ma < mb - 1e-9 || (std::abs(ma - mb) <= 1e-9 && std::abs(a.stance.turn) < std::abs(b.stance.turn));
    });
    std::optional<StanceCandidate> best;
    for (const Bounded &b : all) {
        if (b.blocked || b.width + 1e-9 < x.o.width) continue;
        if (best && b.stance.move() > best->stance.move() + 1e-9) break;
        const auto c = evaluate(x, b.surface, b.stance, b.footprint, 0.0);
        if (c && better(x.o, *c, best)) best = c;
    }
    if (best) return {*best};
    // None wide enough: the widest there is, for the reason (the 20 widest bounds looked at).
    std::sort(all.begin(), all.end(), [](const Bounded &a, const Bounded &b) { return a.width > b.width; });
    int looked = 0;
    for (const Bounded &b : all)
        if (!b.blocked && ++looked <= 20) evaluate(x, b.surface, b.stance, b.footprint, 0.0);
    return {};
}

/// Local search about a seed: moves and turns by a step, halved down to the fine step.
StanceCandidate refine(Context &x, StanceCandidate c) {
    const double coarse = std::max(x.o.step, x.o.max_move / 8.0);
    double step = 0.5 * coarse, turn = 0.5 * x.o.turn_step_deg * kPi / 180.0;
    while (step >= x.o.fine_step - 1e-12) {
        for (int round = 0; round < 6; ++round) {
            std::optional<StanceCandidate> next;
            const double moves[6][3] = {{step, 0, 0}, {-step, 0, 0}, {0, step, 0}, {0, -step, 0}, {0, 0, turn}, {0, 0, -turn}};
            for (const auto &d : moves) {
                const Stance s = makeStance(x.floor.frame(), c.stance.forward + d[0], c.stance.left + d[1], c.stance.turn + d[2]);
                if (!reachable(x, s)) continue;
                const auto fp = stanceFootprint(x.surfaces[c.surface], x.projector, x.rays, s, x.limits);
                if (!fp) continue;
                const auto t =
                    evaluate(x, c.surface, s, *fp, x.o.width > 0.0 ? 0.0 : 0.99 * c.score(x.o.assumed_weight));
                if (t && better(x.o, *t, next ? next : std::optional<StanceCandidate>(c))) next = t;
            }
            if (!next) break;
            c = *next;
        }
        step *= 0.5;
        turn *= 0.5;
    }
    return c;
}

/// The largest picture from stances the floor refuses whose bound beats the best (at most 40 looked at).
double blockedArea(Context &x, const std::vector<Bounded> &all, double best) {
    double out = 0.0;
    int looked = 0;
    for (const Bounded &b : all) {
        if (!b.blocked || b.area <= 1.05 * best) continue;
        if (++looked > 40) break;
        if (const auto c = evaluate(x, b.surface, b.stance, b.footprint, 1.05 * best)) out = std::max(out, c->picture.area());
    }
    return out;
}

}  // namespace

StanceSearch searchStances(const std::vector<PlanSurface> &surfaces, const Projector &projector,
                           const FloorOccupancy &floor, const StanceLimits &limits, double robot_radius,
                           const StanceSearchOptions &o) {
    Context x{surfaces, projector, floor, limits, robot_radius, o, projector.footprintRays(), {}, {}};
    std::vector<Bounded> all = boundStances(x);
    const std::vector<StanceCandidate> seeds = o.width > 0.0 ? firstWideEnough(x, all) : bestByArea(x, all);
    for (const StanceCandidate &seed : seeds) {
        const StanceCandidate c = refine(x, seed);
        if (better(o, c, x.out.best)) x.out.best = c;
    }
    if (o.width <= 0.0) {
        std::sort(all.begin(), all.end(), [](const Bounded &a, const Bounded &b) { return a.area > b.area; });
        x.out.blocked_area = blockedArea(x, all, x.out.best ? x.out.best->picture.area() : 0.0);
    }
    return x.out;
}

}  // namespace projsurf
