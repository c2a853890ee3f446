#pragma once
// The detector's settings as a YAML file (`detect --config`, the node's ~config, Python's
// config=): any key of the table (frontend/settings/detector_config_keys.hpp), nested (`planes:
// {max_planes: 6}`) or dotted (`planes.max_planes: 6`); and the whole config written back
// (`detect --print-config`), which reads back to the same config.
#include <string>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf::frontend {

/// The file's settings over `config` (keys it does not give keep their values). Throws
/// InputError naming the file, and the key when one is at fault: an unknown key (with the
/// nearest known one), a value of the wrong type or out of range, a malformed or hostile file.
void readDetectorConfig(const std::string &path, DetectorConfig &config);

/// Every key of `config` as YAML, each after a comment line with its doc, type and range.
std::string detectorConfigYaml(const DetectorConfig &config);

}  // namespace projsurf::frontend
