#pragma once
// projsurf/sim: the simulator: depth sensor models (Kinect v1, ToF, D435), rendering a frame,
// projector light, ground truth, calibration captures.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/sim/calibration_captures.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/ray_cast.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/sensor_model.hpp"
