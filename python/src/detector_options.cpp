#include "detector_options.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <cstdio>

#include "argument_types.hpp"
#include "projsurf/frontend/aspect.hpp"
#include "projsurf/frontend/depth_range_check.hpp"
#include "projsurf/frontend/gravity_sanity.hpp"
#include "projsurf/frontend/suitability_mode.hpp"
#include "projsurf/io/errors.hpp"

namespace py = pybind11;

namespace projsurf::python {
namespace {

std::string exactText(double a) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", a);  // exact: the same double read back
    return text;
}

/// "16:9", 16 / 9 or (16, 9), read as --aspect reads its words.
double aspectFrom(const py::object &aspect) {
    if (aspect.is_none()) return 0.0;
    if (PyUnicode_Check(aspect.ptr())) return frontend::parseAspect("aspect", aspect.cast<std::string>());
    if (PyTuple_Check(aspect.ptr()) || PyList_Check(aspect.ptr())) {
        const std::pair<double, double> wh = pairArgument(aspect, "aspect");
        return frontend::parseAspect("aspect", exactText(wh.first) + ":" + exactText(wh.second));
    }
    double a = std::nan("");
    try {
        a = numberArgument(aspect, "aspect");
    } catch (const InputError &) {
        throw InputError("aspect", "expected None, a number, 'W:H' or a pair (W, H), got " + describe(aspect));
    }
    return frontend::parseAspect("aspect", exactText(a));
}

/// None -> `fallback`; else a finite number >= 0.
double minimumFrom(const char *name, const py::object &value, double fallback) {
    if (value.is_none()) return fallback;
    double v = std::nan("");
    try {
        v = numberArgument(value, name);
    } catch (const InputError &) {
    }
    if (!(v >= 0.0 && std::isfinite(v)))
        throw InputError(name, "expected a number >= 0 or None, got " +
                                   (PyLong_Check(value.ptr()) || PyFloat_Check(value.ptr())
                                        ? "'" + py::str(value).cast<std::string>() + "'"
                                        : describe(value)));
    return v;
}

frontend::GravityChoice gravityFrom(const py::object &gravity) {
    if (gravity.is_none()) return {};
    if (PyUnicode_Check(gravity.ptr())) return frontend::parseGravityChoice("gravity", gravity.cast<std::string>());
    Eigen::Vector3d g;
    try {
        g = vectorArgument(gravity, "gravity");
    } catch (const InputError &) {
        throw InputError("gravity", "expected three numbers gx, gy, gz, 'gx,gy,gz' or 'auto', got " + describe(gravity));
    }
    return frontend::gravityChoiceFrom("gravity", g.data(), 3);
}

}  // namespace

DetectorOptions detectorOptions(const DetectorArguments &a) {
    DetectorOptions o;
    o.config.aspect = aspectFrom(a.aspect);
    const std::string method = wordArgument(a.method, "method");
    if (method == "paper")
        o.config.method = Method::Paper;
    else if (method == "default")
        o.config.method = Method::Default;
    else
        throw InputError("method", "expected 'default' or 'paper', got '" + method + "'");
    const std::string hull = wordArgument(a.hull, "hull");
    if (hull == "concave")
        o.config.paper.hull = HullKind::Concave;
    else if (hull == "convex")
        o.config.paper.hull = HullKind::Convex;
    else
        throw InputError("hull", "expected 'concave' or 'convex', got '" + hull + "'");
    o.config.seed = static_cast<unsigned>(wholeArgument(a.seed, "seed", 0, 4294967295LL));
    if (!a.suitability.is_none()) {
        o.config.suitability.mode =
            frontend::parseSuitabilityMode("suitability", wordArgument(a.suitability, "suitability"));
        o.suitability_given = true;
    }
    const frontend::MinimumSize defaults = frontend::defaultMinimumSize(o.config.method);
    o.minimum.width = minimumFrom("min_width", a.min_width, defaults.width);
    o.minimum.area = minimumFrom("min_area", a.min_area, defaults.area);
    o.gravity = gravityFrom(a.gravity);
    o.gravity_given = !a.gravity.is_none() && !o.gravity.from_floor;
    return o;
}

ResolvedInput resolveInput(const DetectorOptions &options, const Cloud &cloud) {
    ResolvedInput out;
    const frontend::ResolvedGravity resolved = frontend::resolveGravity(options.gravity, cloud);
    out.gravity = resolved.gravity;
    if (options.gravity.from_floor && !resolved.floor_found)
        out.warnings.push_back("gravity='auto' found no floor; assuming a level camera");
    if (options.gravity_given)
        for (const std::string &w : frontend::gravityWarnings("gravity", options.gravity.gravity, cloud))
            out.warnings.push_back(w);
    if (const auto w = frontend::depthRangeWarning(cloud, "points", false)) out.warnings.push_back(*w);
    if (options.suitability_given && options.config.suitability.mode != SuitabilityMode::Off && !cloud.hasColour() &&
        options.config.method == Method::Default)
        out.warnings.push_back("suitability needs registered colour (colour=); the surface is judged by depth only");
    return out;
}

void warnAll(const std::vector<std::string> &warnings) {
    for (const std::string &w : warnings)
        if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();
}

}  // namespace projsurf::python
