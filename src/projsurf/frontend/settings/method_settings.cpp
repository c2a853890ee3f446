#include "projsurf/frontend/settings/method_settings.hpp"

#include <algorithm>

namespace projsurf::frontend {

std::vector<std::string> settingsIgnoredBy(Method method) {
    if (method == Method::Paper) return {"cell", "max_planes", "max_outlier_fraction", "suitability"};
    return {"hull", "voxel_leaf", "ransac_distance", "max_outliers"};
}

std::string optionName(const std::string &setting) {
    std::string out = "--" + setting;
    std::replace(out.begin(), out.end(), '_', '-');
    return out;
}

}  // namespace projsurf::frontend
