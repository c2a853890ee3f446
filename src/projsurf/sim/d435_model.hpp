#pragma once
// An active-stereo depth camera of the Intel RealSense D435 class, 848x480 (field notes section
// 8: Intel RealSense D400 series datasheet; Keselman et al. 2017, "Intel RealSense Stereoscopic
// Depth Cameras"):
//  - depth from disparity between two imagers 50 mm apart, referenced to the left one; 1/z is
//    quantised in steps of 1/32 px of disparity;
//  - RMS error growing with z^2, spatially correlated: a per-frame field correlated over the
//    matching window, a per-unit smooth field (calibration), a small independent part; the
//    total is `rms_at_2m` (Intel: <= 2 % of depth at 2 m);
//  - speckle holes (small blobs where matching fails), more on black and glossy surfaces;
//  - edges fattened: beside a foreground edge the background reads the foreground's depth over
//    a few pixels (the matching window straddles the edge);
//  - an invalid band beside near objects (left of them) and along the left image border:
//    what the right imager cannot see;
//  - glass: reads what is behind (mostly).
#include <opencv2/core.hpp>

#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/scenes/scene.hpp"

namespace projsurf::sim {

struct D435Model {
    /// 848x480 depth, 87 x 58 deg (datasheet); fx = fy = 424.7 px, the usual factory value at
    /// this resolution (librealsense reports 420-430 px).
    CameraIntrinsics camera{848, 480, 424.7, 424.7, 423.5, 239.5, 1000.0};
    double baseline = 0.050;  ///< m, left-right imager (datasheet)
    /// px, disparity quantisation step. Measured: the D435 frame in ../shared/data/real steps by
    /// 13.5 mm at 2.87 m, i.e. 1/32 px at its native 382 px focal length and 50 mm baseline.
    double subpixel = 1.0 / 32.0;
    double min_depth = 0.28;  ///< m, the datasheet's min-Z at full resolution (less at 848x480: conservative)
    double max_depth = 10.0;  ///< m (datasheet: ~10 m, accuracy falls with range)
    double grazing_max_deg =
        75.0;  ///< deg, no reading beyond this ray-normal angle (our choice: stereo matching fails)
    /// m, total RMS depth error at 2 m (0.65 % of depth; Intel's <= 2 % is a bound), growing
    /// with z^2: set so that the median plane RMS of 24 px windows meets the D435 frame in
    /// ../shared/data/real per depth band (tests/sim/test_sensor_models.cpp).
    double rms_at_2m = 0.013;
    // The split of that error and the size of the other effects: our choices, with the
    // shares set so that the bedroom frame's local noise is met (tests/sim/test_sensor_models.cpp).
    double share_correlated = 0.45;  ///< variance share of the per-frame correlated field
    double share_unit = 0.45;        ///< variance share of the per-unit smooth field
    /// The rest (1 - the two shares) is independent per pixel.
    double correlated_sigma_px = 4.0;   ///< px, correlation of the per-frame field (about a 7-9 px matching window)
    double unit_cell_px = 200.0;        ///< px, feature size of the per-unit field
    double speckle_share = 0.02;        ///< share of pixels in speckle holes
    double speckle_sigma_px = 1.2;      ///< px, hole blob size
    double black_speckle_share = 0.5;   ///< share of holes on black surfaces (the projector's dots hardly show)
    double glossy_speckle_share = 0.6;  ///< share of holes on glossy surfaces (the dots are mirrored away)
    double glass_through = 0.8;         ///< probability of reading through glass, else nothing
    int fatten_px = 3;                  ///< px, edge fattening horizontally (1 px vertically)
    double edge_jump = 0.05;            ///< m, depth difference that makes a depth edge
};

struct D435Unit {
    int unit = 0;
    cv::Mat field;  ///< CV_32F, unit RMS, the per-unit smooth error pattern
};
D435Unit makeD435Unit(const D435Model &model, int unit);

/// Depth readings (CV_64F, m, 0 = none), per-frame noise from `seed`.
cv::Mat measureD435(const Scene &scene, const ExactDepth &exact, const D435Model &model, const D435Unit &unit,
                    unsigned seed);

}  // namespace projsurf::sim
