#pragma once
// What became of every vertical plane a detection considered, and why all but one lost: the
// data behind `projsurf detect --explain` (plain values, filled where a method drops a plane).
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/detection/cell_state.hpp"
#include "projsurf/detection/surface_check.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// Why a candidate plane lost (or that it won), in the order a method looks at it.
enum class CandidateVerdict {
    NotExamined,       ///< never looked at: its extent could not hold a bigger rectangle than the chosen one
    Chosen,            ///< the picture's surface
    TooSmall,          ///< its rectangle is below the smallest picture worth showing (a front end's minimum)
    NotReached,        ///< the projector's beam does not reach where it was seen
    BeyondOpening,     ///< seen through an opening of a nearer wall (a window, a door)
    Object,            ///< a face that stands free in the room (furniture, a box), not a wall
    NoFreeArea,        ///< no rectangle of the aspect fits on its free cells in the beam
    SmallerRectangle,  ///< it held a rectangle, smaller than the chosen one
    CheckRejected,     ///< the surface check found too many points off the wall in its rectangle
};


struct CandidateOutcome {
    Plane plane;
    int inliers = 0;
    /// Its seen extent: the box of its points on the plane in the upright frame (2nd to 98th
    /// percentile on each axis), corners top-left, top-right, bottom-right, bottom-left (camera frame).
    std::array<Eigen::Vector3d, 4> seen{};
    double seen_width = 0.0, seen_height = 0.0;  ///< m
    Rectangle rectangle;                         ///< its best rectangle (area 0: none was placed)
    double bound = 0.0;  ///< m^2, the largest rectangle the beam's part of its extent could hold (default method)
    CandidateVerdict verdict = CandidateVerdict::NotExamined;
    SurfaceCheckResult check;  ///< CheckRejected: the counts (no indices)
    /// Share of the beam's raster cells on it in each cell state (default method, once its
    /// free space was observed; all 0 otherwise).
    std::array<double, kCellStates> beam_cells{};
    std::string detail;  ///< a front end's sentence for TooSmall (names its option), else empty
};

/// The seen extent of `indices` of `points` on `frame`'s plane, into `o.seen*`.
void setSeenExtent(const std::vector<Point> &points, const std::vector<int> &indices, const PlaneFrame &frame,
                   CandidateOutcome &o);

/// Shares of `state`'s cells (CellState values) among those set in `beam` (same size, CV_8U),
/// into `o.beam_cells`; nothing when either is empty.
void setBeamCells(const cv::Mat &state, const cv::Mat &beam, CandidateOutcome &o);

/// The cell state (CellState value) that covers most of the beam's cells on it, edges and
/// free cells aside; -1 when none does (no cells counted).
int mainBlocker(const CandidateOutcome &o);

/// The outcome in words, for a user: "shadowed by something in front (62 % of the beam on
/// it)", "a smaller rectangle, 0.41 x 0.23 m, than the chosen 1.20 x 0.68 m". `chosen`: the
/// chosen rectangle (area 0 when nothing was chosen).
std::string outcomeWords(const CandidateOutcome &o, const Rectangle &chosen);

/// The rectangle the other candidates lost to: the chosen plane's, or, when it was too small
/// for a front end, the detection's own (`answer`); area 0 when nothing was chosen.
Rectangle winningRectangle(const std::vector<CandidateOutcome> &candidates, const Rectangle &answer);

/// One word for the verdict, for the JSON ("chosen", "too_small", "not_reached", ...).
const char *verdictName(CandidateVerdict v);

/// The verdict's word, a plane with no free area named by what blocks it most ("shadowed",
/// "seen_through", "no_reading", "too_dark", "glare", "textured", "saturated").
std::string outcomeName(const CandidateOutcome &o);

}  // namespace projsurf
