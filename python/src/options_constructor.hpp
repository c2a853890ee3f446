#pragma once
// The constructor that Detector and Tracker share: (projector, *, aspect=None, gravity=None,
// method=None, hull=None, seed=None, min_width=None, min_area=None, suitability=None,
// config=None, **settings), each checked as detect() checks it.
#include <pybind11/pybind11.h>

#include "argument_types.hpp"
#include "detector_options.hpp"

namespace projsurf::python {

/// Adds that constructor to `cls`: T(const Projector &, DetectorOptions).
template <class T>
void addOptionsConstructor(pybind11::class_<T> &cls) {
    namespace py = pybind11;
    using namespace pybind11::literals;
    cls.def(py::init([](const py::object &projector, const py::object &aspect, const py::object &gravity,
                        const py::object &method, const py::object &hull, const py::object &seed,
                        const py::object &min_width, const py::object &min_area, const py::object &suitability,
                        const py::object &config, const py::kwargs &settings) {
                return T(projectorArgument(projector, "projector"),
                         detectorOptions({aspect, gravity, method, hull, seed, min_width, min_area, suitability, config,
                                          settings}));
            }),
            "projector"_a, py::kw_only(), "aspect"_a = py::none(), "gravity"_a = py::none(), "method"_a = py::none(),
            "hull"_a = py::none(), "seed"_a = py::none(), "min_width"_a = py::none(), "min_area"_a = py::none(),
            "suitability"_a = py::none(), "config"_a = py::none());
}

}  // namespace projsurf::python
