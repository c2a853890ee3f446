#pragma once
// Simulated calibration captures (paper 3.1.1): the calibration picture (black, one white disc)
// projected on a plain wall from several robot positions, as the RGB-D camera sees it.
#include <vector>

#include "projsurf/core/calibration.hpp"
#include "projsurf/core/projector.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::sim {

/// `count` captures of the plain "wall" scenario with the disc projected by `projector`:
/// capture k is taken from 1.2 m (k = 0) to 3.0 m (k = count - 1), evenly spaced, turned by
/// 0, 10, -10, 20, -20 degrees (repeating), the camera pitched by `pitch_deg` then rolled by
/// `roll_deg` (pitchCamera, rollCamera); noise seed seed + 1000 + k. Throws
/// std::invalid_argument for count < 1.
std::vector<RgbdFrame> renderCalibrationCaptures(const Projector &projector, const SensorModel &sensor, int count,
                                                 unsigned seed, double roll_deg = 0.0, double pitch_deg = 0.0);

/// The colour and depth images of rendered captures, as calibrateProjector takes them.
std::vector<CaptureImages> captureImages(const std::vector<RgbdFrame> &frames);

}  // namespace projsurf::sim
