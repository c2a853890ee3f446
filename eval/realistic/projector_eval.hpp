#pragma once
// The eval table of real projectors: simulated real projectors (sim/projector_rigs.hpp) calibrated by
// the paper's disc method and by structured light, each scored against the true projector:
// reprojection error over points at 1-4 m, origin error, and end to end (detection on a noisy
// cloud of a wall at 2 m, keystone with the estimate, picture cast with the true projector):
// eq. 8 error, corner placement and uprightness.
#include <string>
#include <vector>

#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/sensor_model.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::eval {

struct CalibrationScore {
    bool ok = false;
    std::string problem;
    double rms_px = 0, worst_px = 0;  ///< believed.toPixel vs the true pixel, points at 1-4 m
    double origin_mm = 0;
    double eq8_pct = 0;      ///< worst of the eq. 8 errors of the landed picture
    double corner_mm = 0;    ///< farthest landed corner from the detected rectangle's, wall at 2 m
    double upright_deg = 0;  ///< landed left/right edges vs the wall's vertical, worst
};

/// Scores `believed` against `truth` (end to end on the "wall" scenario at 2 m, 20 deg).
CalibrationScore scoreCalibration(const Projector &believed, const Projector &truth, const sim::SensorModel &sensor,
                                  unsigned seed);

struct ProjectorEvalRow {
    sim::RigSpec rig;
    std::string sl_poses;  ///< "3 flat" or "1 relief"
    CalibrationScore disc, structured;
    double seconds = 0;
};

/// Every rig of evalRigs() with three flat poses, and one rig from a single relief pose.
std::vector<ProjectorEvalRow> runProjectorEval(unsigned seed, bool quick);
std::string projectorEvalMarkdown(const std::vector<ProjectorEvalRow> &rows);
/// One line: the structured-light worst values against the targets.
std::string projectorEvalSummary(const std::vector<ProjectorEvalRow> &rows);

}  // namespace projsurf::eval
