#pragma once
// A time-of-flight depth camera of the Kinect v2 class, 512x424 (field notes section 8:
// Sarbolandi, Lefloch & Kolb 2015; Fuersattel et al. 2016):
//  - small noise, a few mm, growing with range and towards the image border (the emitter's
//    light falls off there);
//  - multipath: light that bounces off another surface first arrives late, so points near a
//    concave corner (wall-floor, wall-wall, a box against a wall) read too far, by a few cm;
//  - strong flying pixels: pixels on a depth edge mix both depths (anywhere in between);
//  - no reading on black (too little light back), glass and glossy surfaces (mostly);
//  - per unit: a depth offset and a "wiggling" error (periodic in range) of a few mm.
#include <opencv2/core.hpp>

#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/scenes/scene.hpp"

namespace projsurf::sim {

struct TofModel {
    /// Kinect v2 depth camera: 512x424, 70.6 x 60 deg; fx = fy = 365.5 px, typical factory values
    /// (libfreenect2 / iai_kinect2 calibrations report 364-366 px).
    CameraIntrinsics camera{512, 424, 365.5, 365.5, 255.5, 211.5, 1000.0};
    double min_depth = 0.5;          ///< m (Microsoft's Kinect v2 range: 0.5-4.5 m)
    double max_depth = 4.5;          ///< m (same)
    double grazing_max_deg = 80.0;   ///< deg, no reading beyond this ray-normal angle (our choice, as the Kinect v1's)
    double noise_base = 1.0e-3;      ///< m, sigma at range 0 (our choice for "a few mm", field notes 8)
    double noise_per_m = 1.0e-3;     ///< m per m of range: 2 mm at 1 m, 4 mm at 3 m at the centre (same)
    double noise_border_gain = 1.0;  ///< sigma grows by this factor (+100 %) from the centre to the corner (our choice)
    /// Scales the one-bounce indirect light (Lambertian form factors between scene points,
    /// 1 = physical), chosen so that a wall-wall corner at 2 m reads 1-6 cm too far within
    /// ~10 cm of the corner (Fuersattel 2016: "a few cm").
    double multipath_gain = 0.6;
    int multipath_cell_px = 8;  ///< px, grid of the indirect-light computation (cost vs detail; our choice)
    double modulation_wavelength =
        1.874;  ///< m of range per phase turn: c / (2 x 80 MHz), Kinect v2's highest modulation frequency
    // Our choices for the effects the field notes (section 8) name without numbers:
    double flying_probability = 0.9;  ///< share of depth-edge pixels that read a mix ("strong flying pixels")
    int flying_radius_px = 1;         ///< px either side of a depth edge
    double edge_jump = 0.03;          ///< m, depth difference that makes a depth edge (as SensorModel::edge_jump)
    double black_dropout = 0.95;      ///< probability of no reading on black (too little light comes back)
    double glossy_dropout = 0.7;  ///< probability of no reading on glossy surfaces (light mirrored away or saturating)
    double glass_through = 0.3;   ///< probability of reading through glass, else nothing
    double offset_sigma = 3e-3;   ///< m, sigma of the per-unit depth offset ("a few mm")
    double wiggle_amplitude = 3e-3;  ///< m, per-unit periodic error amplitude ("a few mm")
    double wiggle_period = 1.25;     ///< m of range
};

struct TofUnit {
    int unit = 0;
    double offset = 0.0;        ///< m
    double wiggle_phase = 0.0;  ///< rad
};
TofUnit makeTofUnit(const TofModel &model, int unit);

/// Range bias (m, positive = reads farther) from one-bounce multipath, per pixel (CV_64F).
cv::Mat multipathBias(const Scene &scene, const ExactDepth &exact, const TofModel &model);

/// Depth readings (CV_64F, m, 0 = none), per-frame noise from `seed`. `multipath`: the scene's
/// multipathBias when already known (it depends on the scene and the model only), else computed.
cv::Mat measureTof(const Scene &scene, const ExactDepth &exact, const TofModel &model, const TofUnit &unit,
                   unsigned seed, const cv::Mat &multipath = cv::Mat());

}  // namespace projsurf::sim
