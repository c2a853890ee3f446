#pragma once
// The CLI's and Python's warning for a setting the chosen method does not use
// (frontend/settings/ignored_settings.hpp), for the node's parameters: "~max_planes is ignored by the
// paper method", logged once when the node starts.
#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf::ros_node {

/// A parameter the user gave: set, and not the empty string (the launch file passes its
/// unset arguments as "").
bool paramGiven(const ros::NodeHandle &pnh, const std::string &key);

/// The warning texts for the parameters `method` ignores that were given on `pnh`.
std::vector<std::string> ignoredParamWarnings(const ros::NodeHandle &pnh, Method method);

}  // namespace projsurf::ros_node
