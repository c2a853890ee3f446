#pragma once
// Continuous mode's words beside a detection, for the front ends that report each frame
// (`detect --bag --steady`'s lines, Python's Tracker.update): what is shown and what happened.
#include <nlohmann/json.hpp>

#include "projsurf/tracking/continuous_tracker.hpp"

namespace projsurf::frontend {

/// Adds to a frame's detection document `shown` (the rectangle to show, camera frame, as the
/// contract writes `rectangle`; null when nothing is held) and `event` (SteadyEvent's word:
/// none, acquired, kept, moved, switched, held, lost).
void addContinuousFrame(nlohmann::json &document, const ContinuousFrame &frame);

}  // namespace projsurf::frontend
