#pragma once
// A vertical plane under consideration and what was found on it (shared by both methods).
#include <array>
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/projector_footprint.hpp"
#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

struct Candidate {
    Plane plane;
    int inliers = 0;
    std::vector<int> inlier_indices;  ///< into the input cloud
    PlaneFrame frame;
    Footprint footprint;  ///< the projector's picture on the plane
    RasterFrame raster;
    cv::Mat free;        ///< CV_8U, 255 = free cells inside the footprint
    cv::Mat surface;     ///< CV_8U, 255 = free surface, the footprint not applied (default method)
    cv::Mat cell_state;  ///< CV_8U CellState (default method)
    Rectangle rectangle;
    std::vector<std::vector<Eigen::Vector3d>> outlines;
    CandidateVerdict verdict = CandidateVerdict::NotExamined;  ///< what became of it (set where it is dropped)
    SurfaceCheckResult check;                                  ///< CheckRejected: its check
};

/// The candidate's intermediate results, as a detection reports them.
inline void describeCandidate(const Candidate &c, DetectionDebug &debug) {
    debug.frame = c.frame;
    debug.workspace = c.footprint.corners;
    debug.has_workspace = true;
    debug.hull = c.outlines;
    debug.free_space = c.free;
    debug.cell_state = c.cell_state;
    debug.grid_origin = c.raster.top_left;
    debug.grid_cell = c.raster.cell;
    debug.inliers = c.inlier_indices;
}

/// What became of the candidate, as a detection reports it (`chosen`: it is the answer's).
/// `points`: what its inlier indices index (the cloud's points, or the paper's voxels);
/// `bound`: m^2, the largest rectangle its extent in the beam could hold (0: not known).
CandidateOutcome outcomeOf(const Candidate &c, const std::vector<Point> &points, bool chosen, double bound = 0.0);

}  // namespace projsurf
