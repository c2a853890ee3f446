#include "print_config_function.hpp"

#include "detector_options.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {

void addPrintConfigFunction(py::module_ &m) {
    m.def(
        "print_config",
        [](const py::object &config, const py::object &aspect, const py::object &method, const py::object &hull,
           const py::object &seed, const py::object &suitability, const py::kwargs &settings) {
            // The settings detect() would run with, read and checked by the same call; gravity and
            // the minimum size are no detector settings (neither are they in the YAML).
            const DetectorOptions options = detectorOptions(
                {aspect, py::none(), method, hull, seed, py::none(), py::none(), suitability, config, settings});
            return frontend::detectorConfigYaml(options.config);
        },
        py::kw_only(), "config"_a = py::none(), "aspect"_a = py::none(), "method"_a = py::none(), "hull"_a = py::none(),
        "seed"_a = py::none(), "suitability"_a = py::none(),
        "The detector settings in effect (the defaults, then config's file, then every other argument that\n"
        "is not None) as the YAML text `projsurf detect --print-config` writes for the same file and options:\n"
        "every key with a comment line (unit, type, range); it reads back through config=. Takes detect()'s\n"
        "config, aspect, method, hull, seed, suitability and pipeline settings (max_tilt, voxel_leaf,\n"
        "ransac_distance, max_outliers, cell, max_planes, max_outlier_fraction). Raises InputError.");
}

}  // namespace projsurf::python
