#include "detection_dict.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include "json_values.hpp"
#include "projsurf/frontend/answer/continuous_json.hpp"
#include "projsurf/frontend/answer/detection_document.hpp"
#include "projsurf/io/files/errors.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {

namespace {

/// d[key] (when it is a list) as a float64 numpy array of the same numbers.
void numpyAt(py::dict d, const char *key) {
    if (d.contains(key) && py::isinstance<py::list>(d[key]))
        d[key] = py::module_::import("numpy").attr("asarray")(d[key], "dtype"_a = "float64");
}

}  // namespace

py::dict detectionToDict(const Detection &det, const DetectorConfig &config, const Projector &projector, bool explain) {
    py::dict d = pythonFromJson(frontend::detectionDocument(det, config, projector, explain));
    // The vectors are numpy arrays (the module's promise since its first version).
    numpyAt(d, "gravity");
    if (py::isinstance<py::dict>(d["plane"])) numpyAt(d["plane"].cast<py::dict>(), "coefficients");
    if (py::isinstance<py::dict>(d["rectangle"])) numpyAt(d["rectangle"].cast<py::dict>(), "corners");
    return d;
}

py::dict continuousFrameToDict(const Detection &det, const ContinuousFrame &frame, const DetectorConfig &config,
                               const Projector &projector) {
    py::dict d = detectionToDict(det, config, projector);
    nlohmann::json words;
    frontend::addContinuousFrame(words, frame);
    const py::dict extra = pythonFromJson(words);
    d["shown"] = extra["shown"];
    d["event"] = extra["event"];
    if (py::isinstance<py::dict>(d["shown"])) numpyAt(d["shown"].cast<py::dict>(), "corners");
    return d;
}

Rectangle rectangleFromDetection(const py::handle &detection) {
    py::object corners_obj;
    if (py::isinstance<py::dict>(detection)) {
        const py::dict d = py::reinterpret_borrow<py::dict>(detection);
        if (!d.contains("found") || !d.contains("rectangle"))
            throw InputError("detection", "expected the dict of projsurf.detect (keys 'found', 'rectangle')");
        if (!py::bool_(d["found"])) {
            std::string reason =
                d.contains("reason") && !d["reason"].is_none() ? std::string(py::str(d["reason"])) : "";
            throw InputError("detection",
                             "the detection found no surface" + (reason.empty() ? std::string() : " (" + reason + ")"));
        }
        const py::object rect = d["rectangle"];
        if (!py::isinstance<py::dict>(rect) || !rect.contains("corners"))
            throw InputError("detection", "'rectangle.corners' is missing");
        corners_obj = rect["corners"];
    } else {
        corners_obj = py::reinterpret_borrow<py::object>(detection);
    }
    py::array_t<double, py::array::forcecast> c;
    try {
        c = py::array_t<double, py::array::forcecast>::ensure(corners_obj);
    } catch (const py::error_already_set &) {
        c = {};
    }
    if (!c || c.ndim() != 2 || c.shape(0) != 4 || c.shape(1) != 3)
        throw InputError("detection", "'rectangle.corners' must hold 4 [x, y, z] points");
    Rectangle r;
    auto v = c.unchecked<2>();
    for (int i = 0; i < 4; ++i) {
        r.corners[i] = Eigen::Vector3d(v(i, 0), v(i, 1), v(i, 2));
        if (!r.corners[i].allFinite()) throw InputError("detection", "'rectangle.corners' is not finite");
    }
    // The same checks as the detection file reader (io/formats/detection_json.cpp).
    const auto &k = r.corners;
    r.width = (k[1] - k[0]).norm();
    r.height = (k[3] - k[0]).norm();
    const double w2 = (k[2] - k[3]).norm(), h2 = (k[2] - k[1]).norm();
    if (!(r.width > 1e-6 && r.height > 1e-6))
        throw InputError("detection", "'rectangle.corners' do not span a rectangle");
    const double tol = 1e-3 * std::max(r.width, r.height) + 1e-6;
    if (std::abs(w2 - r.width) > tol || std::abs(h2 - r.height) > tol ||
        std::abs((k[1] - k[0]).normalized().dot((k[3] - k[0]).normalized())) > 1e-3)
        throw InputError("detection", "'rectangle.corners' are not the corners of a rectangle (TL, TR, BR, BL)");
    return r;
}

}  // namespace projsurf::python
