#pragma once
// Numbers written into YAML files with a stated number of significant digits (yaml-cpp would
// write 39.299999999999997 for 39.3).
#include <cstdio>
#include <initializer_list>
#include <string>

#include <yaml-cpp/yaml.h>

namespace projsurf {

inline YAML::Node yamlNumber(double v, int digits) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return YAML::Node(std::string(buf));
}

/// A flow sequence [a, b, c] of such numbers.
inline YAML::Node yamlNumbers(std::initializer_list<double> values, int digits) {
    YAML::Node n;
    for (double v : values) n.push_back(yamlNumber(v, digits));
    n.SetStyle(YAML::EmitterStyle::Flow);
    return n;
}

}  // namespace projsurf
