#pragma once
// A detection in one line for a person: what `detect --json` prints and the node's ~detect answers.
#include <string>

#include "projsurf/detection/detection.hpp"

namespace projsurf::frontend {

/// "found 1.34 x 0.84 m (1.13 m^2) on a plane 2.00 m away at 0.0 deg in 2.1 ms", or
/// "not found: <reason>" ("not found: no projection surface found" without one).
std::string detectionSummary(const Detection &det);

}  // namespace projsurf::frontend
