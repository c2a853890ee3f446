#pragma once
// The warning every front end gives for a setting the chosen method does not use
// (method_settings.hpp): "--max-planes is ignored by the paper method" (the CLI),
// "max_planes is ..." (Python), "~max_planes is ..." (the node): one sentence, each front end
// naming the setting as its users write it.
#include <functional>
#include <string>
#include <vector>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf::frontend {

/// "<name> is ignored by the <method> method" for each setting settingsIgnoredBy(method) names
/// that `given` says the user gave; `spell` turns the setting's snake_case name into the front
/// end's (optionName for the CLI).
std::vector<std::string> ignoredSettingWarnings(Method method, const std::function<bool(const std::string &)> &given,
                                                const std::function<std::string(const std::string &)> &spell);

}  // namespace projsurf::frontend
