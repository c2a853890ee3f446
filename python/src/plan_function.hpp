#pragma once
// projsurf.plan(): where the robot should stand (contract "Where to stand"), as `projsurf plan`.
#include <pybind11/pybind11.h>

namespace projsurf::python {

/// Adds plan() to the module.
void addPlanFunction(pybind11::module_ &m);

}  // namespace projsurf::python
