#include "params.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/method_words.hpp"
#include "projsurf/frontend/settings/shared_settings.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf::ros_node {
namespace {

std::string name(const ros::NodeHandle &pnh, const std::string &key) { return pnh.resolveName(key); }

template <typename T>
void get(const ros::NodeHandle &pnh, const std::string &key, T &value) {
    if (!pnh.hasParam(key)) return;
    if (!pnh.getParam(key, value)) throw InputError(name(pnh, key), "has the wrong type");
}

// A double parameter given as 1 or 1.0 (ROS stores ints and doubles apart).
void getNumber(const ros::NodeHandle &pnh, const std::string &key, double &value) {
    if (!pnh.hasParam(key)) return;
    double d;
    int i;
    if (pnh.getParam(key, d))
        value = d;
    else if (pnh.getParam(key, i))
        value = i;
    else
        throw InputError(name(pnh, key), "must be a number");
    if (!std::isfinite(value)) throw InputError(name(pnh, key), "must be finite");
}

void getPositive(const ros::NodeHandle &pnh, const std::string &key, double &value) {
    getNumber(pnh, key, value);
    if (!(value > 0.0)) throw InputError(name(pnh, key), "must be > 0");
}

void getCount(const ros::NodeHandle &pnh, const std::string &key, int &value, int min) {
    get(pnh, key, value);
    if (value < min) throw InputError(name(pnh, key), "must be >= " + std::to_string(min));
}

frontend::GravityChoice parseGravity(const ros::NodeHandle &pnh) {
    const std::string key = "gravity";
    std::vector<double> list;
    std::string text;
    if (pnh.getParam(key, list)) return frontend::gravityChoiceFrom(name(pnh, key), list.data(), list.size());
    if (pnh.getParam(key, text)) return frontend::parseGravityChoice(name(pnh, key), text);
    throw InputError(name(pnh, key), "needs 3 numbers, e.g. [0, 1, 0], or auto");
}

/// ~aspect as "W:H" or a number; "" (the launch file's default): the config's.
void getAspect(const ros::NodeHandle &pnh, DetectorConfig &c) {
    if (!pnh.hasParam("aspect")) return;
    std::string text;
    double number;
    if (pnh.getParam("aspect", text)) {
        if (!text.empty()) c.aspect = frontend::parseAspect(name(pnh, "aspect"), text);
    } else if (pnh.getParam("aspect", number)) {
        c.aspect = frontend::parseAspect(name(pnh, "aspect"), std::to_string(number));
    } else {
        throw InputError(name(pnh, "aspect"), "expected \"W:H\"");
    }
}

/// The picture, continuous mode, blanking and the move planner's limits.
void loadOutputParams(const ros::NodeHandle &pnh, NodeParams &p) {
    get(pnh, "image", p.image);
    get(pnh, "continuous", p.continuous);
    get(pnh, "blank", p.blank);
    getNumber(pnh, "plan_width", p.plan.width);
    getNumber(pnh, "plan_max_move", p.plan.max_move);
    if (!(p.plan.width >= 0.0 && p.plan.width <= 50.0))
        throw InputError(name(pnh, "plan_width"), "must be between 0 and 50 m");
    if (!(p.plan.max_move >= 0.0 && p.plan.max_move <= 10.0))
        throw InputError(name(pnh, "plan_max_move"), "must be between 0 and 10 m");
}

/// ~config first: every parameter given after it overrides the file's value. Then the
/// aspect, gravity, method, hull, colour and suitability.
void loadDetectorChoices(const ros::NodeHandle &pnh, NodeParams &p) {
    DetectorConfig &c = p.detector;
    std::string config_file;
    get(pnh, "config", config_file);
    if (!config_file.empty()) frontend::readDetectorConfig(config_file, c);
    getAspect(pnh, c);
    if (pnh.hasParam("gravity")) p.gravity = parseGravity(pnh);
    std::string method, hull;  // "" (the launch file's default): the config's
    get(pnh, "method", method);
    get(pnh, "hull", hull);
    if (!method.empty()) c.method = frontend::parseMethod(name(pnh, "method"), method);
    if (!hull.empty()) c.paper.hull = frontend::parseHull(name(pnh, "hull"), hull);
    get(pnh, "use_colour", p.use_colour);
    get(pnh, "explain", p.explain);
    if (pnh.hasParam("suitability")) {
        std::string mode;
        get(pnh, "suitability", mode);
        p.suitability_given = !mode.empty();  // "" (the launch file's default): the config's, avoid by default
        if (p.suitability_given) c.suitability.mode = frontend::parseSuitabilityMode(name(pnh, "suitability"), mode);
    }
}

/// The CLI's pipeline options (projsurf detect --voxel-leaf ... -> ~voxel_leaf ...).
void loadPipelineParams(const ros::NodeHandle &pnh, DetectorConfig &c) {
    for (const std::string &setting : frontend::sharedNumberSettings()) {
        XmlRpc::XmlRpcValue value;
        if (pnh.getParam(setting, value)) setSharedParam(c, setting, value, name(pnh, setting));
    }
}

/// The smallest picture worth showing: the method's default, or ~min_width / ~min_area.
frontend::MinimumSize loadMinimumSize(const ros::NodeHandle &pnh, Method method) {
    frontend::MinimumSize minimum = frontend::defaultMinimumSize(method);
    getNumber(pnh, "min_width", minimum.width);
    getNumber(pnh, "min_area", minimum.area);
    if (minimum.width < 0.0) throw InputError(name(pnh, "min_width"), "must be >= 0");
    if (minimum.area < 0.0) throw InputError(name(pnh, "min_area"), "must be >= 0");
    return minimum;
}

/// Frames and continuous mode: tf, the steady rectangle, the keystone's margins, the outputs.
void loadFrameAndSteadyParams(const ros::NodeHandle &pnh, NodeParams &p) {
    get(pnh, "gravity_frame", p.gravity_frame);
    get(pnh, "fixed_frame", p.fixed_frame);
    getPositive(pnh, "tf_timeout", p.tf_timeout);
    SteadyConfig &s = p.steady;
    getPositive(pnh, "steady_scale", s.scale);
    if (s.scale > 1.0) throw InputError(name(pnh, "steady_scale"), "must be within (0, 1]");
    getCount(pnh, "switch_frames", s.switch_frames, 1);
    getCount(pnh, "hold_frames", s.hold_frames, 0);
    getPositive(pnh, "plane_smoothing", s.plane_smoothing);
    if (s.plane_smoothing > 1.0) throw InputError(name(pnh, "plane_smoothing"), "must be within (0, 1]");
    getPositive(pnh, "same_wall_angle", s.same_wall_angle);
    getPositive(pnh, "same_wall_distance", s.same_wall_distance);
    getPositive(pnh, "grow_ratio", s.grow_ratio);
    getNumber(pnh, "fit_margin_px", p.fit_margin_px);
    getNumber(pnh, "keystone_tolerance_px", p.keystone_tolerance_px);
    get(pnh, "framebuffer_file", p.framebuffer_file);
    get(pnh, "marker_ns", p.marker_ns);
}

/// The parameter as the text a config file would hold: a whole double as a whole number (a
/// seed of 3e9 given as 3000000000.0), other doubles exactly.
std::string paramText(const XmlRpc::XmlRpcValue &value, const std::string &what) {
    XmlRpc::XmlRpcValue v = value;  // the conversions are not const
    switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeInt: return std::to_string(static_cast<int>(v));
    case XmlRpc::XmlRpcValue::TypeString: return static_cast<std::string>(v);
    case XmlRpc::XmlRpcValue::TypeDouble: {
        const double d = static_cast<double>(v);
        char text[64];
        std::snprintf(text, sizeof text,
                      std::isfinite(d) && d == std::trunc(d) && std::abs(d) < 1e15 ? "%.0f" : "%.17g", d);
        return text;
    }
    default: break;
    }
    throw InputError(what, "must be a number");
}

}  // namespace

void setSharedParam(DetectorConfig &config, const std::string &setting, const XmlRpc::XmlRpcValue &value,
                    const std::string &what) {
    frontend::setSharedSetting(config, setting, paramText(value, what), what);
}

NodeParams loadParams(const ros::NodeHandle &pnh) {
    NodeParams p;
    if (!pnh.getParam("calib", p.calib) || p.calib.empty())
        throw InputError(name(pnh, "calib"), "is required: the path of the projector calibration YAML");
    p.projector = readCalibration(p.calib, &p.calib_warnings);
    loadOutputParams(pnh, p);
    loadDetectorChoices(pnh, p);
    loadPipelineParams(pnh, p.detector);
    p.minimum = loadMinimumSize(pnh, p.detector.method);
    loadFrameAndSteadyParams(pnh, p);
    return p;
}

}  // namespace projsurf::ros_node
