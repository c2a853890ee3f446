#pragma once
// Simulated real projectors : the paper's example projector given a lens offset,
// roll, unequal focal lengths and radial distortion, and what the paper's model of such a
// projector would be (the ray through the framebuffer centre, a symmetric field of view).
#include <string>
#include <vector>

#include "projsurf/types/projector.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/sim/calibration_captures.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::sim {

struct RigSpec {
    double offset = 0.0;    ///< vertical lens offset, fraction: cy = (H-1)/2 + offset H/2 (1.0 = 100 %)
    double roll_deg = 0.0;  ///< rotation about the optical axis, deg
    double fy_ratio = 1.0;  ///< fy over the example's fy (fx stays the example's)
    double k1 = 0.0;        ///< radial distortion (OpenCV k1)
    std::string name() const;
};

/// The example projector (scenarios.cpp: 1280x800, 39.3 deg, origin (0, 0.12, 0)) with the
/// full model of `spec`; the whole rig is tilted so that the ray through the framebuffer
/// centre stays the example's axis (the picture stays where it was, the lens points lower).
Projector projectorRig(const RigSpec &spec);

/// What the paper's model of `real` is: same origin and resolution, the axis through the
/// framebuffer centre, the field of view spanned by the framebuffer (symmetric, zero roll).
Projector paperModelOf(const Projector &real);

/// Structured-light calibration of `truth` from simulated captures at `poses` (rendered,
/// decoded, lifted through the simulated depth, fitted).
ProjectorFit structuredCalibration(const Projector &truth, const SensorModel &sensor,
                                   const std::vector<PatternPose> &poses, unsigned seed);
/// Poses for structured light: three positions in front of a plain wall (flat), or one
/// position where the picture falls on a big box standing against the wall (relief).
std::vector<PatternPose> flatWallPoses();
std::vector<PatternPose> reliefPose();

/// The rigs of the eval table: offsets 0-133 %, roll up to +-3 deg, fy/fx 1.005, k1 +-0.05.
std::vector<RigSpec> evalRigs();

}  // namespace projsurf::sim
