#include "ignored_params.hpp"

#include "projsurf/frontend/settings/ignored_settings.hpp"

namespace projsurf::ros_node {

bool paramGiven(const ros::NodeHandle &pnh, const std::string &key) {
    std::string text;
    return pnh.hasParam(key) && !(pnh.getParam(key, text) && text.empty());
}

std::vector<std::string> ignoredParamWarnings(const ros::NodeHandle &pnh, Method method) {
    return frontend::ignoredSettingWarnings(
        method, [&](const std::string &setting) { return paramGiven(pnh, setting); },
        [](const std::string &setting) { return "~" + setting; });
}

}  // namespace projsurf::ros_node
