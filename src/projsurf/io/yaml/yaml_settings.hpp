#pragma once
// A YAML file of settings read as dotted keys (`planes: {max_planes: 6}` and
// `planes.max_planes: 6` are the same key), and settings written back as nested YAML. What
// the keys mean is the caller's (frontend/settings/detector_config_file.hpp); this knows only YAML.
#include <string>
#include <vector>

namespace projsurf {

/// One setting as the file holds it: a scalar (`items` of one), or a sequence of scalars.
struct SettingText {
    std::string key;                 ///< dotted: the mapping keys from the top down, joined by '.'
    std::vector<std::string> items;  ///< the scalars, exactly as written (quotes removed)
    bool sequence = false;           ///< written as a list
    bool quoted = false;             ///< a scalar (or any item) was quoted: a word, never a number
};

/// The settings of the YAML file at `path`, in the file's order: a regular file of at most
/// limits::kMaxSettingsYamlBytes whose top level is a mapping (an empty file has none).
/// Throws InputError naming the file on a malformed file, a key given twice, a key without a
/// value, a non-scalar key or a list holding anything but scalars.
std::vector<SettingText> readYamlSettings(const std::string &path);

/// `settings` as nested YAML (keys sharing a dotted prefix under one mapping, in first-seen
/// order), each preceded by its comment line from `comments` (same index; "" for none).
/// Items are written as given, quoted when `quoted`; lists in flow style.
std::string yamlSettingsText(const std::vector<SettingText> &settings, const std::vector<std::string> &comments);

}  // namespace projsurf
