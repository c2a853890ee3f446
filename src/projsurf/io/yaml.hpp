#pragma once
// projsurf/io/yaml: YAML: bounded trees, the calibration, camera and settings files.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/io/yaml/yaml_numbers.hpp"
#include "projsurf/io/yaml/yaml_settings.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"
