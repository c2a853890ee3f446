#pragma once
// Where the readings on a wall step along a line: the border of a picture frame or a TV a few
// cm proud, inside the band of a sensor whose error at that depth is as large, but sharp where
// the wall's bend and the sensor's distortion are smooth over tens of centimetres.
#include <opencv2/core.hpp>

#include "projsurf/detection/default/plane_observation.hpp"
#include "projsurf/detection/detector_config.hpp"

namespace projsurf {

/// The cells (255) on a step of the readings' mean offset from the wall's shape: between two
/// strips `steps.width` wide and `steps.length` long side by side (rows and columns), the jump
/// of their means less the slope their outer neighbours show; beyond `steps.spreads` robust
/// spreads of such jumps over the raster and `steps.min_step`. `cell`: the raster's cell (m).
/// Empty when the observation has no offsets or the evidence is off.
cv::Mat stepEdgeCells(const PlaneObservation &observation, const StepEvidence &steps, double cell);

}  // namespace projsurf
