#pragma once
// The reference answer of a labelled real frame, independent of the detector: a robust plane
// per labelled surface, and the largest upright rectangle of the projector's aspect that lies
// inside the surface's polygons, outside every obstacle polygon and inside the projector's
// footprint, found exhaustively on a fine raster of the plane.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "eval/real/real_labels.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf::eval {

/// Even-odd point-in-polygon test (pixel coordinates).
bool insidePolygon(const std::vector<Eigen::Vector2d> &polygon, const Eigen::Vector2d &p);

/// Where a camera-frame point falls in the label: inside a region of surface `surface` and
/// outside every obstacle (false also behind the camera or outside the image).
bool labelledFree(const RealLabel &label, const CameraIntrinsics &camera, int surface, const Eigen::Vector3d &point);

struct SurfaceFit {
    bool ok = false;
    Plane plane;       ///< camera frame, normal towards the camera
    int points = 0;    ///< depth readings kept by the last pass
    double rms = 0.0;  ///< m, of the kept points about the plane
};

/// Plane of the depth readings inside the surface's regions and outside the obstacles:
/// least squares, then 6 passes that keep the points within max(2.5 robust sigmas, 5 mm).
SurfaceFit fitLabelSurface(const Cloud &cloud, const CameraIntrinsics &camera, const RealLabel &label, int surface);

/// The best rectangle on one surface whose plane is known (found = false when the projector's
/// footprint misses the plane or nothing fits). `cell` is the raster side in metres (capped at
/// 2500 cells a side); the answer is exact on that raster, so it is within one cell of the
/// continuous optimum on each side.
LabelBest bestRectangleOnSurface(const RealLabel &label, const CameraIntrinsics &camera, int surface,
                                 const Plane &plane, double cell = 0.0025);

/// Fits every surface (stores the planes in `label`) and returns the best rectangle over all.
LabelBest referenceBest(const Cloud &cloud, const CameraIntrinsics &camera, RealLabel &label, double cell = 0.0025);

/// The label with its colour-unsuitable polygons added to the obstacles (colour.best as its
/// best): what a colour-aware answer is scored against.
RealLabel colourAwareLabel(const RealLabel &label);

/// The colour-aware best: the same search as referenceBest, on the surfaces' planes
/// as fitted by it (call referenceBest first), with the unsuitable polygons as further obstacles.
LabelBest colourReferenceBest(const CameraIntrinsics &camera, const RealLabel &label, double cell = 0.0025);

}  // namespace projsurf::eval
