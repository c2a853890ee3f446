#pragma once
// The paper's detection (section 3.2), step by step, for reproduction.
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/projector.hpp"
#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/detector_config.hpp"

namespace projsurf {

/// 3.2.1 the biggest vertical plane of a voxel grid (RANSAC, kept as it is), 3.2.2 its hull and
/// the projector workspace rasterised and the biggest free rectangle, 3.2.3 the surface checker.
/// `gravity` in the camera frame; aspect = width / height.
Detection detectPaper(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                      const Eigen::Vector3d &gravity, double aspect);

}  // namespace projsurf
