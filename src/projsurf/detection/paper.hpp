#pragma once
// projsurf/detection/paper: the paper's method, step by step, for reproduction (detectPaper;
// usually reached through projsurf/detector.hpp with Method::Paper).
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/detection/paper/paper_method.hpp"
