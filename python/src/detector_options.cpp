#include "detector_options.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "argument_types.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/depth_range_check.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/gravity_warnings.hpp"
#include "projsurf/frontend/settings/ignored_settings.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"
#include "projsurf/frontend/settings/method_words.hpp"
#include "projsurf/frontend/settings/shared_settings.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
#include "projsurf/io/files/errors.hpp"

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
        throw InputError(
            name, "expected a number >= 0 or None, got " + (PyLong_Check(value.ptr()) || PyFloat_Check(value.ptr())
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
        throw InputError("gravity",
                         "expected three numbers gx, gy, gz, 'gx,gy,gz' or 'auto', got " + describe(gravity));
    }
    return frontend::gravityChoiceFrom("gravity", g.data(), 3);
}

/// A number as the text a config file would hold, for the key table to read: a whole number as
/// written, any other number exactly, with ".0" when whole (a float is no count).
std::string settingText(const py::handle &value, const char *name) {
    if (!PyBool_Check(value.ptr()) && PyIndex_Check(value.ptr())) {
        const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
        if (index) return py::str(index).cast<std::string>();
        PyErr_Clear();
    }
    char buffer[64];  // the shortest text that reads back exactly, as Python's repr writes it
    std::string text(buffer, std::to_chars(buffer, buffer + sizeof buffer, numberArgument(value, name)).ptr);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

const char *const kNamedArguments =
    "points, projector, aspect, gravity, method, hull, seed, min_width, min_area, suitability, colour, config, "
    "explain, overlay";

/// Puts the keyword settings into `o`: each is a key of the table (frontend/settings/shared_settings.hpp),
/// checked by it as the CLI's flag and the node's parameter are. Returns the names given.
std::vector<std::string> applySettings(const py::dict &settings, DetectorOptions &o) {
    const std::vector<std::string> &shared = frontend::sharedNumberSettings();
    std::vector<std::string> given;
    for (const auto &item : settings) {
        const std::string name = py::str(item.first).cast<std::string>();
        if (std::find(shared.begin(), shared.end(), name) == shared.end() || name == "seed") {
            std::string known = kNamedArguments;
            for (const std::string &k : shared)
                if (k != "seed") known += ", " + k;
            throw InputError(name, "unknown keyword argument (known: " + known + ")");
        }
        frontend::setSharedSetting(o.config, name, settingText(item.second, name.c_str()), name);
        given.push_back(name);
    }
    return given;
}

}  // namespace

DetectorOptions detectorOptions(const DetectorArguments &a) {
    DetectorOptions o;
    if (a.config && !a.config.is_none()) frontend::readDetectorConfig(pathArgument(a.config, "config"), o.config);
    if (!a.aspect.is_none()) o.config.aspect = aspectFrom(a.aspect);
    if (!a.method.is_none()) o.config.method = frontend::parseMethod("method", wordArgument(a.method, "method"));
    if (!a.hull.is_none()) o.config.paper.hull = frontend::parseHull("hull", wordArgument(a.hull, "hull"));
    if (!a.seed.is_none()) frontend::setSharedSetting(o.config, "seed", settingText(a.seed, "seed"), "seed");
    if (!a.suitability.is_none()) {
        o.config.suitability.mode =
            frontend::parseSuitabilityMode("suitability", wordArgument(a.suitability, "suitability"));
        o.suitability_given = true;
    }
    const frontend::MinimumSize defaults = frontend::defaultMinimumSize(o.config.method);
    o.minimum.width = minimumFrom("min_width", a.min_width, defaults.width);
    o.minimum.area = minimumFrom("min_area", a.min_area, defaults.area);
    o.gravity = gravityFrom(a.gravity);
    o.gravity_level_assumed = a.gravity.is_none();
    std::vector<std::string> given = a.settings ? applySettings(a.settings, o) : std::vector<std::string>{};
    if (!a.hull.is_none()) given.push_back("hull");
    if (!a.suitability.is_none()) given.push_back("suitability");
    warnAll(frontend::ignoredSettingWarnings(
        o.config.method, [&](const std::string &s) { return std::find(given.begin(), given.end(), s) != given.end(); },
        [](const std::string &s) { return s; }));
    return o;
}

CheckedDetection detectChecked(SurfaceDetector &detector, const DetectorOptions &options, const Cloud &cloud,
                               bool check_gravity) {
    CheckedDetection out;
    const frontend::GravityDetection answer = frontend::detectWithGravity(
        detector, cloud, options.gravity, options.minimum, "points", "min_width", "min_area");
    out.detection = answer.detection;
    out.gravity = answer.gravity.gravity;
    const frontend::GravityUsed used{options.gravity, options.gravity_level_assumed, answer.gravity};
    out.warnings = frontend::gravityUsedWarnings({"gravity", "gravity='auto'"}, used, cloud, check_gravity);
    if (const auto w = frontend::depthRangeWarning(cloud, "points", false)) out.warnings.push_back(*w);
    if (options.suitability_given && options.config.suitability.mode != SuitabilityMode::Off && !cloud.hasColour() &&
        options.config.method == Method::Default)
        out.warnings.push_back(frontend::suitabilityWithoutColourWarning("suitability", "colour="));
    return out;
}

void warnAll(const std::vector<std::string> &warnings) {
    // Stack level 2: every function is called through its one-line-errors wrapper
    // (argument_errors.hpp), whose frame is level 1; the warning names the caller's line.
    for (const std::string &w : warnings)
        if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 2) < 0) throw py::error_already_set();
}

}  // namespace projsurf::python
