#pragma once
// Which of the detector's settings a method does not use, by the names the front ends share
// (the CLI writes them as --max-planes, Python as max_planes=, the node as ~max_planes): a
// setting given for a method that ignores it is warned about, once, by every front end.
#include <string>
#include <vector>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf::frontend {

/// The settings `method` ignores, in snake_case: the paper method's own (hull, voxel_leaf,
/// ransac_distance, max_outliers) for the default method, the default method's own (cell,
/// max_planes, max_outlier_fraction, suitability) for the paper method.
std::vector<std::string> settingsIgnoredBy(Method method);

/// "max_planes" -> "--max-planes".
std::string optionName(const std::string &setting);

}  // namespace projsurf::frontend
