#pragma once
// The detection method and the paper method's hull as a user writes them (`detect --method
// --hull`, the node's ~method ~hull, Python's method= hull=, the config file's `method` and
// `paper.hull`). The words themselves, and their way back (methodName, hullName), are the
// detection's own table (detection/method_names.hpp).
#include <string>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/method_names.hpp"

namespace projsurf::frontend {

/// "default" | "paper". Throws InputError(what, problem) for any other word.
Method parseMethod(const std::string &what, const std::string &word);

/// "concave" | "convex". Throws InputError(what, problem) for any other word.
HullKind parseHull(const std::string &what, const std::string &word);

}  // namespace projsurf::frontend
