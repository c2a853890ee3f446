#pragma once
// projsurf/keystone: paper 3.3: the keystone homography of a rectangle on the wall and the
// framebuffer warp (with lens distortion).
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/keystone/keystone_warper.hpp"
