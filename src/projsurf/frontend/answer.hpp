#pragma once
// projsurf/frontend/answer: what the front ends share to answer: one detection as a document (JSON,
// messages, dict), continuous events, a plan as JSON, the one-line summary.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/frontend/answer/candidates_json.hpp"
#include "projsurf/frontend/answer/continuous_json.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/answer/detection_document.hpp"
#include "projsurf/frontend/answer/detection_summary.hpp"
#include "projsurf/frontend/answer/plan_json.hpp"
