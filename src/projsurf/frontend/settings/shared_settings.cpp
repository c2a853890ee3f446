#include "projsurf/frontend/settings/shared_settings.hpp"

#include <stdexcept>
#include <variant>

namespace projsurf::frontend {

const std::vector<std::string> &sharedNumberSettings() {
    // The shared names whose key holds a plain number, in the table's order (the aspect's "W:H"
    // and the words aside): the one list is configKeyOfSetting()'s.
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const std::string &name : sharedSettingNames()) {
            // By the field the key reaches: the aspect's key is a double too, but written "W:H".
            const ConfigAccess &field = sharedSettingKey(name).access;
            if (std::holds_alternative<ConfigField<double>>(field) || std::holds_alternative<ConfigField<int>>(field) ||
                std::holds_alternative<ConfigField<unsigned>>(field))
                out.push_back(name);
        }
        return out;
    }();
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
