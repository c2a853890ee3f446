#pragma once
// The colour suitability mode as a user writes it (`detect --suitability`, the node's
// ~suitability): "off", "avoid" or "prefer" (docs/suitability.md); its word back is
// suitabilityModeName (detection/detector_config.hpp).
#include <string>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf::frontend {

/// "off" | "avoid" | "prefer"; "" is avoid (the default when registered colour is given).
/// Throws InputError(what, problem) for any other word.
SuitabilityMode parseSuitabilityMode(const std::string &what, const std::string &word);

}  // namespace projsurf::frontend
