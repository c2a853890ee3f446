#include "projsurf/frontend/settings/ignored_settings.hpp"

#include "projsurf/detection/method_names.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"

namespace projsurf::frontend {

std::vector<std::string> ignoredSettingWarnings(Method method, const std::function<bool(const std::string &)> &given,
                                                const std::function<std::string(const std::string &)> &spell) {
    std::vector<std::string> out;
    for (const std::string &setting : settingsIgnoredBy(method))
        if (given(setting)) out.push_back(spell(setting) + " is ignored by the " + methodName(method) + " method");
    return out;
}

}  // namespace projsurf::frontend
