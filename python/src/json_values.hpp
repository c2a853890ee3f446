#pragma once
// A JSON tree as plain Python values, so that a dict the module returns is the JSON a front end
// writes (one serialiser, frontend/answer/detection_document.hpp), key for key and value for value.
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace projsurf::python {

/// object -> dict (the tree's key order), array -> list, integer -> int, floating point ->
/// float (the same double), string -> str, boolean -> bool, null -> None.
pybind11::object pythonFromJson(const nlohmann::json &j);

}  // namespace projsurf::python
