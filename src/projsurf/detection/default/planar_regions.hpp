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

#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/point_grid.hpp"

namespace projsurf {

struct PlanarRegionOptions {
    int cell = 8;                  ///< grid elements per cell side (8 at the 2-px grid: 16 px, CAPE's 20 px order)
    double min_fill = 0.5;         ///< share of a cell's points that must be readings
    double thickness_bands = 0.5;  ///< a flat cell is thinner (RMS off its plane) than this many inlier bands
    double seed_tilt = 0.5;        ///< rad, a region starts from a cell whose normal is within this of horizontal
    double max_tilt = 0.1;         ///< rad, a region's plane within this of horizontal (contract)
    double join_bands =
        0.6;  ///< a neighbour cell joins when its points' RMS distance to the region's plane is below this many bands
    int min_cells = 6;  ///< smaller regions are not surfaces
    double merge_angle =
        0.15;  ///< rad, regions this parallel whose points lie within the obstacle margin of each other's plane are one
};

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
