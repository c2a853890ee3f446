#pragma once
// The demo's real projector: a projector whose lens throws the picture above its
// axis (100 % vertical offset) and is mounted with 1 deg of roll, calibrated by the paper's
// disc method and by structured light, each used to detect and correct the same picture, and
// the picture as an audience facing the wall sees it through the true projector.
#include <opencv2/core.hpp>
#include <string>

#include "eval/paper/experiments.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::eval {

/// One calibration of the rig, used end to end.
struct LensOffsetShot {
    bool ok = false;
    std::string problem;  ///< why there is no picture (calibration failed, nothing found, ...)
    Projector believed;   ///< the calibrated projector
    Detection detection;  ///< with `believed`
    WallPicture on_wall;  ///< where the corrected picture lands through the true projector (eq. 8)
    cv::Mat audience;     ///< what the audience sees
};

struct LensOffsetDemo {
    sim::RigSpec rig{1.0, 1.0, 1.0, 0.0};  ///< 100 % offset (spec sheets: 100-133 %), 1 deg roll
    Projector truth;
    LensOffsetShot disc;        ///< paper 3.1, given the projector's true field of view
    LensOffsetShot structured;  ///< Gray code through the depth camera, three poses at a flat wall
};

/// Runs both calibrations of the rig and shows `picture` with each on the scenario's wall,
/// seen from `viewer` under `light` (the main demo's audience view).
LensOffsetDemo runLensOffsetDemo(const sim::Scenario &scenario, const cv::Mat &picture, const sim::PinholeView &viewer,
                                 const sim::Lighting &light, unsigned seed);

}  // namespace projsurf::eval
