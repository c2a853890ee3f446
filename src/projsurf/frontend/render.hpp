#pragma once
// projsurf/frontend/render: what the front ends share to draw: the overlays of a detection and a
// plan, the framebuffer render, the test card, blanking, the progress line.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/frontend/render/framebuffer_render.hpp"
#include "projsurf/frontend/render/overlay.hpp"
#include "projsurf/frontend/render/plan_overlay.hpp"
#include "projsurf/frontend/render/progress.hpp"
#include "projsurf/frontend/render/rectangle_blanking.hpp"
#include "projsurf/frontend/render/test_card.hpp"
