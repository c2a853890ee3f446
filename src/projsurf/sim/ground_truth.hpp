#pragma once
// The true answer for a simulated scene: on every vertical projection surface, the cells
// (default 5 mm) that are on the surface, seen by the camera (in the image, in range, not
// at a grazing angle, not hidden) and lit by the projector (in its frustum, not in an
// obstacle's shadow); then the largest free upright rectangle of the wanted aspect ratio
// (detection/rectangle_search.hpp). The best surface's rectangle is the ground truth.
//
// What is free (TruthOptions::tolerance, 1 cm): a thing standing at most 1 cm proud of the
// surface does not hide it, anything farther out does. So flush things (posters, whiteboards,
// <= 3 mm) and a bowed wall's few mm are free; frames, TVs (2-5 cm) are obstacles; of the 1-2
// cm things, switches, sockets and skirting boards modelled 1.5 cm proud are obstacles (a
// picture on them is visibly broken), anything 1 cm proud or less is free. Glass (Material::
// Glass) is neither a surface nor an obstacle: a window is a hole in the wall. A bowed wall's
// truth is its flat plane (Quad::bow is ignored here).
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/sim/sensor_model.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::sim {

struct TruthOptions {
    double aspect = 0.0;                   ///< width / height; 0 = the projector framebuffer's
    double cell = 0.005;                   ///< m, raster cell on the surface
    double max_tilt = kVerticalTolerance;  ///< rad, a surface is vertical within this (contract, paper 3.2.1)
    double tolerance = 0.01;               ///< m, a hit this close in front of a cell does not hide it (posters)
    /// Also require a depth reading to be possible: when the sensor models the IR emitter's
    /// shadow, cells the emitter's pattern cannot reach (beside foreground edges) are not
    /// free. Off by default: those cells are free wall, only unmeasured.
    bool require_depth = false;
};

/// The result on one projection surface.
struct SurfaceTruth {
    int surface = -1;                                       ///< Quad::surface id
    std::string label;                                      ///< label of its quads ("wall", "closet", ...)
    Plane plane;                                            ///< camera frame, normal towards the camera
    PlaneFrame frame;                                       ///< up = -gravity, origin where the projector axis meets it
    std::array<Eigen::Vector3d, 4> footprint{};             ///< projector footprint TL, TR, BR, BL
    bool has_footprint = false;                             ///< false when a corner ray misses the plane
    cv::Mat free_mask;                                      ///< CV_8U, 255 = free; row 0 is the top (largest up)
    Eigen::Vector2d grid_origin = Eigen::Vector2d::Zero();  ///< plane coords of the mask's top-left corner
    double cell = 0.0;                                      ///< m
    bool found = false;
    Rectangle rectangle;     ///< exact aspect, inside free cells
    double free_area = 0.0;  ///< m^2 of free cells
};

struct GroundTruth {
    bool found = false;
    double aspect = 0.0;
    SurfaceTruth best;                   ///< the surface with the largest rectangle
    std::vector<SurfaceTruth> surfaces;  ///< every vertical projection surface considered
};

/// Ground truth for a scene seen by `sensor.camera` (its range and grazing limits) with
/// `projector`; `gravity` in the camera frame.
GroundTruth computeGroundTruth(const Scene &scene, const SensorModel &sensor, const Projector &projector,
                               const Eigen::Vector3d &gravity, const TruthOptions &options = {});

/// True when the segment from `from` to `to` is blocked by a quad (not glass) more than
/// `tolerance` before `to`.
bool segmentBlocked(const Scene &scene, const Eigen::Vector3d &from, const Eigen::Vector3d &to, double tolerance);

}  // namespace projsurf::sim
