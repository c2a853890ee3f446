#pragma once
// projsurf/types: the shared vocabulary: clouds, planes and plane frames, camera intrinsics, the
// projector model and rigid transforms.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/formatted.hpp"
#include "projsurf/types/lens_model_check.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"
