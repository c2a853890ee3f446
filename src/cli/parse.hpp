#pragma once
// Small value parsers shared by the subcommands; they throw InputError naming the option.
#include <Eigen/Core>
#include <string>

namespace projsurf::cli {

/// "gx,gy,gz" -> a finite, non-zero vector.
Eigen::Vector3d parseVector3(const std::string &option, const std::string &text);
/// "W:H" (or a single positive number) -> W / H.
double parseAspect(const std::string &option, const std::string &text);
/// "A,B" -> two finite numbers.
Eigen::Vector2d parsePair(const std::string &option, const std::string &text);

}  // namespace projsurf::cli
