#include "detector_options.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <sstream>

#include "projsurf/core/gravity.hpp"
#include "projsurf/io/errors.hpp"

namespace py = pybind11;

namespace projsurf::python {
namespace {

double aspectFrom(const py::object &aspect) {
    if (aspect.is_none()) return 0.0;
    double a = 0.0;
    std::string text;
    if (py::isinstance<py::str>(aspect)) {
        text = aspect.cast<std::string>();
        std::stringstream ss(text);
        double w = 0, h = 0;
        char colon = 0;
        if (ss >> w >> colon >> h && colon == ':' && (ss >> std::ws).eof() && h != 0.0) a = w / h;
    } else {
        try {
            a = aspect.cast<double>();
        } catch (const py::cast_error &) {
        }
        text = py::str(aspect);
    }
    if (!(a > 0.01 && a < 100.0))
        throw InputError("aspect", "expected a positive aspect ratio W:H or width / height, got '" + text + "'");
    return a;
}

}  // namespace

DetectorOptions detectorOptions(const py::object &aspect, const py::object &gravity, const std::string &method,
                                const std::string &hull, unsigned seed) {
    DetectorOptions o;
    o.config.aspect = aspectFrom(aspect);
    if (method == "paper") o.config.method = Method::Paper;
    else if (method == "default") o.config.method = Method::Default;
    else throw InputError("method", "expected 'default' or 'paper', got '" + method + "'");
    if (hull == "concave") o.config.paper.hull = HullKind::Concave;
    else if (hull == "convex") o.config.paper.hull = HullKind::Convex;
    else throw InputError("hull", "expected 'concave' or 'convex', got '" + hull + "'");
    o.config.seed = seed;
    if (py::isinstance<py::str>(gravity) && gravity.cast<std::string>() == "auto") {
        o.auto_gravity = true;
    } else if (!gravity.is_none()) {
        py::array_t<double, py::array::forcecast> g;
        try {
            g = py::array_t<double, py::array::forcecast>::ensure(gravity);
        } catch (const py::error_already_set &) {
        }
        if (!g || g.size() != 3)
            throw InputError("gravity", "expected three numbers gx,gy,gz or 'auto', got '" +
                                            std::string(py::str(gravity)) + "'");
        const Eigen::Vector3d v(g.data()[0], g.data()[1], g.data()[2]);
        if (!v.allFinite()) throw InputError("gravity", "the vector is not finite");
        if (v.norm() < 1e-9) throw InputError("gravity", "the vector is zero");
        o.gravity = v;
    }
    return o;
}

Eigen::Vector3d gravityFor(const DetectorOptions &options, const Cloud &cloud) {
    if (options.auto_gravity)
        if (const auto g = estimateGravityFromFloor(cloud, options.gravity)) return g->gravity;
    return options.gravity;
}

}  // namespace projsurf::python
