#include "projsurf/detection/candidate.hpp"

#include "projsurf/detection/raster_frame.hpp"

namespace projsurf {

CandidateOutcome outcomeOf(const Candidate &c, const std::vector<Point> &points, bool chosen, double bound) {
    CandidateOutcome o;
    o.bound = bound;
    o.plane = c.plane;
    o.inliers = c.inliers;
    o.verdict = chosen ? CandidateVerdict::Chosen : c.verdict;
    // A rectangle placed before colour took its cells away is not this plane's answer.
    if (o.verdict != CandidateVerdict::NoFreeArea) o.rectangle = c.rectangle;
    o.check = {c.check.points, c.check.outliers, c.check.accepted, {}};
    setSeenExtent(points, c.inlier_indices, c.frame, o);
    if (!c.cell_state.empty() && c.raster.cols > 0)
        setBeamCells(c.cell_state, footprintCells(c.raster, c.footprint.uv), o);
    return o;
}

}  // namespace projsurf
