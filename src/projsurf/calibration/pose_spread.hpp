#pragma once
// How well a set of poses pins the projector down: the projector fitted again with each pose
// left out once (leave-one-pose-out, the jackknife), compared with the fit on all of them. A
// covariance from one fit says how well the points constrain the parameters if the model and
// the noise are right; the jackknife says how much one pose moves the answer, whatever the
// cause (a pose seen at a poor angle, a lens term trading against the principal point).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "projsurf/types/projector.hpp"

namespace projsurf {

/// The quantities compared. OpenCV's convention: P_proj = rotation P_cam + translation.
struct ProjectorEstimate {
    double fx = 0, fy = 0, cx = 0, cy = 0;  ///< framebuffer px
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< m
};

/// From the contract's projector (rotation: columns the projector's axes in the camera frame).
ProjectorEstimate projectorEstimate(const Projector &p);

struct PoseSpread {
    int poses = 0;   ///< leave-one-out fits tried (one per pose; 0: too few poses to leave one out)
    int failed = 0;  ///< of them, fits that failed (too little left)
    int on_cap = 0;  ///< of them, fits that stopped on an iteration cap
    /// Largest deviation of a leave-one-out fit from the all-pose fit.
    double fx_pct = 0, fy_pct = 0, cx_px = 0, cy_px = 0, rotation_deg = 0, translation_dir_deg = 0, origin_mm = 0;
    /// Jackknife standard errors, sqrt((n - 1) / n sum (x_i - mean)^2), of the same.
    double se_fx_pct = 0, se_fy_pct = 0, se_cx_px = 0, se_cy_px = 0;
};

/// `leave_one_out[i]`: the fit without pose i, nullopt when it failed.
PoseSpread poseSpread(const ProjectorEstimate &all, const std::vector<std::optional<ProjectorEstimate>> &leave_one_out);

/// Above these the spread is large: leaving one pose out moves the projector by more than the
/// agreement projsurf asks of a calibration (issue 37's targets).
struct SpreadLimits {
    double focal_pct = 1.0, principal_px = 30.0, rotation_deg = 1.0, translation_dir_deg = 2.0;
};

/// One line, e.g. "fx 0.94 %, fy 0.90 %, cx 36.1 px, cy 35.9 px, rotation 0.76 deg, translation
/// direction 1.71 deg (5 poses left out once each)".
std::string describeSpread(const PoseSpread &s);
/// "" when within the limits, else a one-line warning naming what is large.
std::string spreadWarning(const PoseSpread &s, const SpreadLimits &limits = {});

}  // namespace projsurf
