#pragma once
// The calibration YAML written by structured-light `calibrate`: the contract's keys and the
// full-model keys (io/yaml/yaml_files.cpp), plus the fit's residuals and where the captures were.
#include <string>

#include "projsurf/calibration/projector_fit.hpp"

namespace projsurf {

void writeStructuredCalibration(const std::string &path, const ProjectorFit &fit, const std::string &captures_dir,
                                int poses, const std::string &created_utc);

}  // namespace projsurf
