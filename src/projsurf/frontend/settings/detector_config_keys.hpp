#pragma once
// Every setting of DetectorConfig (detection/detector_config.hpp) under one dotted key that
// spells the struct fields' path (`planes.regions.min_fill`), with its type, its range and its
// doc (unit and source), all taken from the field's line, where each setting is declared once
// (the table is written from it at build time: frontend/settings/detector_config_table.hpp). The config
// file (`detect --config`, ~config, config=), `detect --print-config` and the settings the
// front ends share by name (frontend/settings/shared_settings.hpp) go through this table only.
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/io/yaml/yaml_settings.hpp"

namespace projsurf::frontend {

enum class KeyType { Bool, Int, Unsigned, Double, DoubleList, Word };

/// The field a key reaches (a function from the config to it).
template <typename T>
using ConfigField = T &(*)(DetectorConfig &);
/// `aspect`: a number (0 = the framebuffer's) or "W:H", as --aspect reads it.
struct AspectField {
    ConfigField<double> field;
};
using ConfigAccess = std::variant<ConfigField<bool>, ConfigField<int>, ConfigField<unsigned>, ConfigField<double>,
                                  ConfigField<std::vector<double>>, ConfigField<Method>, ConfigField<HullKind>,
                                  ConfigField<SuitabilityMode>, AspectField>;

/// Numbers (each item of a list) within [lo, hi]; (lo, hi] when `lo_open`. Never NaN or inf.
struct KeyRange {
    double lo = -std::numeric_limits<double>::max();
    double hi = std::numeric_limits<double>::max();
    bool lo_open = false;
};

struct ConfigKey {
    std::string key;  ///< dotted path of the field in DetectorConfig
    KeyType type;
    KeyRange range;
    std::string doc;  ///< one line: unit first where there is one
    ConfigAccess access;
};

/// The table, in DetectorConfig's order (each nested struct's keys together).
const std::vector<ConfigKey> &detectorConfigKeys();
/// nullptr when no key is spelt `key`.
const ConfigKey *findConfigKey(const std::string &key);
/// The known key `unknown` was most likely meant to be (same last word, or a small typo);
/// "" when none is near.
std::string nearestConfigKey(const std::string &unknown);

/// The key of a setting the front ends share by name (`detect --max-planes`, ~max_planes,
/// max_planes=; frontend/settings/method_settings.hpp): "max_planes" -> "planes.max_planes"; "" for
/// another name.
std::string configKeyOfSetting(const std::string &setting);
/// Every name configKeyOfSetting knows, in the CLI's order.
std::vector<std::string> sharedSettingNames();

/// "bool", "int", "unsigned", "double", "list of double", "word".
const char *keyTypeName(KeyType type);
/// What a key accepts, for messages and docs: "true | false", "1 to 20", "> 0", "default | paper".
std::string keyRangeText(const ConfigKey &key);

/// The value in `config`, written so that setConfigValue reads back the same (numbers exact).
SettingText configValue(const DetectorConfig &config, const ConfigKey &key);
/// Sets the key's field from `value`; a wrong type or a value out of range throws
/// InputError(what, problem) and leaves `config` unchanged.
void setConfigValue(DetectorConfig &config, const ConfigKey &key, const SettingText &value, const std::string &what);

}  // namespace projsurf::frontend
