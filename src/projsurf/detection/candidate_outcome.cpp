#include "projsurf/detection/candidate_outcome.hpp"

#include <algorithm>
#include <cmath>

#include "projsurf/types/formatted.hpp"

namespace projsurf {
namespace {

/// Each cell state's JSON word and what it says of the wall's cells, after "N % of the beam's
/// cells on it are " (CellState order).
struct StateWords {
    const char *name, *words;
};
constexpr StateWords kStates[kCellStates] = {
    {"no_free_area", "not free"},
    {"no_reading", "without a wall reading"},
    {"seen_through", "seen through (a hole, a door, glass)"},
    {"shadowed", "shadowed by something in front of it"},
    {"no_free_area", "not free"},
    {"glare", "unfit by their colour: glare (specular or emissive)"},
    {"too_dark", "too dark (low albedo)"},
    {"textured", "unfit by their colour: textured (a picture, a pattern)"},
    {"saturated", "unfit by their colour: too saturated"},
    {"proud", "standing proud of the wall (a frame, a switch, a screen)"},
};

const char *blockerWords(int state) { return kStates[state >= 0 && state < kCellStates ? state : 0].words; }

const char *blockerName(int state) { return kStates[state >= 0 && state < kCellStates ? state : 0].name; }

/// "62 % of the beam's cells on it are shadowed by something in front of it" (below 10 %, one
/// decimal: "0.6 %", never "0 %").
std::string blockedShare(int state, double share) {
    return formatted(share < 0.1 ? "%.1f %% of the beam's cells on it are " : "%.0f %% of the beam's cells on it are ",
                     100.0 * share) +
           blockerWords(state);
}

/// Share of a plane's points left out of its seen extent at each end of each axis.
constexpr double kExtentTail = 0.02;

std::string size(const Rectangle &r) { return formatted("%.3f", r.width) + " x " + formatted("%.3f m", r.height); }

/// "0.412 x 0.232 m (0.0956 m^2)" for both, the areas with digits enough to differ.
std::pair<std::string, std::string> sizes(const Rectangle &a, double area_a, const Rectangle &b) {
    const auto [x, y] = comparedPair(area_a, b.area(), 4);
    return {(a.area() > 0.0 ? size(a) + " (" : "(") + x + " m^2)", size(b) + " (" + y + " m^2)"};
}

/// The colour state covering most of the beam's cells on the plane, and its share.
std::pair<int, double> mainColour(const CandidateOutcome &o) {
    int best = -1;
    double share = 0.0;
    for (int s = static_cast<int>(CellState::Glare); s <= static_cast<int>(CellState::Saturated); ++s)
        if (o.beam_cells[s] > share) {
            best = s;
            share = o.beam_cells[s];
        }
    return {best, share};
}

/// Relative difference below which two rectangles are as large (rectangles grow by whole raster
/// cells, so two walls often hold the very same size): the later one lost a tie, it is not smaller.
constexpr double kSameArea = 1e-9;

/// Colour takes only cells that depth left free, so even a few of them can cost the picture
/// area (the dark top of a sofa's back above which the wall is free): said from 0.5 %.
constexpr double kColourWorthSaying = 0.005;

/// "; 6 % of the beam's cells on it are too dark (low albedo)" for the colour state covering
/// most of them, when colour took any; empty otherwise, or when `named` already said it.
std::string colourClause(const CandidateOutcome &o, int named) {
    const auto [colour, share] = mainColour(o);
    if (colour < 0 || colour == named || share < kColourWorthSaying) return "";
    return "; " + blockedShare(colour, share);
}

}  // namespace

void setSeenExtent(const std::vector<Point> &points, const std::vector<int> &indices, const PlaneFrame &frame,
                   CandidateOutcome &o) {
    if (indices.empty()) return;
    std::vector<double> u, v;
    for (int i : indices) {
        const Eigen::Vector2d uv = frame.toPlane(points[i].cast<double>());
        u.push_back(uv.x());
        v.push_back(uv.y());
    }
    // A few stray points in the plane's band far off (a chair's edge, the floor's) would
    // stretch a bounding box over the whole view: the 2nd to 98th percentile on each axis.
    auto quantile = [](std::vector<double> &x, double q) {
        const auto at = x.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(x.size() - 1));
        std::nth_element(x.begin(), at, x.end());
        return *at;
    };
    const Eigen::Vector2d lo(quantile(u, kExtentTail), quantile(v, kExtentTail));
    const Eigen::Vector2d hi(quantile(u, 1.0 - kExtentTail), quantile(v, 1.0 - kExtentTail));
    o.seen = {frame.toCamera({lo.x(), hi.y()}), frame.toCamera(hi), frame.toCamera({hi.x(), lo.y()}),
              frame.toCamera(lo)};
    o.seen_width = hi.x() - lo.x();
    o.seen_height = hi.y() - lo.y();
}

void setBeamCells(const cv::Mat &state, const cv::Mat &beam, CandidateOutcome &o) {
    if (state.empty() || beam.empty() || state.size() != beam.size()) return;
    std::array<double, kCellStates> count{};
    double total = 0.0;
    for (int r = 0; r < state.rows; ++r) {
        const uchar *s = state.ptr<uchar>(r), *b = beam.ptr<uchar>(r);
        for (int c = 0; c < state.cols; ++c)
            if (b[c] && s[c] < kCellStates) {
                count[s[c]] += 1.0;
                total += 1.0;
            }
    }
    if (total > 0.0)
        for (int s = 0; s < kCellStates; ++s) o.beam_cells[s] = count[s] / total;
}

int mainBlocker(const CandidateOutcome &o) {
    int best = -1;
    double share = 0.0;
    for (int s = static_cast<int>(CellState::NoReading); s < kCellStates; ++s)
        if (s != static_cast<int>(CellState::Edge) && o.beam_cells[s] > share) {
            best = s;
            share = o.beam_cells[s];
        }
    return best;
}

Rectangle winningRectangle(const std::vector<CandidateOutcome> &candidates, const Rectangle &answer) {
    for (const CandidateOutcome &o : candidates)
        if (o.verdict == CandidateVerdict::Chosen) return o.rectangle;
    for (const CandidateOutcome &o : candidates)
        if (o.verdict == CandidateVerdict::TooSmall && o.rectangle.area() > 0.0 &&
            o.rectangle.corners == answer.corners)
            return o.rectangle;
    return Rectangle{};
}

const char *verdictName(CandidateVerdict v) {
    switch (v) {
    case CandidateVerdict::NotExamined: return "smaller_extent";
    case CandidateVerdict::Chosen: return "chosen";
    case CandidateVerdict::TooSmall: return "too_small";
    case CandidateVerdict::NotReached: return "not_reached";
    case CandidateVerdict::BeyondOpening: return "beyond_opening";
    case CandidateVerdict::Object: return "object";
    case CandidateVerdict::NoFreeArea: return "no_free_area";
    case CandidateVerdict::SmallerRectangle: return "smaller_rectangle";
    case CandidateVerdict::CheckRejected: return "check_rejected";
    }
    return "unknown";
}

std::string outcomeName(const CandidateOutcome &o) {
    return o.verdict == CandidateVerdict::NoFreeArea ? blockerName(mainBlocker(o)) : verdictName(o.verdict);
}

std::string outcomeWords(const CandidateOutcome &o, const Rectangle &chosen) {
    switch (o.verdict) {
    case CandidateVerdict::Chosen: {
        std::string words = "chosen: the largest free rectangle, " + size(o.rectangle);
        int blocker = mainBlocker(o);
        if (blocker >= 0 && o.beam_cells[blocker] >= 0.1)
            words += "; " + blockedShare(blocker, o.beam_cells[blocker]);
        else
            blocker = -1;
        return words + colourClause(o, blocker);
    }
    case CandidateVerdict::TooSmall:
        return (o.detail.empty() ? "too small for a picture" : o.detail) + colourClause(o, -1);
    case CandidateVerdict::NotReached: return "the projector's beam does not reach where it was seen";
    case CandidateVerdict::BeyondOpening:
        return "seen through an opening of a nearer wall (a window, a door): the light would fall on the glass or "
               "through it";
    case CandidateVerdict::Object:
        return "a face that stands free in the room (furniture, a box, a person), not a wall";
    case CandidateVerdict::CheckRejected:
        if (o.check.points == 0) return "the surface check saw no point of it in its rectangle (nothing confirms it)";
        return "the surface check rejected its rectangle: " + std::to_string(o.check.outliers) + " of " +
               std::to_string(o.check.points) + " points off the wall";
    case CandidateVerdict::NoFreeArea: {
        const int blocker = mainBlocker(o);
        if (blocker < 0) return "no room for the picture: no free area of its aspect in the beam";
        return "no room for the picture: " + blockedShare(blocker, o.beam_cells[blocker]) + colourClause(o, blocker);
    }
    case CandidateVerdict::NotExamined: {
        if (!(chosen.area() > 0.0)) return "not looked at closely";
        const auto [x, y] = comparedPair(o.bound, chosen.area(), 4);
        return "not looked at closely: the beam's part of it could hold at most " + x + " m^2, no more than the " +
               "chosen " + y + " m^2";
    }
    case CandidateVerdict::SmallerRectangle: {
        if (chosen.area() > 0.0 && o.rectangle.area() >= chosen.area() * (1.0 - kSameArea))
            return "a rectangle as large as the chosen one, " + size(o.rectangle) +
                   ": a tie keeps the plane looked at first" + colourClause(o, -1);
        const auto [mine, theirs] = sizes(o.rectangle, o.rectangle.area(), chosen);
        std::string words = chosen.area() > 0.0 ? "a smaller rectangle, " + mine + ", than the chosen " + theirs
                                                : "held a rectangle, " + mine + ", none was chosen";
        return words + colourClause(o, -1);
    }
    }
    return "";
}

}  // namespace projsurf
