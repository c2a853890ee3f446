#pragma once
// projsurf/io/formats: clouds (PCD, PLY, depth PNG), the detection JSON, structured-light patterns,
// procam captures, video.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/formats/pattern_files.hpp"
#include "projsurf/io/formats/procam_captures.hpp"
#include "projsurf/io/formats/procam_xml.hpp"
#include "projsurf/io/formats/video_files.hpp"
