#pragma once
// The default detection: every vertical plane, free space where the wall was seen, the
// picture upright with respect to gravity, a surface check relative to the depth noise.
#include <memory>
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/detection/default/planar_regions.hpp"
#include "projsurf/detection/default/plane_observation.hpp"
#include "projsurf/types/point_grid.hpp"
#include "projsurf/types/projector.hpp"
#include "projsurf/detection/colour/surface_suitability.hpp"
#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/detector_config.hpp"

namespace projsurf {

/// Working buffers kept from one frame to the next (the point grid, the per-plane counts).
struct DefaultScratch {
    PointGrid grid;
    std::vector<PlaneObservation> observations;  ///< one per candidate plane
    std::vector<CellSuitability> colour;         ///< one per candidate plane, when the cloud has colour
    std::vector<std::int16_t> region_labels;     ///< depth images: the planar region of each grid element
    std::vector<PlanarRegion> regions;           ///< depth images: the planar regions found
    std::vector<std::uint8_t> exclude;           ///< grid elements of another region than the candidate's
};

/// `gravity` in the camera frame; aspect = width / height.
Detection detectDefault(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                        const Eigen::Vector3d &gravity, double aspect, DefaultScratch &scratch);

}  // namespace projsurf
