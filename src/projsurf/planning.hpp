#pragma once
// projsurf/planning: where the robot should stand for the largest picture (planStance).
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/planning/floor_occupancy.hpp"
#include "projsurf/planning/stance_view.hpp"
#include "projsurf/planning/stand_planner.hpp"
