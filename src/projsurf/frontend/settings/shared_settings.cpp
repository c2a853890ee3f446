#include "projsurf/frontend/settings/shared_settings.hpp"

#include <stdexcept>

namespace projsurf::frontend {

const std::vector<std::string> &sharedNumberSettings() {
    static const std::vector<std::string> names = {"max_tilt",     "seed", "voxel_leaf", "ransac_distance",
                                                   "max_outliers", "cell", "max_planes", "max_outlier_fraction"};
    return names;
}

const ConfigKey &sharedSettingKey(const std::string &setting) {
    const ConfigKey *key = findConfigKey(configKeyOfSetting(setting));
    if (!key) throw std::logic_error("no shared setting '" + setting + "'");
    return *key;
}

void setSharedSetting(DetectorConfig &config, const std::string &setting, const std::string &text,
                      const std::string &what) {
    SettingText value;
    value.key = setting;
    value.items = {text};
    setConfigValue(config, sharedSettingKey(setting), value, what);
}

std::string sharedSettingHelp(const std::string &setting) {
    const ConfigKey &key = sharedSettingKey(setting);
    return key.doc + "; " + keyRangeText(key);
}

}  // namespace projsurf::frontend
