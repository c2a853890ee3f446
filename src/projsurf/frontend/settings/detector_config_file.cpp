#include "projsurf/frontend/settings/detector_config_file.hpp"

#include "projsurf/frontend/settings/detector_config_keys.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/yaml/yaml_settings.hpp"

namespace projsurf::frontend {
namespace {

/// Settings every front end takes, but as an option of its own and not from the file: the
/// smallest picture (applied to what the detector returns, frontend/settings/minimum_size.hpp) and the
/// gravity (an input per frame). How each front end spells them; "" for another key.
std::string flagNotKey(std::string key) {
    if (key.rfind("--", 0) == 0) key = key.substr(2);
    for (char &c : key)
        if (c == '-') c = '_';
    if (key == "min_width" || key == "min_area")
        return "the smallest picture is not a detector setting: give it as detect " + optionName(key) + ", the node's ~" +
               key + " or Python's " + key + "=";
    if (key == "gravity")
        return "gravity goes with the frames, not in this file: give it as detect or plan --gravity, the node's "
               "~gravity (or ~gravity_frame) or Python's gravity=";
    return "";
}

/// Why `key` is not a setting, with what was meant when that can be told.
std::string unknownKeyProblem(const std::string &key) {
    std::string section;
    for (const ConfigKey &k : detectorConfigKeys())
        if (k.key.rfind(key + ".", 0) == 0) section += (section.empty() ? "" : ", ") + k.key;
    if (!section.empty()) {
        if (section.size() > 80) section = section.substr(0, section.rfind(", ", 80)) + ", ...";
        return "key '" + shownText(key) + "' holds settings (" + section + "), not a value";
    }
    std::string problem = "unknown key '" + shownText(key) + "'";
    const std::string first = key.substr(0, key.find('.'));
    if (first == "projector" || first == "camera" || first == "image_width")
        return problem + " (a calibration or camera file, not a detector configuration?)";
    if (const std::string flag = flagNotKey(key); !flag.empty()) return problem + " (" + flag + ")";
    const std::string near = nearestConfigKey(key);
    if (!near.empty()) problem += " (did you mean '" + near + "'?)";
    return problem;
}

/// Settings that are each in range but contradict each other.
void checkTogether(const std::string &path, const DetectorConfig &c) {
    auto notAbove = [&](double lo, double hi, const char *lo_key, const char *hi_key) {
        if (lo > hi) throw InputError(path, std::string("'") + lo_key + "' must not exceed '" + hi_key + "'");
    };
    notAbove(c.tolerance.min_band, c.tolerance.max_band, "tolerance.min_band", "tolerance.max_band");
    notAbove(c.wall.noise_min, c.wall.noise_max, "wall.noise_min", "wall.noise_max");
    notAbove(c.wall.shape.min_points, c.wall.shape.max_points, "wall.shape.min_points", "wall.shape.max_points");
    // The relief's smoothing, in nodes: sigma_px / node_px sizes a Gaussian kernel on the node grid.
    const auto &relief = c.wall.shape.relief;
    if (relief.sigma_px > 10.0 * relief.node_px)
        throw InputError(path, "'wall.shape.relief.sigma_px' must not exceed 10 x 'wall.shape.relief.node_px' (" +
                                   std::to_string(relief.sigma_px) + " > 10 x " + std::to_string(relief.node_px) + ")");
}

}  // namespace

void readDetectorConfig(const std::string &path, DetectorConfig &config) {
    DetectorConfig read = config;  // `config` unchanged when the file is refused
    for (const SettingText &s : readYamlSettings(path)) {
        const ConfigKey *key = findConfigKey(s.key);
        if (!key) throw InputError(path, unknownKeyProblem(s.key));
        setConfigValue(read, *key, s, path + ": key '" + shownText(s.key) + "'");
    }
    checkTogether(path, read);
    config = read;
}

std::string detectorConfigYaml(const DetectorConfig &config) {
    std::vector<SettingText> settings;
    std::vector<std::string> comments;
    for (const ConfigKey &k : detectorConfigKeys()) {
        settings.push_back(configValue(config, k));
        comments.push_back(k.doc + " [" + keyTypeName(k.type) + ": " + keyRangeText(k) + "]");
    }
    return "# projsurf detector settings: projsurf detect --config FILE, the node's ~config, Python's config=.\n"
           "# Every key is optional (a missing one keeps its default); command-line flags override the file.\n"
           "# Keys may be nested as here or dotted (planes.max_planes: 6); docs/interface.md lists them.\n\n" +
           yamlSettingsText(settings, comments);
}

}  // namespace projsurf::frontend
