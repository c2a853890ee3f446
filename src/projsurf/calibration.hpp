#pragma once
// projsurf/calibration: paper 3.1: the projector relative to the camera (the disc calibration,
// chessboards, structured light, the full lens fit) and the closed-loop check.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/calibration/calibration.hpp"
#include "projsurf/calibration/calibration_picture.hpp"
#include "projsurf/calibration/chessboard_pose.hpp"
#include "projsurf/calibration/converged_fit.hpp"
#include "projsurf/calibration/decoded_points.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/pose_spread.hpp"
#include "projsurf/calibration/projected_picture.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/calibration/stereo_fit.hpp"
