#pragma once
// projsurf.print_config(): the detector settings in effect as YAML, `projsurf detect --print-config`.
#include <pybind11/pybind11.h>

namespace projsurf::python {

/// Adds print_config() to the module.
void addPrintConfigFunction(pybind11::module_ &m);

}  // namespace projsurf::python
