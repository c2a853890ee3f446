#pragma once
// projsurf/frontend/settings: what the CLI, the node and Python share to read a user's settings:
// the detector's keys and the settings shared by name, aspect, gravity, resolution, the smallest
// picture and the warnings about them.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/depth_range_check.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/detector_config_keys.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/gravity_sanity.hpp"
#include "projsurf/frontend/settings/gravity_warnings.hpp"
#include "projsurf/frontend/settings/ignored_settings.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"
#include "projsurf/frontend/settings/method_words.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/frontend/settings/resolution.hpp"
#include "projsurf/frontend/settings/shared_settings.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
