#pragma once
// The demo's planned move: where the robot should stand for a bigger picture, the
// scene seen again from there, detected and corrected, and what an audience then sees.
#include <opencv2/core.hpp>

#include "projsurf/planning/stand_planner.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

struct PlanShot {
    PlanResult plan;     ///< planned on the first frame, with the believed projector
    Detection after;     ///< detected from the moved robot (moved camera frame)
    cv::Mat view_after;  ///< the corrected picture from there, seen by the audience (BGR)
};

/// Plans on `cloud`, moves the robot (its camera and the true projector with it), renders and
/// detects there, corrects `picture` and renders the audience's view from `viewer` (today's
/// camera frame, as the demo's other views). `view_after` is empty when nothing was found.
PlanShot planShot(const sim::Scenario &scenario, const Projector &real, const Projector &believed, const Cloud &cloud,
                  const DetectorConfig &config, const cv::Mat &picture, const sim::PinholeView &viewer,
                  const sim::Lighting &light, unsigned seed);

}  // namespace projsurf::eval
