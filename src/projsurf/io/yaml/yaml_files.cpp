#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/types/lens_model_check.hpp"

#include <yaml-cpp/yaml.h>
#include <Eigen/SVD>
#include <algorithm>
#include <cctype>
#include <cmath>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"

namespace projsurf {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

YAML::Node loadYaml(const std::string &path) {
    const std::string text = readSmallTextFile(path, limits::kMaxYamlBytes, "YAML");
    YAML::Node root = loadCheckedYaml(path, text);
    if (!root.IsMap()) throw InputError(path, "expected a YAML mapping at the top level");
    return root;
}

YAML::Node child(const std::string &path, const YAML::Node &node, const std::string &key, const std::string &where) {
    if (!node.IsMap() || !node[key]) throw InputError(path, "missing key '" + where + key + "'");
    return node[key];
}

double number(const std::string &path, const YAML::Node &node, const std::string &what) {
    try {
        const double v = node.as<double>();
        if (!std::isfinite(v)) throw InputError(path, "'" + what + "' is not finite");
        return v;
    } catch (const YAML::Exception &) {
        throw InputError(path, "'" + what + "' is not a number");
    }
}

std::vector<double> numbers(const std::string &path, const YAML::Node &node, const std::string &what, std::size_t n) {
    if (!node.IsSequence() || node.size() != n)
        throw InputError(path, "'" + what + "' must be a list of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(number(path, node[i], what));
    return out;
}

/// Unknown keys named at most in the one warning line of a file: a file of 1000 typos is one
/// problem, not 1000 lines.
constexpr std::size_t kMaxUnknownKeysNamed = 3;

/// Unknown keys of one file, noted as they are found and told as one warning line (each key
/// escaped by shownText, at most kMaxUnknownKeysNamed of them, then "and N more").
struct UnknownKeys {
    UnknownKeys(const std::string &p, std::vector<std::string> *w) : path(p), warnings(w) {}
    const std::string &path;
    std::vector<std::string> *warnings;
    std::size_t count = 0;
    std::vector<std::string> named;
    std::string known;  // of the first unknown key's mapping

    void note(const YAML::Node &node, const std::string &where, const std::vector<std::string> &keys) {
        if (!warnings || !node.IsMap()) return;
        for (const auto &kv : node) {
            const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
            if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
            if (count++ == 0)
                for (const auto &k : keys) known += (known.empty() ? "" : ", ") + k;
            if (named.size() < kMaxUnknownKeysNamed) named.push_back("'" + shownText(where + key) + "'");
        }
    }
    /// The warning line, when a key was unknown.
    void finish() {
        if (!warnings || count == 0) return;
        if (count == 1) {
            warnings->push_back(path + ": unknown key " + named.front() + " is ignored (known: " + known + ")");
            return;
        }
        std::string list;
        for (const auto &k : named) list += (list.empty() ? "" : ", ") + k;
        if (count > named.size()) list += " and " + std::to_string(count - named.size()) + " more";
        warnings->push_back(path + ": unknown keys " + list + " are ignored (typos? docs/interface.md lists the keys)");
    }
};

/// The contract's optional full-model keys (intrinsics, distortion, rotation), when present.
void readFullModel(const std::string &path, const YAML::Node &p, Projector &proj) {
    if (p["intrinsics"]) {
        const YAML::Node k = p["intrinsics"];
        ProjectorIntrinsics in;
        in.fx = number(path, child(path, k, "fx", "projector.intrinsics."), "projector.intrinsics.fx");
        in.fy = number(path, child(path, k, "fy", "projector.intrinsics."), "projector.intrinsics.fy");
        in.cx = number(path, child(path, k, "cx", "projector.intrinsics."), "projector.intrinsics.cx");
        in.cy = number(path, child(path, k, "cy", "projector.intrinsics."), "projector.intrinsics.cy");
        if (!(in.fx > 0 && in.fy > 0)) throw InputError(path, "projector.intrinsics.fx and fy must be positive");
        const double span = 4.0 * std::max(proj.width, proj.height);
        if (std::abs(in.cx - 0.5 * proj.width) > span || std::abs(in.cy - 0.5 * proj.height) > span)
            throw InputError(path, "projector.intrinsics.cx, cy lie implausibly far outside the framebuffer");
        proj.intrinsics = in;
    }
    if (p["distortion"]) {
        const auto d = numbers(path, p["distortion"], "projector.distortion", 5);
        for (int i = 0; i < 5; ++i) proj.distortion[i] = d[i];
        if (std::any_of(d.begin(), d.end(), [](double k) { return std::abs(k) > 10.0; }))
            throw InputError(path, "projector.distortion has a coefficient beyond +-10: not a projector lens");
    }
    if (p["rotation"]) {
        const YAML::Node r = p["rotation"];
        if (!r.IsSequence() || r.size() != 3)
            throw InputError(path, "'projector.rotation' must be a list of 3 rows of 3 numbers");
        Eigen::Matrix3d R;
        for (int i = 0; i < 3; ++i) {
            const auto row = numbers(path, r[i], "projector.rotation", 3);
            for (int j = 0; j < 3; ++j) R(i, j) = row[j];
        }
        if ((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-3)
            throw InputError(path, "projector.rotation is not orthonormal (to 1e-3)");
        if (!(R.determinant() > 0)) throw InputError(path, "projector.rotation has determinant -1: not a rotation");
        const double angle = std::acos(std::clamp(R.col(2).normalized().dot(proj.direction), -1.0, 1.0)) / kDeg;
        if (!(angle <= 0.5))
            throw InputError(path, "projector.rotation's third column is " + std::to_string(angle) +
                                       " deg from projector.axis.direction (at most 0.5 allowed)");
        // The nearest exact rotation, so toPixel and ray stay inverse to each other.
        Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
        proj.setRotation(svd.matrixU() * svd.matrixV().transpose());
    }
}

}  // namespace

std::string readCalibrationVerdict(const std::string &path) {
    const YAML::Node root = loadYaml(path);
    const YAML::Node c = root["calibration"];
    if (!c || !c.IsMap() || !c["fit"] || !c["fit"].IsMap()) return "";
    const YAML::Node v = c["fit"]["verdict"];
    if (!v || !v.IsScalar()) return "";
    return v.as<std::string>();
}

namespace {

/// readCalibration's checks on a parsed file.
Projector calibrationFromYaml(const std::string &path, const YAML::Node &root, std::vector<std::string> *warnings) {
    if (!root["projector"] && (root["camera"] || root["camera_matrix"]))
        throw InputError(path,
                         "is camera intrinsics, not a projector calibration (projector:); --camera and --calib "
                         "swapped?");
    const YAML::Node p = child(path, root, "projector", "");
    const auto res = numbers(path, child(path, p, "resolution", "projector."), "projector.resolution", 2);
    const auto fov = numbers(path, child(path, p, "fov_deg", "projector."), "projector.fov_deg", 2);
    const YAML::Node axis = child(path, p, "axis", "projector.");
    const auto o = numbers(path, child(path, axis, "origin", "projector.axis."), "projector.axis.origin", 3);
    const auto d = numbers(path, child(path, axis, "direction", "projector.axis."), "projector.axis.direction", 3);

    Projector proj;
    const double side = limits::kMaxFramebufferSide;
    if (res[0] < 2 || res[1] < 2 || res[0] > side || res[1] > side || res[0] != std::floor(res[0]) ||
        res[1] != std::floor(res[1]))
        throw InputError(path, "projector.resolution must be two whole numbers between 2 and " +
                                   std::to_string(limits::kMaxFramebufferSide));
    if (res[0] * res[1] > static_cast<double>(limits::kMaxFramebufferPixels))
        throw InputError(path, "projector.resolution " + std::to_string(static_cast<int>(res[0])) + " x " +
                                   std::to_string(static_cast<int>(res[1])) + " exceeds the limit of " +
                                   std::to_string(limits::kMaxFramebufferPixels) + " framebuffer pixels");
    proj.width = static_cast<int>(res[0]);
    proj.height = static_cast<int>(res[1]);
    if (!(fov[0] > 0 && fov[0] < kMaxLensFovDeg && fov[1] > 0 && fov[1] < kMaxLensFovDeg))
        throw InputError(path, "projector.fov_deg must be two angles between 0 and " +
                                   std::to_string(static_cast<int>(kMaxLensFovDeg)) + " degrees");
    // Likely mistakes that are still numbers: radians for degrees, millimetres for metres.
    if (fov[0] < 3.2 && fov[1] < 3.2)
        throw InputError(path, "projector.fov_deg [" + std::to_string(fov[0]) + ", " + std::to_string(fov[1]) +
                                   "] looks like radians: give the field of view in degrees (a projector's is 15-120)");
    if (!(std::abs(o[0]) <= 3.0 && std::abs(o[1]) <= 3.0 && std::abs(o[2]) <= 3.0))
        throw InputError(path,
                         "projector.axis.origin is more than 3 m from the camera: give it in metres (millimetres?)");
    proj.fov_h = fov[0] * kDeg;
    proj.fov_v = fov[1] * kDeg;
    proj.origin = Eigen::Vector3d(o[0], o[1], o[2]);
    const Eigen::Vector3d dir(d[0], d[1], d[2]);
    if (dir.norm() < 1e-9) throw InputError(path, "projector.axis.direction is the zero vector");
    proj.direction = dir.normalized();
    readFullModel(path, p, proj);
    // What the contract and `projsurf calibrate` write under `projector:`.
    UnknownKeys unknown{path, warnings};
    unknown.note(p, "projector.",
                 {"resolution", "fov_deg", "axis", "intrinsics", "distortion", "rotation", "corner_rays", "residuals",
                  "camera", "captures", "created_utc"});
    unknown.note(axis, "projector.axis.", {"origin", "direction"});
    if (p["intrinsics"]) unknown.note(p["intrinsics"], "projector.intrinsics.", {"fx", "fy", "cx", "cy"});
    unknown.finish();
    if (const std::string problem = lensModelProblem(proj); !problem.empty()) throw InputError(path, problem);
    if (!isValidProjector(proj))
        throw InputError(path,
                         "projector.axis.direction is (nearly) vertical: the projector's image axes are undefined");
    return proj;
}

/// The dotted key of the first scalar under `node` that reads as a number but not a finite
/// one (.nan, .inf), "" when there is none; text values (a folder's name) are skipped.
std::string nonFiniteKey(const YAML::Node &node, const std::string &key) {
    if (node.IsScalar()) {
        // The text keys the writers write (a capture folder may be called "nan").
        const std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
        for (const char *text : {"dir", "captures_dir", "rgb", "tool", "created_utc", "origin_note", "verdict", "method",
                                 "order"})
            if (last == text || last.rfind(std::string(text) + "[", 0) == 0) return "";
        double v = 0;
        std::string word = node.Scalar();
        for (char &c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const bool written_nan = word == "nan" || word == "inf" || word == "-inf" || word == "+inf";  // printf's
        return written_nan || (YAML::convert<double>::decode(node, v) && !std::isfinite(v)) ? key : "";
    }
    if (node.IsMap())
        for (const auto &kv : node) {
            const std::string k = nonFiniteKey(kv.second, key.empty() ? kv.first.Scalar() : key + "." + kv.first.Scalar());
            if (!k.empty()) return k;
        }
    if (node.IsSequence())
        for (std::size_t i = 0; i < node.size(); ++i) {
            const std::string k = nonFiniteKey(node[i], key + "[" + std::to_string(i) + "]");
            if (!k.empty()) return k;
        }
    return "";
}

}  // namespace

Projector readCalibration(const std::string &path, std::vector<std::string> *warnings) {
    return calibrationFromYaml(path, loadYaml(path), warnings);
}

std::string calibrationYamlText(const std::string &path, const YAML::Node &root) {
    YAML::Emitter out;
    out.SetDoublePrecision(9);
    out << root;
    const std::string text = std::string(out.c_str()) + "\n";
    checkCalibrationText(path, text);
    return text;
}

void checkCalibrationText(const std::string &path, const std::string &text) {
    // Read back as every reader reads it: a fit that no reader accepts (a distortion beyond
    // +-10, an origin beyond 3 m) is refused here with the reader's reason.
    try {
        const YAML::Node back = loadCheckedYaml(path, text);
        if (!back.IsMap()) throw InputError(path, "expected a YAML mapping at the top level");
        calibrationFromYaml(path, back, nullptr);
        if (const std::string key = nonFiniteKey(back, ""); !key.empty())
            throw InputError(path, "'" + key + "' is not finite");
    } catch (const InputError &e) {
        std::string reason = e.what();
        if (reason.rfind(path + ": ", 0) == 0) reason = reason.substr(path.size() + 2);
        throw InputError(path, "not written: the calibration would be refused by every reader (" + reason + ")");
    }
}

YAML::Node calibrationNode(const Projector &projector) {
    YAML::Node p;
    auto seq = [](std::initializer_list<double> v) {
        YAML::Node n;
        for (double x : v) n.push_back(x);
        n.SetStyle(YAML::EmitterStyle::Flow);
        return n;
    };
    YAML::Node res;
    res.push_back(projector.width);
    res.push_back(projector.height);
    res.SetStyle(YAML::EmitterStyle::Flow);
    p["resolution"] = res;
    p["fov_deg"] = seq({projector.fov_h / kDeg, projector.fov_v / kDeg});
    const Eigen::Vector3d &o = projector.origin;
    const Eigen::Vector3d d = projector.direction.normalized();
    p["axis"]["origin"] = seq({o.x(), o.y(), o.z()});
    p["axis"]["direction"] = seq({d.x(), d.y(), d.z()});
    if (projector.fullModel()) {  // the contract's optional keys; fov_deg then follows from them
        const auto fov = fieldOfView(projector);
        p["fov_deg"] = seq({fov[0] / kDeg, fov[1] / kDeg});
        const Eigen::Vector3d a = projector.axis();
        p["axis"]["direction"] = seq({a.x(), a.y(), a.z()});
        p["intrinsics"]["fx"] = projector.fx();
        p["intrinsics"]["fy"] = projector.fy();
        p["intrinsics"]["cx"] = projector.cx();
        p["intrinsics"]["cy"] = projector.cy();
        const auto &k = projector.distortion;
        p["distortion"] = seq({k[0], k[1], k[2], k[3], k[4]});
        const Eigen::Matrix3d R = projector.rotation
                                      ? *projector.rotation
                                      : (Eigen::Matrix3d() << projector.right(), projector.down(), a).finished();
        for (int i = 0; i < 3; ++i) p["rotation"].push_back(seq({R(i, 0), R(i, 1), R(i, 2)}));
    }
    return p;
}

void writeCalibration(const std::string &path, const Projector &projector) {
    YAML::Node root;
    root["projector"] = calibrationNode(projector);
    writeFileAtomic(path, calibrationYamlText(path, root));
}

namespace {

/// A ROS camera_info YAML (camera_calibration's format) as intrinsics.
CameraIntrinsics rosCameraInfo(const std::string &path, const YAML::Node &root) {
    CameraIntrinsics cam;
    const double w = number(path, child(path, root, "image_width", ""), "image_width");
    const double h = number(path, child(path, root, "image_height", ""), "image_height");
    if (w < 1 || h < 1 || w > limits::kMaxCameraSide || h > limits::kMaxCameraSide || w != std::floor(w) || h != std::floor(h))
        throw InputError(path, "image_width and image_height must be positive whole numbers");
    cam.width = static_cast<int>(w);
    cam.height = static_cast<int>(h);
    const auto k = numbers(path, child(path, child(path, root, "camera_matrix", ""), "data", "camera_matrix."),
                           "camera_matrix.data", 9);
    cam.fx = k[0];
    cam.fy = k[4];
    cam.cx = k[2];
    cam.cy = k[5];
    if (root["distortion_coefficients"] && root["distortion_coefficients"]["data"]) {
        const YAML::Node d = root["distortion_coefficients"]["data"];
        if (!d.IsSequence()) throw InputError(path, "'distortion_coefficients.data' must be a list of numbers");
        for (std::size_t i = 0; i < d.size(); ++i)
            if (number(path, d[i], "distortion_coefficients.data") != 0.0)
                throw InputError(path,
                                 "camera_info has non-zero distortion_coefficients; projsurf reads rectified "
                                 "(pinhole) depth: give the camera_info of the rectified image (image_rect, "
                                 "all-zero D) or rectify first");
    }
    cam.depth_scale = 1000.0;  // 16UC1 depth is in millimetres (REP 118)
    return cam;
}

}  // namespace

CameraIntrinsics readCamera(const std::string &path, std::vector<std::string> *warnings) {
    const YAML::Node root = loadYaml(path);
    CameraIntrinsics cam;
    if (!root["camera"] && root["camera_matrix"]) {
        cam = rosCameraInfo(path, root);
        UnknownKeys unknown{path, warnings};
        unknown.note(root, "",
                     {"image_width", "image_height", "camera_name", "camera_matrix", "distortion_model",
                      "distortion_coefficients", "rectification_matrix", "projection_matrix"});
        unknown.finish();
    } else {
        if (!root["camera"] && root["projector"])
            throw InputError(path,
                             "is a projector calibration (projector:), not camera intrinsics (camera:); "
                             "--camera and --calib swapped?");
        const YAML::Node c = child(path, root, "camera", "");
        const double w = number(path, child(path, c, "width", "camera."), "camera.width");
        const double h = number(path, child(path, c, "height", "camera."), "camera.height");
        if (w < 1 || h < 1 || w > limits::kMaxCameraSide || h > limits::kMaxCameraSide || w != std::floor(w) || h != std::floor(h))
            throw InputError(path, "camera.width and camera.height must be positive whole numbers");
        cam.width = static_cast<int>(w);
        cam.height = static_cast<int>(h);
        cam.fx = number(path, child(path, c, "fx", "camera."), "camera.fx");
        cam.fy = number(path, child(path, c, "fy", "camera."), "camera.fy");
        cam.cx = number(path, child(path, c, "cx", "camera."), "camera.cx");
        cam.cy = number(path, child(path, c, "cy", "camera."), "camera.cy");
        cam.depth_scale = c["depth_scale"] ? number(path, c["depth_scale"], "camera.depth_scale") : 1000.0;
        UnknownKeys unknown{path, warnings};
        unknown.note(root, "", {"camera"});
        unknown.note(c, "camera.", {"width", "height", "fx", "fy", "cx", "cy", "depth_scale"});
        unknown.finish();
    }
    if (static_cast<double>(cam.width) * cam.height > static_cast<double>(limits::kMaxDepthPixels))
        throw InputError(path, "camera image of " + std::to_string(cam.width) + " x " + std::to_string(cam.height) +
                                   " pixels exceeds the limit of " + std::to_string(limits::kMaxDepthPixels) +
                                   " pixels");
    if (!(cam.fx > 0 && cam.fy > 0)) throw InputError(path, "camera.fx and camera.fy must be positive");
    if (!(cam.depth_scale > 0)) throw InputError(path, "camera.depth_scale must be positive");
    if (const std::string problem = cameraModelProblem(cam); !problem.empty()) throw InputError(path, problem);
    return cam;
}

void writeCamera(const std::string &path, const CameraIntrinsics &cam) {
    YAML::Node root;
    root["camera"]["width"] = cam.width;
    root["camera"]["height"] = cam.height;
    root["camera"]["fx"] = cam.fx;
    root["camera"]["fy"] = cam.fy;
    root["camera"]["cx"] = cam.cx;
    root["camera"]["cy"] = cam.cy;
    root["camera"]["depth_scale"] = cam.depth_scale;
    YAML::Emitter out;
    out << root;
    writeFileAtomic(path, std::string(out.c_str()) + "\n");
}

}  // namespace projsurf
