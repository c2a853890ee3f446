#pragma once
// The detector's numeric settings the front ends share by name (`detect --max-tilt`, the node's
// ~max_tilt, Python's max_tilt=): each is a key of the table (frontend/settings/detector_config_keys.hpp),
// so its type, range, doc and the message that refuses a value are the key's, the same in every
// front end.
#include <string>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/frontend/settings/detector_config_keys.hpp"

namespace projsurf::frontend {

/// The shared settings (sharedSettingNames(), configKeyOfSetting()'s table) whose value is a
/// plain number (not the aspect's W:H), in the table's order, which is the order of the CLI's
/// flags and of Python's list of keywords: max_tilt, seed, voxel_leaf, ransac_distance,
/// max_outliers, cell, max_planes, max_outlier_fraction.
const std::vector<std::string> &sharedNumberSettings();

/// The table's key of one of them ("max_planes" -> planes.max_planes); throws std::logic_error
/// for another name.
const ConfigKey &sharedSettingKey(const std::string &setting);

/// Sets the setting from `text` as the config file would set its key: a wrong type or a value
/// out of range throws InputError(what, "must be ..., got '...'") and leaves `config` unchanged.
void setSharedSetting(DetectorConfig &config, const std::string &setting, const std::string &text,
                      const std::string &what);

/// The setting's help line: its doc and what it accepts ("...; 0 to 1.5").
std::string sharedSettingHelp(const std::string &setting);

}  // namespace projsurf::frontend
