#pragma once
// Fits the full projector model (intrinsics, distortion, rotation, origin) to 3-D points in the
// camera frame and the framebuffer pixels that lit them (structured light lifted through the
// registered depth). Linear start (DLT, RQ decomposition), then Levenberg-Marquardt on the
// reprojection error with Huber weights (IRLS) and a final trimming of gross outliers.
// Distortion is fitted only as far as the data's coverage of the framebuffer constrains it.
// Each Levenberg-Marquardt stage runs to convergence (no step lowers the cost by more than a
// relative 1e-10) under an explicit cap, and reports its iterations and last step.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "projsurf/calibration/converged_fit.hpp"
#include "projsurf/calibration/pose_spread.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct ProjectorCorrespondence {
    Eigen::Vector3d point;  ///< camera frame, m
    Eigen::Vector2d pixel;  ///< framebuffer px (centres at integers)
};

struct ProjectorFitConfig {
    int width = 1280, height = 800;  ///< framebuffer, px
    std::size_t min_points = 2000;   ///< fewer decoded pixels cannot be trusted
    std::size_t max_points = 40000;  ///< subsampled (evenly) beyond this, for speed
    double huber_px = 1.5;           ///< Huber threshold, px (decoding quantises to ~1-2 px)
    double trim_px = 6.0;            ///< after the robust fit, points beyond this are dropped and the fit repeated
    double min_relief_m = 0.02;      ///< RMS distance of the points from their best plane below this: flat
    double coverage_k1 = 0.35;       ///< share of the framebuffer (16 x 10 cells) with points to fit k1
    double coverage_k2 = 0.65;       ///< ... to fit k2 as well
    int max_iterations = 500;        ///< cap of each Levenberg-Marquardt stage
    double cost_eps = 1e-10;         ///< converged: no step lowers the cost by a larger share
};

struct ProjectorFit {
    bool ok = false;
    std::string problem;            ///< why not (what to capture instead)
    Projector projector;            ///< the full model
    double rms_px = 0, max_px = 0;  ///< reprojection residuals of the inliers, framebuffer px
    std::size_t points = 0, inliers = 0;
    double coverage = 0;       ///< share of framebuffer cells with points
    double relief_m = 0;       ///< RMS distance of the points from their best plane
    int distortion_terms = 0;  ///< 0, 1 (k1) or 2 (k1, k2)
    /// The stages: "pinhole", "distortion", "trimmed" (last_step: the last accepted step's
    /// relative cost decrease; last_step_px: its largest change of fx, fy, cx, cy).
    std::vector<FitConvergence> convergence;
    PoseSpread spread;  ///< fitProjectorPoses with 3 or more poses
};

ProjectorFit fitProjector(const std::vector<ProjectorCorrespondence> &pairs, const ProjectorFitConfig &config = {});

/// The same on the poses' points together, then again with each pose left out once (3 or more
/// poses; ProjectorFit::spread).
ProjectorFit fitProjectorPoses(const std::vector<std::vector<ProjectorCorrespondence>> &poses,
                               const ProjectorFitConfig &config = {});

/// The iteration-cap warnings of the fit and its leave-one-out fits, then the spread's.
std::vector<std::string> projectorFitWarnings(const ProjectorFit &fit, const SpreadLimits &limits = {});

}  // namespace projsurf
