#include "params.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "projsurf/io/errors.hpp"
#include "projsurf/io/yaml_files.hpp"

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
    if (pnh.getParam(key, d)) value = d;
    else if (pnh.getParam(key, i)) value = i;
    else throw InputError(name(pnh, key), "must be a number");
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

Eigen::Vector3d parseGravity(const ros::NodeHandle &pnh) {
    const std::string key = "gravity";
    std::vector<double> list;
    std::string text;
    Eigen::Vector3d g;
    if (pnh.getParam(key, list)) {
        if (list.size() != 3) throw InputError(name(pnh, key), "needs 3 numbers");
        g = {list[0], list[1], list[2]};
    } else if (pnh.getParam(key, text)) {
        std::replace(text.begin(), text.end(), ',', ' ');
        std::istringstream in(text);
        if (!(in >> g.x() >> g.y() >> g.z())) throw InputError(name(pnh, key), "needs 3 numbers, e.g. [0, 1, 0]");
        std::string rest;
        if (in >> rest) throw InputError(name(pnh, key), "needs exactly 3 numbers");
    } else {
        throw InputError(name(pnh, key), "needs 3 numbers, e.g. [0, 1, 0]");
    }
    if (!g.allFinite() || g.norm() < 1e-9) throw InputError(name(pnh, key), "must be a finite non-zero vector");
    return g.normalized();
}

}  // namespace

double parseAspectText(const std::string &what, const std::string &text) {
    const auto colon = text.find(':');
    try {
        std::size_t used = 0;
        double value;
        if (colon == std::string::npos) {
            value = std::stod(text, &used);
            if (used != text.size()) throw std::invalid_argument("trailing");
        } else {
            const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
            std::size_t ua = 0, ub = 0;
            const double w = std::stod(a, &ua), h = std::stod(b, &ub);
            if (ua != a.size() || ub != b.size() || !(h > 0.0)) throw std::invalid_argument("bad");
            value = w / h;
        }
        if (!(value > 0.0) || !std::isfinite(value)) throw std::invalid_argument("bad");
        return value;
    } catch (const std::exception &) {
        throw InputError(what, "expected W:H with positive numbers (e.g. 16:9), got '" + text + "'");
    }
}

NodeParams loadParams(const ros::NodeHandle &pnh) {
    NodeParams p;
    if (!pnh.getParam("calib", p.calib) || p.calib.empty())
        throw InputError(name(pnh, "calib"), "is required: the path of the projector calibration YAML");
    p.projector = readCalibration(p.calib);
    get(pnh, "image", p.image);
    get(pnh, "continuous", p.continuous);
    get(pnh, "blank", p.blank);
    getNumber(pnh, "plan_width", p.plan.width);
    getNumber(pnh, "plan_max_move", p.plan.max_move);
    if (!(p.plan.width >= 0.0 && p.plan.width <= 50.0)) throw InputError(name(pnh, "plan_width"), "must be between 0 and 50 m");
    if (!(p.plan.max_move >= 0.0 && p.plan.max_move <= 10.0))
        throw InputError(name(pnh, "plan_max_move"), "must be between 0 and 10 m");

    DetectorConfig &c = p.detector;
    if (pnh.hasParam("aspect")) {
        std::string text;
        double number;
        if (pnh.getParam("aspect", text)) {
            if (!text.empty()) c.aspect = parseAspectText(name(pnh, "aspect"), text);
        } else if (pnh.getParam("aspect", number)) {
            c.aspect = parseAspectText(name(pnh, "aspect"), std::to_string(number));
        } else {
            throw InputError(name(pnh, "aspect"), "expected \"W:H\"");
        }
    }
    std::string gravity_text;
    if (pnh.getParam("gravity", gravity_text) && gravity_text == "auto") p.gravity_auto = true;
    else if (pnh.hasParam("gravity")) p.gravity = parseGravity(pnh);
    std::string method = "default", hull = "concave";
    get(pnh, "method", method);
    get(pnh, "hull", hull);
    if (method == "default") c.method = Method::Default;
    else if (method == "paper") c.method = Method::Paper;
    else throw InputError(name(pnh, "method"), "expected 'default' or 'paper', got '" + method + "'");
    if (hull == "concave") c.paper.hull = HullKind::Concave;
    else if (hull == "convex") c.paper.hull = HullKind::Convex;
    else throw InputError(name(pnh, "hull"), "expected 'concave' or 'convex', got '" + hull + "'");
    getPositive(pnh, "max_tilt", c.max_tilt);
    int seed = static_cast<int>(c.seed);
    getCount(pnh, "seed", seed, 0);
    c.seed = static_cast<unsigned>(seed);
    // The CLI's pipeline options (projsurf detect --voxel-leaf ... -> ~voxel_leaf ...).
    getPositive(pnh, "voxel_leaf", c.paper.voxel_leaf);
    getPositive(pnh, "ransac_distance", c.paper.ransac_distance);
    getCount(pnh, "max_outliers", c.paper.max_outliers, 0);
    getPositive(pnh, "cell", c.free_space.cell);
    getCount(pnh, "max_planes", c.planes.max_planes, 1);
    getNumber(pnh, "max_outlier_fraction", c.check.max_outlier_fraction);
    if (c.check.max_outlier_fraction < 0.0 || c.check.max_outlier_fraction > 1.0)
        throw InputError(name(pnh, "max_outlier_fraction"), "must be within [0, 1]");

    // Frames and continuous mode.
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
    return p;
}

}  // namespace projsurf::ros_node
