#include "projsurf/sim/projector_rigs.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "projsurf/calibration/decoded_points.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::sim {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
}

std::string RigSpec::name() const {
    char buf[120];
    std::snprintf(buf, sizeof buf, "offset %3.0f%% roll %+.1f fy x%.3f k1 %+.2f", offset * 100, roll_deg, fy_ratio, k1);
    return buf;
}

Projector projectorRig(const RigSpec &spec) {
    const Projector base = exampleProjector();
    Projector p = base;
    ProjectorIntrinsics in;
    in.fx = base.fx();
    in.fy = base.fy() * spec.fy_ratio;
    in.cx = base.cx();
    in.cy = base.cy() + spec.offset * 0.5 * base.height;
    p.intrinsics = in;
    p.distortion = {spec.k1, 0, 0, 0, 0};
    // Axes of the example (zero roll), then: roll about the axis, and tilt about image right so
    // that the centre pixel's ray is the example's axis.
    Eigen::Matrix3d r;
    r << base.right(), base.down(), base.axis();
    const Eigen::Matrix3d roll(Eigen::AngleAxisd(spec.roll_deg * kDeg, Eigen::Vector3d::UnitZ()));
    p.setRotation(r * roll);
    const Eigen::Vector3d centre_ray = p.ray({base.cx(), base.cy()});
    const Eigen::Quaterniond tilt = Eigen::Quaterniond::FromTwoVectors(centre_ray, base.axis());
    p.setRotation(tilt.toRotationMatrix() * *p.rotation);
    return p;
}

Projector paperModelOf(const Projector &real) {
    Projector p;
    p.width = real.width;
    p.height = real.height;
    p.origin = real.origin;
    p.direction = real.ray({0.5 * (real.width - 1), 0.5 * (real.height - 1)});
    const auto fov = fieldOfView(real);
    p.fov_h = fov[0];
    p.fov_v = fov[1];
    return p;
}

ProjectorFit structuredCalibration(const Projector &truth, const SensorModel &sensor,
                                   const std::vector<PatternPose> &poses, unsigned seed) {
    const auto captures = renderPatternCaptures(truth, sensor, poses, seed);
    std::vector<ProjectorCorrespondence> pairs;
    for (const auto &cap : captures) {
        const GrayDecoding d = decodeGray(cap.colour, truth.width, truth.height);
        const auto lifted = liftDecoding(d, cap.depth, sensor.camera);
        pairs.insert(pairs.end(), lifted.begin(), lifted.end());
    }
    ProjectorFitConfig cfg;
    cfg.width = truth.width;
    cfg.height = truth.height;
    return fitProjector(pairs, cfg);
}

std::vector<PatternPose> flatWallPoses() {
    return {{"wall", 1.5, 0.0, 0.0, 0.0}, {"wall", 2.3, 20.0, 0.0, 0.0}, {"wall", 3.0, -15.0, 0.0, 0.0}};
}

std::vector<PatternPose> reliefPose() { return {{"big_obstacle", 1.6, 0.0, 8.0, 0.0}}; }

std::vector<RigSpec> evalRigs() {
    return {{0.0, 0.0, 1.0, 0.0},  {1.0, 0.0, 1.0, 0.0},   {1.33, 0.0, 1.0, 0.0},
            {1.0, 1.0, 1.0, 0.0},  {1.0, -3.0, 1.0, 0.0},  {1.0, 0.0, 1.005, 0.0},
            {1.0, 0.0, 1.0, 0.05}, {1.0, 0.0, 1.0, -0.05}, {1.33, 3.0, 1.005, -0.05}};
}

}  // namespace projsurf::sim
