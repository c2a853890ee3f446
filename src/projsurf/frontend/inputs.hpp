#pragma once
// projsurf/frontend/inputs: what the front ends share to read frames: a depth image as a cloud,
// a camera_info's pinhole, registered colour, bag frames paired by stamp, chessboard captures.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/frontend/inputs/bag_frames.hpp"
#include "projsurf/frontend/inputs/camera_info_intrinsics.hpp"
#include "projsurf/frontend/inputs/chessboard_calibration.hpp"
#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/frontend/inputs/stamp_pairing.hpp"
