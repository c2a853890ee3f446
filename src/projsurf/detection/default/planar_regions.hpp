#pragma once
// The vertical planes of an organized cloud, found deterministically (the default method's
// 3.2.1 on depth images): the image is cut into cells, a plane is fitted to each, the flat and
// vertical cells grow into regions of one plane each, and regions on the same plane (a wall
// cut in two by a cupboard) merge. The same frame gives the same planes, whatever the seed.
// In the spirit of CAPE (Proença & Gao, IROS 2018: cell-grid plane fits with depth-dependent
// thresholds), written for this project.
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/point_grid.hpp"

namespace projsurf {

struct PlanarRegion {
    Plane plane;
    int points = 0;  ///< grid points in its cells
    int cells = 0;
};

/// Biggest first. `grid` must come from an organized cloud. With `labels`, also which region
/// (index into the result) each grid element's cell belongs to, -1 for none: grid-sized.
std::vector<PlanarRegion> findVerticalRegions(const PointGrid &grid, const Eigen::Vector3d &gravity,
                                              const DepthTolerance &tolerance, const PlanarRegionOptions &options = {},
                                              std::vector<std::int16_t> *labels = nullptr);

/// Grid elements in `box` (grid coordinates) that belong to a region `other` marks and lie
/// nearer its plane than `plane`, by more than a quarter of the inlier band (1), else 0: where two
/// surfaces meet (a corner), a point is the nearer one's unless noise cannot tell. `regions` and
/// `other` as findVerticalRegions returned and labelled them.
void nearerOtherMask(const PointGrid &grid, const cv::Rect &box, const std::vector<std::int16_t> &labels,
                     const std::vector<PlanarRegion> &regions, const std::vector<char> &other, const Plane &plane,
                     const DepthTolerance &tolerance, std::vector<std::uint8_t> &mask);

}  // namespace projsurf
