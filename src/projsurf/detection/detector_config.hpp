#pragma once
// Every setting of projection surface detection, one source per default, each with its unit
// and where it comes from (paper section, datasheet, or a measurement of this project).
#include "projsurf/detection/colour/surface_suitability.hpp"
#include "projsurf/detection/default/face_surround.hpp"
#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/detection/default/planar_regions.hpp"
#include "projsurf/detection/default/wall_shape.hpp"
#include "projsurf/detection/virtual_depth_image.hpp"
#include "projsurf/types/depth_tolerance.hpp"

namespace projsurf {

enum class Method {
    Default,  ///< every vertical plane, observed free space, gravity-upright, relative check
    Paper,    ///< the paper's steps, one by one (for reproduction)
};
enum class HullKind { Concave, Convex };

/// The paper's method (section 3.2), step by step.
struct PaperConfig {
    HullKind hull = HullKind::Concave;  ///< hull of the inliers (paper 4.1 keeps concave)
    double voxel_leaf = 0.05;           ///< m, voxel-grid side (paper 3.2.1)
    double ransac_distance = 0.05;      ///< m, inlier band; not given in the paper, = voxel side
    int ransac_iterations = 1000;       ///< PCL SACSegmentation's default max iterations
    double concave_alpha = 0.1;         ///< m, alpha of the concave hull (2 voxels)
    double cell = 0.02;                 ///< m, raster cell of the free-space matrices (paper 3.2.2)
    double outlier_distance = 0.05;     ///< m, |z - mean z| above this is an outlier (paper 3.2.3)
    int max_outliers = 5000;            ///< more outliers reject the surface (paper 4.3)
    int max_voxels = 500000;  ///< more voxels are not searched (the hull keeps them all: memory, time); a VGA frame has
                              ///< 307,200 points
};

/// Default method, stage 1: the vertical planes in view: on depth images, planar regions of the
/// image (deterministic); on unorganized clouds, sequential RANSAC on a sample.
struct PlaneSearchConfig {
    bool image_regions = true;  ///< organized clouds: planar regions instead of RANSAC
    PlanarRegionOptions regions;
    int target_samples = 12000;    ///< points kept for the search (pixel stride / every k-th), measured
    int max_planes = 4;            ///< vertical planes tried, biggest first
    int min_plane_points = 150;    ///< sampled inliers for a plane to count
    int ransac_iterations = 300;   ///< hypotheses per plane (adaptive stop usually earlier), measured
    int score_subset = 1500;       ///< points a hypothesis is scored on, measured (same planes as all 12000)
    double max_sample_span = 1.5;  ///< m, the 2nd and 3rd point of a hypothesis within this of the 1st
    int refine_rounds = 2;         ///< least-squares refits of each plane on its inliers
    double merge_angle = 0.05;     ///< rad, a plane this parallel to a found one, within its margin, is a slice of it
    /// Depth images: when the vertical regions hold less than this share of the readings (cells
    /// too rough to grow), the RANSAC search runs as well. Measured: 1-2 % on a D435 wall whose
    /// per-pixel noise is 3x the model's, 8-57 % on the labelled real frames.
    double min_region_share = 0.05;
};

/// Default method, stage 2: how each wall departs from its plane (detection/default/wall_shape.hpp).
struct WallConfig {
    bool fit_shape = true;  ///< follow the smooth bend real depth cameras give a flat wall
    WallShapeOptions shape;
    double noise_min = 0.5;  ///< the band follows the noise measured on the wall, within these
    double noise_max = 4.0;  ///< multiples of the model's (K&OE Kinect v1; ToF is better, stereo worse)
    double local_cap = 1.0;  ///< the wall's noise is at most this many times the local noise (or the model's)
    int noise_offset_px =
        8;  ///< px between the readings whose differences measure the noise (stereo noise is correlated over ~4 px)
    /// Least-squares refits of the plane to the points on the wall's shape (the segmentation's
    /// plane is fitted to part of the wall), each followed by a new shape; a refit that turns
    /// the plane by less than refit_min_turn (rad) and moves it by less than refit_min_shift (m)
    /// ends them.
    int plane_refits = 1;
    double refit_min_turn = 0.0087;  ///< rad, 0.5 deg: a quarter of the 2 deg an upright picture may lean
    double refit_min_shift = 0.005;  ///< m, measured on the labelled real frames (docs/wall_model.md)
};

/// Default method, stage 2: faces that stand free in the room (furniture, boxes, people), stand
/// before a larger wall seen above them, or are too low for a picture are objects, not
/// projection surfaces (detection/default/face_surround.hpp); depth images only.
struct ObjectFaceConfig {
    bool avoid = true;  ///< skip faces that stand free; false takes any vertical face (the paper's behaviour)
    FaceSurroundOptions surround;
    FreeStandingRule rule;
    /// m: a face enclosed in front on every side and this far behind a parallel wall is seen
    /// through an opening in it (a window, a door), not a surface; a kitchen niche between
    /// cabinets is 0.3-0.6 m deep.
    double opening_depth = 0.8;
};

/// Default method, stage 3: where on a plane the camera saw free wall (paper 3.2.2).
struct FreeSpaceConfig {
    double cell = 0.01;  ///< m, raster cell (area error < 0.05 m^2 at 3 m, measured)
    int stride = 2;      ///< pixel step of the pass on organized clouds (3 lost 7 % of the area behind a person)
    bool exclude_other_surfaces = true;  ///< depth images: points clearly nearer another region's plane are no support
    int max_gap_cells = 8;               ///< largest gap between wall samples closed, cells (sensor holes up to 8 cm)
    int min_blocked_neighbours =
        2;  ///< a blocked cell needs this many blocked cells in its 3x3: single cells are noise
    double image_margin =
        1.0 / 64;  ///< of the image width: margin around where a plane is seen (mixed pixels, grazing angles)
    double inlier_box_margin = 1.0 / 16;  ///< of the image width, when the cloud has no fitted intrinsics
    ProudEvidence proud;                  ///< what stands off the wall's shape on average over a window
};

/// Default method, stage 5: the surface check on the rectangle (paper 3.2.3).
struct SurfaceCheckConfig {
    double max_outlier_fraction = 0.03;  ///< share of checked points off the wall that rejects an area, measured
};

/// How registered colour (Cloud::colours) is used.
enum class SuitabilityMode {
    Off,     ///< colour ignored
    Avoid,   ///< cells unfit by their colour are not free
    Prefer,  ///< of the rectangle that avoids them and the one that does not, the larger area x (1 - unfit share)^k
};

/// The mode's word, as the JSON's suitability.mode, `detect --suitability` and ~suitability write it.
inline const char *suitabilityModeName(SuitabilityMode mode) {
    switch (mode) {
    case SuitabilityMode::Off: return "off";
    case SuitabilityMode::Prefer: return "prefer";
    case SuitabilityMode::Avoid: break;
    }
    return "avoid";
}

/// Default method, stage 4b: the surface's suitability from its colour (issue 15), only when
/// the cloud carries colour (without colour it is off whatever the mode).
struct SuitabilityConfig {
    SuitabilityMode mode = SuitabilityMode::Avoid;
    SuitabilityOptions cells;
    double prefer_exponent = 2.0;  ///< k of prefer's rule (a 10 % unfit rectangle counts 81 % of its area)
};

struct DetectorConfig {
    Method method = Method::Default;
    double aspect = 0.0;    ///< picture width / height; 0 = the projector framebuffer's
    double max_tilt = 0.1;  ///< rad, normal vs horizontal (contract; paper 3.2.1)
    unsigned seed = 42;     ///< RANSAC random seed (runs are deterministic)

    DepthTolerance tolerance;        ///< how far off a plane a reading may be (default method)
    VirtualImageConfig unorganized;  ///< default method: unorganized clouds as a pinhole's depth image
    PlaneSearchConfig planes;
    WallConfig wall;
    ObjectFaceConfig objects;
    FreeSpaceConfig free_space;
    SurfaceCheckConfig check;
    SuitabilityConfig suitability;
    PaperConfig paper;
};

}  // namespace projsurf
