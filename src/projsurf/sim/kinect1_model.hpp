#pragma once
// A realistic Kinect v1 / Xtion class structured-light sensor, 640x480: the independent noise
// of SensorModel (Khoshelham & Oude Elberink 2012, disparity quantisation, grazing dropouts,
// IR-emitter shadow, ragged edges) PLUS the errors real units have that are fixed per unit and
// correlated in space (field notes sections 5 and 8):
//  - a smooth low-frequency distortion of inverse depth (so growing with z^2 in depth), larger
//    towards the image border (Smisek, Bajcsy & Pajdla 2011; Herrera, Kannala & Heikkila 2012;
//    Teichman, Miller & Thrun 2013 "CLAMS": +-1-2 cm at 2 m, +-3-5 cm at 3 m at the border);
//  - a depth-scale error of a few tenths of a percent (same sources);
//  - vertical banding of a few mm (Smisek 2011);
//  - no readings on black, glossy (mostly) and glass (read through, or nothing) surfaces;
//  - flying pixels: some depth-edge pixels read a mix of both sides.
// The per-unit errors come from unitSeed("kinect1", unit, ...), never from the frame seed.
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::sim {

struct Kinect1Model {
    /// Camera (640x480, types/camera.hpp defaults), K&OE noise, quantisation, range, grazing
    /// dropouts, IR emitter shadow and ragged edges, as in the independent-noise model.
    SensorModel base;
    /// 1/m, RMS over the image of the low-frequency inverse-depth distortion: depth RMS =
    /// k z^2 (12 mm at 2 m, 26 mm at 3 m). Chosen so that the classroom frame's wall statistic
    /// (sim/wall_residual_stats.hpp over its top 130 rows: 19.0 mm RMS about the plane at
    /// 2.64 m, 10.3 mm local) is reproduced. Near the image border (r > 0.9 of the corner
    /// radius) its 95th percentile is then about 2.5 cm at 2 m and 5.6 cm at 3 m (median of
    /// units 0-11): the upper end of the literature's +-1-2 cm / +-3-5 cm, a little above it.
    double distortion_k = 2.9e-3;
    double distortion_cell_px =
        110.0;  ///< px, feature size of the distortion (our choice: a few smooth features across the image)
    /// The distortion's weight grows from the centre to the border as (1 - g) + g (r / r_corner)^2
    /// ("larger towards the image border", Smisek 2011).
    double distortion_border_growth = 0.6;
    double scale_error_sigma = 3e-3;  ///< relative, sigma of the per-unit depth-scale error (a few tenths of a percent)
    double banding_k = 5e-4;  ///< 1/m, RMS of the column bands in inverse depth: 2 mm at 2 m (Smisek 2011: a few mm)
    double banding_period_px = 10.0;  ///< px, width of the bands (our choice)
    // Our choices for the effects the field notes name without numbers:
    double flying_probability = 0.25;  ///< share of depth-edge pixels (within 1 px) that read a mix of both sides
    double glossy_dropout = 0.85;      ///< probability of no reading on a glossy surface
    double glass_through = 0.6;        ///< probability that a pixel on glass reads what is behind (else nothing)
    double black_dropout = 1.0;        ///< probability of no reading on a black surface
};

/// The systematic errors of one unit.
struct Kinect1Unit {
    int unit = 0;
    cv::Mat distortion;        ///< CV_32F, inverse-depth offset (1/m) per pixel, already scaled by distortion_k
    std::vector<float> bands;  ///< inverse-depth offset (1/m) per column
    double scale = 1.0;        ///< measured depth = scale * true depth (before noise)
};
Kinect1Unit makeKinect1Unit(const Kinect1Model &model, int unit);

/// Depth readings (CV_64F, m, 0 = none) of `exact` through this unit, per-frame noise from `seed`.
cv::Mat measureKinect1(const Scene &scene, const ExactDepth &exact, const Kinect1Model &model, const Kinect1Unit &unit,
                       unsigned seed);

}  // namespace projsurf::sim
