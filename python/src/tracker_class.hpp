#pragma once
// projsurf.Tracker: continuous mode from Python (tracking/continuous_tracker.hpp), the node's
// ~continuous over clouds the caller gives, one at a time.
#include <string>

#include <pybind11/pybind11.h>

namespace projsurf::python {

/// Adds the class Tracker to the module; `options_doc` says what the detector options mean
/// (as for Detector).
void addTrackerClass(pybind11::module_ &m, const std::string &options_doc);

}  // namespace projsurf::python
