#pragma once
// projsurf/sim/scenes: the simulator's scenes: the paper's scenarios and the realistic ones.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/sim/scenes/scenarios_realistic.hpp"
#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/sim/scenes/wall_frame.hpp"
