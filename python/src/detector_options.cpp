#include "detector_options.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <cstdio>

#include "projsurf/frontend/aspect.hpp"
#include "projsurf/io/errors.hpp"

namespace py = pybind11;

namespace projsurf::python {
namespace {

double aspectFrom(const py::object &aspect) {
    if (aspect.is_none()) return 0.0;
    if (py::isinstance<py::str>(aspect)) return frontend::parseAspect("aspect", aspect.cast<std::string>());
    double a = std::nan("");
    try {
        a = aspect.cast<double>();
    } catch (const py::cast_error &) {
        return frontend::parseAspect("aspect", py::str(aspect));
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", a);  // exact: the same double read back
    return frontend::parseAspect("aspect", text);
}

/// None -> `fallback`; else a finite number >= 0.
double minimumFrom(const char *name, const py::object &value, double fallback) {
    if (value.is_none()) return fallback;
    double v = std::nan("");
    try {
        v = value.cast<double>();
    } catch (const py::cast_error &) {
    }
    if (!(v >= 0.0 && std::isfinite(v)))
        throw InputError(name, "expected a number >= 0 or None, got '" + std::string(py::str(value)) + "'");
    return v;
}

}  // namespace

DetectorOptions detectorOptions(const py::object &aspect, const py::object &gravity, const std::string &method,
                                const std::string &hull, unsigned seed, const py::object &min_width,
                                const py::object &min_area) {
    DetectorOptions o;
    o.config.aspect = aspectFrom(aspect);
    if (method == "paper")
        o.config.method = Method::Paper;
    else if (method == "default")
        o.config.method = Method::Default;
    else
        throw InputError("method", "expected 'default' or 'paper', got '" + method + "'");
    if (hull == "concave")
        o.config.paper.hull = HullKind::Concave;
    else if (hull == "convex")
        o.config.paper.hull = HullKind::Convex;
    else
        throw InputError("hull", "expected 'concave' or 'convex', got '" + hull + "'");
    o.config.seed = seed;
    const frontend::MinimumSize defaults = frontend::defaultMinimumSize(o.config.method);
    o.minimum.width = minimumFrom("min_width", min_width, defaults.width);
    o.minimum.area = minimumFrom("min_area", min_area, defaults.area);
    if (py::isinstance<py::str>(gravity)) {
        o.gravity = frontend::parseGravityChoice("gravity", gravity.cast<std::string>());
    } else if (!gravity.is_none()) {
        py::array_t<double, py::array::forcecast> g;
        try {
            g = py::array_t<double, py::array::forcecast>::ensure(gravity);
        } catch (const py::error_already_set &) {
        }
        if (!g || g.size() != 3)
            throw InputError("gravity",
                             "expected three numbers gx,gy,gz or 'auto', got '" + std::string(py::str(gravity)) + "'");
        o.gravity = frontend::gravityChoiceFrom("gravity", g.data(), 3);
    }
    return o;
}

Eigen::Vector3d gravityFor(const DetectorOptions &options, const Cloud &cloud) {
    return frontend::resolveGravity(options.gravity, cloud).gravity;
}

}  // namespace projsurf::python
