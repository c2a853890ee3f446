#include "detection_dict.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include "projsurf/frontend/candidates_json.hpp"
#include "projsurf/frontend/method_words.hpp"
#include "projsurf/io/errors.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {

py::dict detectionToDict(const Detection &det, const DetectorConfig &config, bool explain) {
    py::dict d;
    d["found"] = det.found;
    d["reason"] = det.found ? py::object(py::none()) : py::object(py::str(det.reason));
    d["method"] = methodName(config.method);
    if (det.inliers > 0) {
        const Eigen::Vector4d c = det.plane.coefficients();
        d["plane"] = py::dict("coefficients"_a = py::array_t<double>(4, c.data()),
                              "orientation_deg"_a = det.orientation_deg, "inliers"_a = det.inliers);
    } else {
        d["plane"] = py::none();
    }
    if (det.rectangle.area() > 0.0) {
        py::array_t<double> corners({4, 3});
        auto w = corners.mutable_unchecked<2>();
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k) w(i, k) = det.rectangle.corners[i][k];
        d["rectangle"] = py::dict("corners"_a = corners, "width_m"_a = det.rectangle.width,
                                  "height_m"_a = det.rectangle.height, "area_m2"_a = det.rectangle.area());
    } else {
        d["rectangle"] = py::none();
    }
    d["surface_check"] = py::dict("points"_a = det.surface_check.points, "outliers"_a = det.surface_check.outliers,
                                  "accepted"_a = det.surface_check.accepted);
    if (det.suitability.used)  // as the JSON: only when colour was used
        d["suitability"] =
            py::dict("mode"_a = det.suitability.mode, "mean_albedo"_a = det.suitability.mean_albedo,
                     "texture"_a = det.suitability.texture, "unsuitable_share"_a = det.suitability.unsuitable_share,
                     "wall_luminance"_a = det.suitability.wall_luminance);
    d["timing_ms"] = py::cast(det.timing_ms);
    const Eigen::Vector3d g = det.gravity;
    d["gravity"] = py::array_t<double>(3, g.data());
    if (explain)  // the JSON's own list, by its one serialiser
        d["candidates"] = py::module_::import("json").attr("loads")(frontend::candidatesToJson(det).dump());
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
    // The same checks as the detection file reader (io/detection_json.cpp).
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
