#include "projsurf/sim/depth_sensor.hpp"

#include <cmath>
#include <limits>

namespace projsurf::sim {

std::string sensorName(SensorKind kind) {
    switch (kind) {
    case SensorKind::Kinect1: return "kinect1";
    case SensorKind::Tof: return "tof";
    case SensorKind::D435: return "d435";
    }
    return "?";
}

std::optional<SensorKind> parseSensorKind(const std::string &name) {
    for (SensorKind k : sensorKinds())
        if (sensorName(k) == name) return k;
    return std::nullopt;
}

const std::vector<SensorKind> &sensorKinds() {
    static const std::vector<SensorKind> kinds{SensorKind::Kinect1, SensorKind::Tof, SensorKind::D435};
    return kinds;
}

const CameraIntrinsics &DepthSensor::camera() const {
    switch (kind) {
    case SensorKind::Tof: return tof.camera;
    case SensorKind::D435: return d435.camera;
    default: return kinect1.base.camera;
    }
}

SensorModel DepthSensor::truthModel() const {
    SensorModel s = kinect1.base;
    s.camera = camera();
    if (kind == SensorKind::Tof) {
        s.min_depth = tof.min_depth;
        s.max_depth = tof.max_depth;
        s.grazing_max_deg = tof.grazing_max_deg;
        s.ir_shadow = false;
    } else if (kind == SensorKind::D435) {
        s.min_depth = d435.min_depth;
        s.max_depth = d435.max_depth;
        s.grazing_max_deg = d435.grazing_max_deg;
        s.ir_shadow = false;
    }
    return s;
}

DepthSensor makeDepthSensor(SensorKind kind, int unit) {
    DepthSensor s;
    s.kind = kind;
    s.unit = unit;
    switch (kind) {
    case SensorKind::Kinect1: s.kinect1_unit = std::make_shared<Kinect1Unit>(makeKinect1Unit(s.kinect1, unit)); break;
    case SensorKind::Tof: s.tof_unit = std::make_shared<TofUnit>(makeTofUnit(s.tof, unit)); break;
    case SensorKind::D435: s.d435_unit = std::make_shared<D435Unit>(makeD435Unit(s.d435, unit)); break;
    }
    return s;
}

cv::Mat measureDepth(const Scene &scene, const ExactDepth &exact, const DepthSensor &s, unsigned seed,
                     const cv::Mat &tof_multipath) {
    switch (s.kind) {
    case SensorKind::Tof: return measureTof(scene, exact, s.tof, *s.tof_unit, seed, tof_multipath);
    case SensorKind::D435: return measureD435(scene, exact, s.d435, *s.d435_unit, seed);
    default: return measureKinect1(scene, exact, s.kinect1, *s.kinect1_unit, seed);
    }
}

void fillFrameDepth(const cv::Mat &depth_m, const CameraIntrinsics &cam, RgbdFrame &f) {
    f.depth = cv::Mat(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    f.cloud.width = cam.width;
    f.cloud.height = cam.height;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    f.cloud.points.assign(static_cast<std::size_t>(cam.width) * cam.height, Point(nan, nan, nan));
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            const double z = depth_m.at<double>(v, u);
            if (!(z > 0.0)) continue;
            const double units = std::round(z * cam.depth_scale);
            if (units < 1.0 || units > 65535.0) continue;
            // The cloud holds what the depth image holds (what a user reading depth.png gets).
            const double zq = units / cam.depth_scale;
            f.depth.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(units);
            f.cloud.points[static_cast<std::size_t>(v) * cam.width + u] = cam.backProject(u, v, zq).cast<float>();
        }
}

RgbdFrame renderSensorFrame(const Scene &scene, const DepthSensor &sensor, unsigned seed,
                            const std::optional<Projection> &projection, bool colour) {
    const CameraIntrinsics &cam = sensor.camera();
    const ExactDepth exact = castExactDepth(scene, cam);
    RgbdFrame f;
    if (colour) {
        SensorModel flat = SensorModel::ideal();
        flat.camera = cam;
        f = renderFrame(scene, flat, seed, projection);
    } else {
        f.rgb = cv::Mat(cam.height, cam.width, CV_8UC3, cv::Scalar(0, 0, 0));
    }
    f.quad = exact.quad.clone();
    fillFrameDepth(measureDepth(scene, exact, sensor, seed), cam, f);
    return f;
}

}  // namespace projsurf::sim
