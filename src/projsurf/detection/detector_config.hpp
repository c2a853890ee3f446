#pragma once
// Every setting of projection surface detection, one source per default, each with its unit
// and where it comes from (paper section, datasheet, or a measurement of this project:
// docs/tuning.md).
//
// Each setting is declared once, here (and in types/depth_tolerance.hpp): its field
// line gives the default, and its doc comment, in a fixed form, the range the front ends accept
// and the doc, unit first: `double min_fill = 0.5;  ///< (0, 1] share of ...` (`(lo, hi]`
// refuses lo itself; booleans and words take no range). The key table of the front ends
// (frontend/settings/detector_config_keys.hpp: the YAML file, `detect --print-config`, the CLI's,
// node's and Python's shared settings) is written from these lines at build time by
// scripts/config_keys.py, and docs/interface.md's table is checked against it. A new setting
// is its field line here and its row there (config/detector.yaml, every key at its default, is
// then rewritten by `projsurf detect --print-config`; a test compares). A field whose doc starts
// with "not a key:" is filled in by a stage, not set by users.
#include <vector>

#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"

namespace projsurf {

enum class Method {
    Default,  ///< every vertical plane, observed free space, gravity-upright, relative check
    Paper,    ///< the paper's steps, one by one (for reproduction)
};
enum class HullKind { Concave, Convex };

/// How a cloud's own pixel grid is recognised: x/z of a depth image's points lie on a lattice of
/// step 1 / fx (detection/planes/pixel_lattice.hpp).
struct PixelLatticeOptions {
    double tolerance =
        5e-5;  ///< [0, 0.01] x/z, a gap this small within a column's values (float rounding, a PCD's printed decimals)
    double max_residual = 0.15;  ///< [0, 0.5] of a step: a value further off the lattice is not on it
    double max_off = 0.01;       ///< [0, 1] share of the values that may lie off it (stray points)
    int min_columns = 16;        ///< [2, 8192] fewer distinct columns: too few to tell a lattice
    int max_columns = 8192;      ///< [16, 65536] more: no depth image this wide
    int max_samples = 1 << 16;   ///< [1, 2^24] values looked at (evenly strided)
};

/// Default method, unorganized clouds (`unorganized`): the depth image a pinhole at the camera
/// would have taken of them (detection/planes/virtual_depth_image.hpp).
struct VirtualImageConfig {
    bool enabled = true;               ///< unorganized clouds as a pinhole's depth image; false: sequential RANSAC
    double max_half_angle_deg = 70.0;  ///< (0, 89] deg off the optical axis kept (the projector's beam is < 30)
    double fill =
        1.0;  ///< (0, 16] clouds on no pixel grid: pixels per point over the covered view (1: the cloud's own density)
    int max_pixels = 1 << 20;     ///< [1, 2^24] px, image size cap (about 1.3 x 1280x800)
    int min_points = 500;         ///< [1, 2^24] fewer points in front of the camera: no image
    PixelLatticeOptions lattice;  ///< how a cloud's own pixel grid (a depth image's) is recognised
};

/// The paper's method (section 3.2), step by step.
struct PaperConfig {
    HullKind hull = HullKind::Concave;  ///< hull of the inliers (paper 4.1 keeps concave)
    double voxel_leaf = 0.05;           ///< [0.001, 1] m, voxel-grid side (paper 3.2.1)
    double ransac_distance = 0.05;      ///< [0.001, 1] m, inlier band; not given in the paper, = voxel side
    int ransac_iterations = 1000;       ///< [1, 1e6] RANSAC iterations (PCL SACSegmentation's default)
    double concave_alpha = 0.1;         ///< [0.0001, 10] m, alpha of the concave hull (2 voxels)
    double cell = 0.02;                 ///< [0.002, 0.5] m, raster cell of the free-space matrices (paper 3.2.2)
    double outlier_distance = 0.05;     ///< [0.0001, 10] m, |z - mean z| above this is an outlier (paper 3.2.3)
    int max_outliers = 5000;            ///< [0, 2^31-1] more outliers reject the surface (paper 4.3)
    int max_voxels = 500000;  ///< [1, 2^24] more voxels are not searched (the hull keeps them all: memory, time); a VGA
                              ///< frame has 307,200 points
};

struct PlanarRegionOptions {
    int cell = 8;           ///< [1, 256] grid elements per cell side (8 at the 2-px grid: 16 px, CAPE's 20 px order)
    double min_fill = 0.5;  ///< (0, 1] share of a cell's points that must be readings
    double thickness_bands =
        0.5;                 ///< [0.01, 100] a flat cell is thinner (RMS off its plane) than this many inlier bands
    double seed_tilt = 0.5;  ///< [0, pi/2] rad, a region starts from a cell whose normal is within this of horizontal
    double max_tilt = kVerticalTolerance;  ///< not a key: the default method sets it to DetectorConfig::max_tilt
    double join_bands = 0.6;    ///< [0.01, 100] a neighbour cell joins when its points' RMS distance to the region's
                                ///< plane is below this many bands
    int min_cells = 6;          ///< [1, 2^24] cells: smaller regions are not surfaces
    double merge_angle = 0.15;  ///< [0, pi/2] rad, regions this parallel whose points lie within the obstacle margin of
                                ///< each other's plane are one
};

/// Default method, stage 2 (`planes`): the vertical planes in view: on depth images, planar regions of the
/// image (deterministic); on unorganized clouds, sequential RANSAC on a sample.
struct PlaneSearchConfig {
    bool image_regions = true;  ///< organized clouds: planar regions instead of RANSAC
    PlanarRegionOptions regions;
    int target_samples = 12000;    ///< [3, 2^24] points kept for the search (pixel stride / every k-th; docs/tuning.md)
    int max_planes = 4;            ///< [1, 20] vertical planes tried, biggest first
    int min_plane_points = 150;    ///< [3, 2^24] sampled inliers for a plane to count
    int ransac_iterations = 300;   ///< [1, 1e6] hypotheses per plane (adaptive stop usually earlier; docs/tuning.md)
    int score_subset = 1500;       ///< [3, 2^24] points a hypothesis is scored on (docs/tuning.md)
    double max_sample_span = 1.5;  ///< [0.0001, 10] m, the 2nd and 3rd point of a hypothesis within this of the 1st
    int refine_rounds = 2;         ///< [0, 100] least-squares refits of each plane on its inliers
    double merge_angle =
        0.05;  ///< [0, pi/2] rad, a plane this parallel to a found one, within its margin, is a slice of it
    /// Depth images: when the vertical regions hold less than this share of the readings (cells
    /// too rough to grow), the RANSAC search runs as well (measured: docs/tuning.md).
    double min_region_share =
        0.05;  ///< [0, 1] share of readings: depth images whose regions hold less also run the RANSAC search
};

struct WallReliefOptions {
    bool enabled = true;  ///< fit the relief (features of a few tens of px) too
    /// px of the depth image at the wall's depth between nodes, and the Gaussian's sigma: the
    /// sensor's distortion lives in the image (our Kinect v1 model: features of 110 px), so the
    /// relief follows features of a few tens of pixels and no finer (a frame's edge stays out).
    double node_px = 12.0;     ///< [1, 1000] px at the wall's depth between relief nodes
    double sigma_px = 20.0;    ///< [0.5, 1000] px, the relief's Gaussian sigma
    double tukey_bands = 1.5;  ///< [0.01, 100] Tukey biweight width in inlier bands
    int rounds = 3;            ///< [1, 100] reweighting rounds
    /// Nodes with less than this share of the median node weight shrink towards 0 (the
    /// quadratic): where the wall was hardly seen, the relief does not guess.
    double min_weight_share = 0.25;  ///< [0, 1] nodes below this share of the median node weight shrink towards 0
    int max_nodes = 96;              ///< [1, 1024] per side; a larger wall takes wider spacing
};

struct WallShapeOptions {
    double capture_bands = 2.5;  ///< [0.01, 100] points within this many inlier bands of the plane take part
    double tukey_bands = 1.5;    ///< [0.01, 100] Tukey biweight width, in inlier bands (outliers: what stands proud)
    int iterations = 5;          ///< [1, 100] reweighted least-squares rounds
    int min_points = 60;         ///< [6, 2^24] fewer points: the wall stays flat
    int max_points = 2000;       ///< [6, 2^24] more are thinned evenly (six coefficients; measured, docs/tuning.md)
    double max_bend =
        0.08;  ///< [0.0001, 10] m, a fitted bend larger than this anywhere in the points' extent is refused
    double bend_per_z2 =
        0.0089;  ///< [0, 10] 1/m, or than this times the depth squared there (max_bend at 3 m; Kinect v1's
                 ///< +-3-5 cm at 3 m grows with z^2 as its disparity error does)
    WallReliefOptions relief;
};

/// Default method, stage 4 (`wall_shape`): how each wall departs from its plane (detection/default/wall_shape.hpp).
struct WallConfig {
    bool fit_shape = true;  ///< follow the smooth bend real depth cameras give a flat wall
    WallShapeOptions shape;
    double noise_min =
        0.5;  ///< [0.01, 100] the band follows the noise measured on the wall, at least this many times the model's
    double noise_max =
        4.0;  ///< [0.01, 100] ... and at most this many times (K&OE Kinect v1; ToF is better, stereo worse)
    double local_cap =
        1.0;  ///< [0.01, 100] the wall's noise is at most this many times the local noise (or the model's)
    int noise_offset_px = 8;  ///< [1, 256] px between the readings whose differences measure the noise (stereo noise is
                              ///< correlated over ~4 px)
    /// Least-squares refits of the plane to the points on the wall's shape (the segmentation's
    /// plane is fitted to part of the wall), each followed by a new shape; a refit that turns
    /// the plane by less than refit_min_turn (rad) and moves it by less than refit_min_shift (m)
    /// ends them.
    int plane_refits = 1;            ///< [0, 100] least-squares refits of the plane to the wall's shape
    double refit_min_turn = 0.0087;  ///< [0, pi/2] rad, a refit turning the plane by less than this, 0.5 deg (a quarter
                                     ///< of the 2 deg an upright picture may lean) ...
    double refit_min_shift = 0.005;  ///< [0, 10] m, ... and moving it by less than this (docs/tuning.md)
};

struct FaceSurroundOptions {
    int bins = 16;           ///< [1, 1024] positions along each edge (columns for the top, rows for the sides)
    int min_bin_points = 3;  ///< [1, 2^24] face points a position needs for its edge to be taken there
    double edge_quantile =
        0.97;  ///< [0, 1] the edge at a position: this quantile of the face's points there (stray inliers)
    std::vector<double> offsets = {0.04, 0.10, 0.20};  ///< [0.0001, 10] m beyond the edge, looked at nearest first
    double min_step =
        0.05;           ///< [0.0001, 10] m, a reading this far off the plane (and beyond the noise margin) is off it
    int search_px = 2;  ///< [0, 64] px, a missing reading is looked for this far around its pixel
    double max_gap = 0.10;  ///< [0.0001, 10] m, a gap this wide between a face's points ends it (for its size)
};

struct FreeStandingRule {
    double min_seen = 0.4;  ///< [0, 1] share of an edge's positions that must be past or front for it to count
    double min_past = 0.6;  ///< [0, 1] share of those open behind (pastShare) for the edge to be open
    /// A face at least this tall and wide serves like a wall even when it stands free: a
    /// full-height wardrobe or closet front (paper 4.2 projects on one), taller than a person and
    /// wider than a door.
    double wall_height = 1.8;  ///< [0, 10] m, a face this tall and wall_width wide serves like a wall
    double wall_width = 0.8;   ///< [0, 10] m, ... and this wide (wider than a door)
    /// A face lower than this (its median unbroken height) is a strip, no surface: a desk's or a
    /// shelf's edge, clutter that happens to lie in one plane. The smallest picture (0.15 m wide
    /// at 16:10) is 0.094 m tall.
    double min_height = 0.1;  ///< [0, 10] m, a face lower than this is a strip, no surface
};

/// Default method, stage 4 (`wall_shape`): faces that stand free in the room (furniture, boxes, people), stand
/// before a larger wall seen above them, or are too low for a picture are objects, not
/// projection surfaces (detection/default/face_surround.hpp); depth images only.
struct ObjectFaceConfig {
    bool avoid = true;  ///< skip faces that stand free; false takes any vertical face (the paper's behaviour)
    FaceSurroundOptions surround;
    FreeStandingRule rule;
    /// m: a face enclosed in front on every side and this far behind a parallel wall is seen
    /// through an opening in it (a window, a door), not a surface; a kitchen niche between
    /// cabinets is 0.3-0.6 m deep.
    double opening_depth = 0.8;  ///< [0.0001, 10] m, an enclosed face this far behind a wall is beyond an opening
};

/// Default method, stage 4 (`free_space`): where on a plane the camera saw free wall (paper 3.2.2).
/// Obstacle evidence over an area: what stands a centimetre or two proud of a wall (a picture
/// frame, a switch) lies within the band of a noisy sensor point by point, but the mean of the
/// readings over a few centimetres moves with it. The noise of such a mean is measured on the
/// wall itself (the spread of the window means over the raster), since a depth camera's error
/// is correlated over many pixels and quantised, so that the independent-noise standard error
/// would understate it.
struct ProudEvidence {
    bool enabled = true;  ///< cells whose readings stand off the wall's shape on average are not free
    double window =
        0.06;            ///< [0.0001, 10] m, side of the square the offsets are averaged over (a switch plate is 8 cm)
    int min_points = 8;  ///< [1, 100000] a window with fewer readings says nothing
    double spreads = 4.0;       ///< [0, 100] a window mean beyond this many robust spreads of the window means is proud
    double min_offset = 0.015;  ///< [0, 10] m, and beyond this (posters, whiteboards: a few mm, stay free)
    double min_extent = 0.10;   ///< [0, 10] m, proud areas narrower than this are dropped (a few windows: the sensor's)
};

/// A depth step along the wall (a picture frame's or a TV's border): the mean offset from the
/// wall's shape jumps between two strips side by side, beyond what the wall's own bend and the
/// sensor's correlated error make such jumps over the wall (detection/default/step_edges).
struct StepEvidence {
    bool enabled = true;  ///< cells where the wall's readings step along a line (a frame's border) are not free
    double width =
        0.05;  ///< [0.0001, 10] m, width of each strip either side of the edge (our choice: about a frame's border)
    double length =
        0.20;  ///< [0.0001, 10] m, strips' length along the edge (half the suite's smallest frame side, 40 cm)
    int min_points = 16;  ///< [1, 100000] a strip with fewer readings says nothing
    double spreads =
        6.0;  ///< [0, 100] a step beyond this many robust spreads of the wall's steps is an edge (docs/tuning.md)
    double min_step = 0.02;  ///< [0, 10] m, and beyond this (docs/tuning.md; posters, whiteboards: a few mm, stay free)
};

struct FreeSpaceConfig {
    double cell = 0.01;  ///< [0.002, 0.5] m, raster cell (docs/tuning.md)
    int stride = 2;  ///< [1, 64] pixel step of the pass on organized clouds (3 lost 7 % of the area behind a person)
    bool exclude_other_surfaces = true;  ///< depth images: points clearly nearer another region's plane are no support
    int max_gap_cells = 8;  ///< [0, 1024] largest gap between wall samples closed, cells (sensor holes up to 8 cm)
    int min_blocked_neighbours =
        2;  ///< [0, 8] a blocked cell needs this many blocked cells in its 3x3: single cells are noise
    double image_margin =
        1.0 / 64;  ///< [0, 0.5] of the image width: margin around where a plane is seen (mixed pixels, grazing angles)
    double inlier_box_margin = 1.0 / 16;  ///< [0, 0.5] of the image width, when the cloud has no fitted intrinsics
    ProudEvidence proud;                  ///< what stands off the wall's shape on average over a window
    StepEvidence steps;                   ///< where the wall's readings step along a line
};

/// Default method, stage 4 (`surface_check`): the surface check on the rectangle (paper 3.2.3).
struct SurfaceCheckConfig {
    double max_outlier_fraction =
        0.03;  ///< [0, 1] share of checked points off the wall that rejects an area (docs/tuning.md)
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

struct SuitabilityOptions {
    double context = 0.05;  ///< [0, 10] m, the wall judged beyond the raster on each side, so that a thing reaching
                            ///< into it is judged with the rest of it (colour suite; docs/tuning.md)
    double weak_contrast = 0.12;   ///< [0, 100] window contrast above which cells near wide texture are textured too
                                   ///< (hysteresis; colour suite, docs/tuning.md) ...
    double weak_over_wall = 8.0;   ///< [0, 100] ... and above this many times the wall's median contrast (labelled real
                                   ///< frames, docs/tuning.md)
    double texture_growth = 0.05;  ///< [0, 10] m, how far from wide texture the weak cells may join it (colour suite,
                                   ///< docs/tuning.md)
    double window =
        0.05;  ///< [0.0001, 10] m, side of the square on the wall texture and glare are judged over (5 cells at 1 cm)
    double tone_window = 0.03;  ///< [0.0001, 10] m, the square darkness and saturation are judged over (3 cells: a dark
                                ///< panel's edge to a cell)
    double dark_relative = 0.45;  ///< [0, 1] darker than this share of the wall's median luminance: too dark (measured,
                                  ///< docs/suitability.md)
    double dark_min =
        0.06;  ///< [0, 1] luminance share below which a surface is too dark whatever the wall (near black)
    double max_chroma =
        0.40;  ///< [0, 1] mean (max - min channel) / 255 above this: too saturated (measured, docs/suitability.md)
    double max_contrast =
        0.20;  ///< [0, 100] luminance std / mean over the window above this: textured (measured, docs/suitability.md)
    double glare_level = 0.98;     ///< (0, 1] a sample whose brightest channel reaches this share of 255 is blown out
    double max_glare_share = 0.1;  ///< [0, 1] more blown-out samples than this share of the window: glare (specular,
                                   ///< emissive; one column of 5)
    double glare_wall_share =
        0.85;          ///< [0, 1] no glare on a wall whose median luminance reaches this share of glare_level
                       ///< (the camera clipped the wall itself; labelled real frames, docs/tuning.md)
    int row_step = 1;  ///< [1, 64] every this many rows of the point grid are sampled (colour suite, docs/tuning.md)
    int min_tone_samples = 8;  ///< [1, 2^24] fewer in the tone window: tone is judged over the window (fewer let a
                               ///< plain wall's chroma noise cross max_chroma; docs/tuning.md)
    int min_samples = 3;       ///< [1, 2^24] fewer wall samples in the window: colour decides nothing there
    int trim_cells = 2;  ///< [0, 64] textured and glare cells given back on an unfit area's rim (the window reaches 2
                         ///< cells beyond an edge)
    double max_hole = 0.25;        ///< [0, 100] m^2, fit areas enclosed by unfit cells up to this size are unfit too (a
                                   ///< picture's plain mat)
    double min_unfit_area = 0.01;  ///< [0, 100] m^2, smaller unfit areas are fit (a light switch plate, 8 x 8 cm;
                                   ///< docs/tuning.md)
    double min_texture_width = 0.05;  ///< [0, 10] m, textured areas narrower than this are fit (a door seam, a cable;
                                      ///< docs/tuning.md)
};

/// Whether colour given with a cloud is pixel-registered to it, before the colour is used
/// (detection/colour/colour_registration.hpp; the rows of docs/tuning.md).
struct RegistrationOptions {
    int max_shift_px = 20;     ///< [1, 64] px, shifts tried in x and y (unregistered pairs are 10-20 px off; docs/tuning.md)
    double depth_jump = 0.04;  ///< [0, 10] m, a depth edge: the depth changes by more than this ...
    double depth_jump_share = 0.03;  ///< [0, 1] ... and by more than this share of the depth, across 2 px
    double jump_over_slope =
        3.0;  ///< [0, 100] ... and is this many times steeper than the surface beside it (a grazing floor is no edge)
    int min_edge_pixels = 150;  ///< [1, 2^24] fewer depth-edge pixels: the check cannot tell (docs/tuning.md)
    double min_prominence =
        1.05;  ///< [1, 100] the best score must exceed the median over all shifts by this factor, else it cannot tell
    int local_window_px =
        41;  ///< [1, 1001] px, colour edges are taken relative to their mean over this window (texture does not win)
    double min_zero_over_median =
        1.25;  ///< [0, 100] registered: the score at offset 0 over the median shift's (docs/tuning.md)
    double min_zero_over_best = 0.7;  ///< [0, 1] ... and at least this share of the best shift's (a shift along one edge
                                      ///< direction keeps the other's edges; docs/tuning.md)
    int max_samples = 6000;           ///< [1, 2^24] depth-edge pixels used at most (evenly spread), for speed
};

/// Default method, stage 4 (`suitability`): the surface's suitability from its colour, only when
/// the cloud carries colour (without colour it is off whatever the mode).
struct SuitabilityConfig {
    SuitabilityMode mode = SuitabilityMode::Avoid;  ///< with registered colour: ignore it, avoid unfit cells, or prefer
                                                    ///< a cleaner wall (docs/suitability.md)
    SuitabilityOptions cells;
    RegistrationOptions registration;  ///< whether the colour given with a cloud is registered to it, else not used
    double prefer_exponent = 2.0;  ///< [0, 100] k of prefer's rule (a 10 % unfit rectangle counts 81 % of its area)
};

struct DetectorConfig {
    Method method = Method::Default;  ///< the detection method; paper: the paper's steps, for reproduction
    double aspect = 0.0;              ///< [0, 100] picture width / height, or "W:H"; 0 = the projector framebuffer's
    double max_tilt = kVerticalTolerance;  ///< [0, 1.5] rad, plane normal vs horizontal (contract; paper 3.2.1)
    unsigned seed = 42;                    ///< [0, 2^32-1] RANSAC random seed (runs are deterministic)

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
