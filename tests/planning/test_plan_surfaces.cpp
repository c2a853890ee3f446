// Where a plan may put the picture (issue 41): only on surfaces detection does not refuse.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "projsurf/detection/default/default_method.hpp"
#include "projsurf/planning/floor_occupancy.hpp"
#include "projsurf/planning/plan_surfaces.hpp"
#include "projsurf/planning/stand_planner.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenarios.hpp"

using namespace projsurf;

namespace {

/// The distance of `p` to the plane of the scene's quad labelled `label` (the first one).
double offQuad(const sim::Scenario &sc, const std::string &label, const Eigen::Vector3d &p) {
    for (const auto &q : sc.scene.quads)
        if (q.label == label) return std::abs(q.normal().dot(p - q.corner));
    return 1e9;
}

}  // namespace

TEST(PlanSurfaces, FacesDetectionRefusesHoldNoPicture) {
    // Paper 4.3's big box standing free before the wall: detect names its front an object; the
    // plan's surfaces leave it out, and the plan's picture is on the wall.
    const sim::Scenario sc = sim::makeScenario("big_obstacle", 2.0, 0.0);
    const sim::RgbdFrame f = sim::renderFrame(sc.scene, sim::SensorModel{}, 3);
    DefaultScratch scratch;
    const SeenSurfaces seen = seeVerticalSurfaces(f.cloud, DetectorConfig{}, sc.gravity, 0.03, 5.5, scratch);
    int objects = 0;
    std::size_t usable = 0;
    for (const SeenSurface &s : seen.surfaces) {
        objects += s.object ? 1 : 0;
        usable += s.usable() && !s.free.empty() && cv::countNonZero(s.free) > 0 ? 1 : 0;
    }
    EXPECT_GE(objects, 1);
    const FloorOccupancy floor(f.cloud, sc.gravity, 2.5, 0.08);
    EXPECT_EQ(planSurfaces(f.cloud, seen, floor, {}).size(), usable);
    const PlanResult plan = planStand(f.cloud, sim::exampleProjector(), DetectorConfig{}, sc.gravity);
    ASSERT_TRUE(plan.found) << plan.reason;
    for (const auto &c : plan.predicted.corners) EXPECT_LT(offQuad(sc, "wall", c), 0.05) << c.transpose();
}
