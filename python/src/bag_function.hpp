#pragma once
// projsurf.read_bag(): the clouds of a ROS 1 bag's topic, as `projsurf detect --bag` reads them.
#include <pybind11/pybind11.h>

namespace projsurf::python {

/// Adds read_bag() to the module.
void addBagFunction(pybind11::module_ &m);

}  // namespace projsurf::python
