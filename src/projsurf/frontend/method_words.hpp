#pragma once
// The detection method and the paper method's hull as a user writes them (`detect --method
// --hull`, the node's ~method ~hull, Python's method= hull=, the config file's `method` and
// `paper.hull`), and their words back.
#include <string>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf::frontend {

/// "default" | "paper". Throws InputError(what, problem) for any other word.
Method parseMethod(const std::string &what, const std::string &word);
const char *methodName(Method method);

/// "concave" | "convex". Throws InputError(what, problem) for any other word.
HullKind parseHull(const std::string &what, const std::string &word);
const char *hullName(HullKind hull);

}  // namespace projsurf::frontend
