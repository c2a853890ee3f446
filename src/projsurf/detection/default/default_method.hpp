#pragma once
// The default detection: every vertical plane, free space where the wall was seen, the
// picture upright with respect to gravity, a surface check relative to the depth noise.
#include <memory>
#include <optional>
#include <vector>

#include "projsurf/types/camera.hpp"
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

/// A vertical plane in view and where the camera saw it free with no projector in the way:
/// nothing counts as shadowing it (what does depends on where a projector stands).
struct SeenSurface {
    Plane plane;
    PlaneFrame frame;
    RasterFrame raster;
    cv::Mat free;   ///< CV_8U on `raster`, 255 = seen free (wall seen, nothing seen through it)
    cv::Mat state;  ///< CV_8U CellState per cell
    DepthTolerance tolerance;
    WallShape shape;
    int inliers = 0;
    /// Refused by detection's own judgement, as `detect` refuses it: a face that stands free in
    /// the room (furniture, a box: detection's Object verdict), or one seen through an opening
    /// of a nearer wall (BeyondOpening). A plan puts no picture on either.
    bool object = false, beyond_opening = false;
    bool usable() const { return !object && !beyond_opening; }
};

struct SeenSurfaces {
    std::vector<SeenSurface> surfaces;       ///< biggest first, as detection finds them
    std::optional<CameraIntrinsics> camera;  ///< organized clouds: the pinhole they were seen through
};

/// Every vertical plane detection considers, each observed over all of the part the camera
/// saw within `reach` m (along the plane) of the camera, on a raster of `cell` m; each judged
/// by detection's rules (objectFace, beyondOpening: `refused`), with the same configuration.
SeenSurfaces seeVerticalSurfaces(const Cloud &cloud, const DetectorConfig &config, const Eigen::Vector3d &gravity,
                                 double cell, double reach, DefaultScratch &scratch);

/// `gravity` in the camera frame; aspect = width / height.
Detection detectDefault(const Cloud &cloud, const Projector &projector, const DetectorConfig &config,
                        const Eigen::Vector3d &gravity, double aspect, DefaultScratch &scratch);

}  // namespace projsurf
