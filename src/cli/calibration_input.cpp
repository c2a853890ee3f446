#include "cli/calibration_input.hpp"

#include <cstdio>
#include <vector>

#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf::cli {

Projector readCalibrationWarned(const std::string &path) {
    std::vector<std::string> warnings;
    Projector projector = readCalibration(path, &warnings);
    for (const std::string &w : warnings) std::fprintf(stderr, "projsurf: warning: %s\n", w.c_str());
    return projector;
}

}  // namespace projsurf::cli
