#pragma once
// A Kinect v1 class RGB-D sensor: registered depth + colour pinhole, axial depth noise that
// grows with the square of the distance, disparity quantisation, and missing readings.
//
// Sources:
//  - Noise: Khoshelham & Oude Elberink, "Accuracy and Resolution of Kinect Depth Data for
//    Indoor Mapping Applications", Sensors 12(2):1437-1454, 2012, doi 10.3390/s120201437:
//    sigma_z = (m / (f b)) z^2 sigma_d' ~= 1.425e-3 z^2 m (1.4 mm at 1 m, 12.8 mm at 3 m).
//  - Quantisation: the OpenKinect / ROS raw-disparity fit z = 1 / (3.3309495161 -
//    0.0030711016 raw), i.e. 1/z moves in steps of 3.0711e-3 1/m (dz ~= 3.07e-3 z^2).
//  - Range and dropouts: readings from about 0.5 m to 4-5 m (K&OE 2012 use 0.5-5 m; Microsoft
//    specifies 0.8-4 m); invalid pixels at grazing angles and in the IR emitter's shadow
//    beside depth edges (7.5 cm emitter-camera baseline, K&OE 2012).
//  - Ragged depth edges: Nguyen, Izadi & Lovell, "Modeling Kinect Sensor Noise for Improved
//    3D Reconstruction and Tracking", 3DIMPVT 2012 (lateral sigma ~0.8 px).
#include <Eigen/Core>

#include "projsurf/types/camera.hpp"

namespace projsurf::sim {

struct SensorModel {
    CameraIntrinsics camera;  ///< Kinect v1 VGA, depth registered to colour (types/camera.hpp defaults)

    bool noise = true;                         ///< add axial depth noise (and colour noise)
    double noise_k = 1.425e-3;                 ///< 1/m: total sigma_z = k z^2 (K&OE 2012), quantisation included
    bool quantize = true;                      ///< quantise 1/z like the Kinect's 11-bit raw disparity
    double disparity_step = 3.0711016e-3;      ///< 1/m per raw step (OpenKinect fit)
    double disparity_offset = 3.3309495161;    ///< 1/m, 1/z at raw = 0 (OpenKinect fit)
    double min_depth = 0.5;                    ///< m, nearer readings are missing (K&OE 2012: 0.5 m)
    double max_depth = 4.5;                    ///< m, farther readings are missing (our choice within 4-5 m)
    double grazing_start_deg = 70.0;           ///< ray-normal angle where readings start to drop out
    double grazing_max_deg = 80.0;             ///< beyond this angle no reading (hard cut when !noise)
    bool ir_shadow = true;                     ///< no reading where the IR emitter's pattern cannot reach
    Eigen::Vector3d emitter{0.075, 0.0, 0.0};  ///< m, IR emitter position (camera frame, K&OE baseline)
    double rgb_noise = 2.0;                    ///< grey levels, sigma of colour noise when `noise`
    /// px, sigma of where a depth edge lands (Nguyen, Izadi & Lovell 2012: lateral noise
    /// 0.8 px at moderate angles); beside a depth jump a reading may come from the other
    /// side. Applied only when `noise`; 0 turns it off.
    double edge_jitter_px = 0.8;
    double edge_jump = 0.03;  ///< m, depth difference that counts as a depth edge

    /// Noise-free, unquantised, no random or IR-shadow dropouts: exact geometry, for tests.
    /// Range limits and the hard grazing-angle cut stay.
    static SensorModel ideal();

    /// Total standard deviation of a depth reading at depth z (m): noise_k z^2 when noisy.
    double depthSigma(double z) const { return noise ? noise_k * z * z : 0.0; }
    /// Depth step between neighbouring quantised readings at depth z (m).
    double quantumAt(double z) const { return quantize ? disparity_step * z * z : 0.0; }
    /// Probability that a reading at ray-normal angle `angle_deg` is missing.
    double dropoutProbability(double angle_deg) const;
    /// Sigma (1/m) of the noise added to inverse depth before quantisation, chosen so that
    /// noise + quantisation together give depthSigma(z).
    double inverseDepthSigma() const;
    /// A simulated reading of true depth z (m), given one standard-normal sample: the noise
    /// is added to inverse depth (the Kinect measures disparity), then 1/z is quantised.
    /// Returns 0 when the reading falls outside the range.
    double measure(double z, double standard_normal) const;
};

}  // namespace projsurf::sim
