#pragma once
// How a calibration's fits ended and how well its poses pin the projector down, as YAML under
// the calibration's `residuals`: `convergence` (per fit: iterations, cap, last step, on_cap)
// and `spread` (leave-one-pose-out: the largest change of fx, fy (%), cx, cy (px), rotation,
// translation direction (deg), origin (mm), and the jackknife standard errors).
#include <vector>

#include <yaml-cpp/yaml.h>

#include "projsurf/calibration/converged_fit.hpp"
#include "projsurf/calibration/pose_spread.hpp"

namespace projsurf {

YAML::Node convergenceNode(const std::vector<FitConvergence> &fits);
YAML::Node spreadNode(const PoseSpread &spread);

}  // namespace projsurf
