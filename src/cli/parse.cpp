#include "cli/parse.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "projsurf/io/errors.hpp"

namespace projsurf::cli {
namespace {

std::vector<double> numbers(const std::string &option, const std::string &text, char sep) {
    std::vector<double> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, sep)) {
        try {
            std::size_t used = 0;
            const double v = std::stod(item, &used);
            if (used != item.size() || !std::isfinite(v)) throw std::invalid_argument(item);
            out.push_back(v);
        } catch (const std::exception &) {
            throw InputError(option, "'" + text + "' is not a list of numbers");
        }
    }
    return out;
}

}  // namespace

Eigen::Vector3d parseVector3(const std::string &option, const std::string &text) {
    const auto v = numbers(option, text, ',');
    if (v.size() != 3) throw InputError(option, "expected three numbers gx,gy,gz, got '" + text + "'");
    const Eigen::Vector3d g(v[0], v[1], v[2]);
    if (g.norm() < 1e-9) throw InputError(option, "the vector is zero");
    return g;
}

double parseAspect(const std::string &option, const std::string &text) {
    const auto v = numbers(option, text, ':');
    double a = 0.0;
    if (v.size() == 2 && v[1] != 0.0) a = v[0] / v[1];
    else if (v.size() == 1) a = v[0];
    if (!(a > 0.01 && a < 100.0)) throw InputError(option, "expected a positive aspect ratio W:H, got '" + text + "'");
    return a;
}

Eigen::Vector2d parsePair(const std::string &option, const std::string &text) {
    const auto v = numbers(option, text, ',');
    if (v.size() != 2) throw InputError(option, "expected two numbers A,B, got '" + text + "'");
    return {v[0], v[1]};
}

}  // namespace projsurf::cli
