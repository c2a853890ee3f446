#pragma once
// projsurf/io/reports: the calibration reports (disc, chessboard, structured light) as YAML.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/io/reports/calibration_report.hpp"
#include "projsurf/io/reports/chessboard_report.hpp"
#include "projsurf/io/reports/structured_report.hpp"
