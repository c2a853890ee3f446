#include "eval/demo/plan_demo.hpp"

#include "projsurf/keystone/keystone.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on

PlanShot planShot(const Scenario &scenario, const Projector &real, const Projector &believed, const Cloud &cloud,
                  const DetectorConfig &config, const cv::Mat &picture, const PinholeView &viewer,
                  const Lighting &light, unsigned seed) {
    PlanShot shot;
    shot.plan = planStand(cloud, believed, config, scenario.gravity);
    if (!shot.plan.found) return shot;
    Eigen::Isometry3d today_from_moved = Eigen::Isometry3d::Identity();
    today_from_moved.linear() = shot.plan.rotation;
    today_from_moved.translation() = shot.plan.translation;
    const Scene moved = transformed(scenario.scene, today_from_moved.inverse());
    const RgbdFrame frame = renderFrame(moved, SensorModel(), seed + 2000);
    shot.after = detectSurface(frame.cloud, believed, config, shot.plan.rotation.transpose() * scenario.gravity);
    if (!shot.after.found) return shot;
    const KeystoneResult k = computeKeystone(believed, shot.after.rectangle, picture.size());
    if (!k.keystone) return shot;
    const cv::Mat fb = warpToFramebuffer(picture, *k.keystone);
    // The true projector carried by the moved robot, in today's camera frame (a turn about
    // gravity keeps a level projector's roll zero).
    Projector carried = real;
    carried.origin = today_from_moved * real.origin;
    carried.direction = shot.plan.rotation * real.direction;
    shot.view_after = renderView(scenario.scene, viewer, Projection{carried, fb}, light);
    return shot;
}

}  // namespace projsurf::eval
