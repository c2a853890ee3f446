#pragma once
// The realistic depth sensors behind one interface: which kind (kinect1 | tof | d435), which
// unit (its fixed systematic errors, seeded by the unit number), and rendering a frame through
// it. The independent-noise SensorModel (sensor_model.hpp) stays what the paper experiments use.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "projsurf/sim/d435_model.hpp"
#include "projsurf/sim/kinect1_model.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/tof_model.hpp"

namespace projsurf::sim {

enum class SensorKind { Kinect1, Tof, D435 };

/// "kinect1", "tof", "d435".
std::string sensorName(SensorKind kind);
/// Nullopt for an unknown name.
std::optional<SensorKind> parseSensorKind(const std::string &name);
/// All kinds, in a stable order.
const std::vector<SensorKind> &sensorKinds();

/// One sensor unit with its models' default parameters and its systematic errors.
struct DepthSensor {
    SensorKind kind = SensorKind::Kinect1;
    int unit = 0;
    Kinect1Model kinect1;
    TofModel tof;
    D435Model d435;
    std::shared_ptr<const Kinect1Unit> kinect1_unit;  ///< set for Kinect1
    std::shared_ptr<const TofUnit> tof_unit;          ///< set for Tof
    std::shared_ptr<const D435Unit> d435_unit;        ///< set for D435

    const CameraIntrinsics &camera() const;
    /// The sensor's camera, range and grazing limit as a SensorModel, for computeGroundTruth
    /// (no IR-emitter requirement: shadowed wall is free wall, only unmeasured).
    SensorModel truthModel() const;
};

/// The default models of `kind`, with unit `unit`'s systematic errors.
DepthSensor makeDepthSensor(SensorKind kind, int unit);

/// Depth readings (CV_64F, m, 0 = none) of a scene's exact geometry through the sensor.
/// `tof_multipath`: for Tof, the scene's multipathBias if already computed (frames of one scene).
cv::Mat measureDepth(const Scene &scene, const ExactDepth &exact, const DepthSensor &sensor, unsigned seed,
                     const cv::Mat &tof_multipath = cv::Mat());

/// A full frame through the sensor: depth, cloud and quad from measureDepth; the colour image
/// (rendered noise-free at the same intrinsics, with the projection) only when `colour`.
RgbdFrame renderSensorFrame(const Scene &scene, const DepthSensor &sensor, unsigned seed,
                            const std::optional<Projection> &projection = std::nullopt, bool colour = true);

/// Depth (m, CV_64F) to the frame's depth image (depth_scale units, CV_16U) and cloud.
void fillFrameDepth(const cv::Mat &depth_m, const CameraIntrinsics &camera, RgbdFrame &frame);

}  // namespace projsurf::sim
