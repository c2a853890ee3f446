#include "projsurf/io/formats/detection_json.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "projsurf/detection/method_names.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/people/focus.hpp"

namespace projsurf {
namespace {

nlohmann::json vec(const Eigen::Vector3d &v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

double round6(double v) { return std::round(v * 1e6) / 1e6; }

}  // namespace

nlohmann::json rectangleToJson(const Rectangle &rect) {
    if (!(rect.area() > 0.0)) return nullptr;
    nlohmann::json corners = nlohmann::json::array();
    for (const auto &c : rect.corners) corners.push_back(vec(c));
    return {{"corners", corners},
            {"width_m", round6(rect.width)},
            {"height_m", round6(rect.height)},
            {"area_m2", round6(rect.area())}};
}

nlohmann::json detectionToJson(const Detection &det, const DetectorConfig &config, const Projector *projector) {
    nlohmann::json j;
    j["found"] = det.found;
    j["reason"] = det.found ? nlohmann::json(nullptr) : nlohmann::json(det.reason);
    j["method"] = methodName(config.method);
    if (det.inliers > 0) {
        const auto c = det.plane.coefficients();
        j["plane"] = {{"coefficients", {c[0], c[1], c[2], c[3]}},
                      {"orientation_deg", round6(det.orientation_deg)},
                      {"inliers", det.inliers}};
    } else {
        j["plane"] = nullptr;
    }
    j["rectangle"] = rectangleToJson(det.rectangle);
    j["surface_check"] = {{"points", det.surface_check.points},
                          {"outliers", det.surface_check.outliers},
                          {"accepted", det.surface_check.accepted}};
    if (det.suitability.used) {
        auto r3 = [](double v) { return std::round(v * 1000.0) / 1000.0; };
        j["suitability"] = {{"mode", det.suitability.mode},
                            {"mean_albedo", r3(det.suitability.mean_albedo)},
                            {"texture", r3(det.suitability.texture)},
                            {"unsuitable_share", r3(det.suitability.unsuitable_share)},
                            {"wall_luminance", r3(det.suitability.wall_luminance)}};
    }
    nlohmann::json timing = nlohmann::json::object();
    for (const auto &[k, v] : det.timing_ms) timing[k] = std::round(v * 1000.0) / 1000.0;
    j["timing_ms"] = timing;
    j["gravity"] = vec(det.gravity);
    if (projector) {
        if (det.rectangle.area() > 0.0) {
            const Focus f = focusFor(*projector, det.rectangle);
            j["focus"] = {{"distance_m", round6(f.distance_m)},
                          {"nearest_m", round6(f.nearest_m)},
                          {"farthest_m", round6(f.farthest_m)}};
        } else {
            j["focus"] = nullptr;
        }
    }
    return j;
}

namespace {

/// A detection file that is not JSON at all: what it looks like instead, so a swapped or wrong
/// file is named as such rather than by the parser's complaint.
void requireJsonText(const std::string &path, const std::string &text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '{') return;
    const bool yaml = text.find("projector:") != std::string::npos || text.find("camera:") != std::string::npos ||
                      text.find("image_width:") != std::string::npos;
    if (yaml)
        throw InputError(path,
                         "is a YAML file (a calibration or camera file), not the detection JSON that "
                         "`projsurf detect --json` writes; --detection and --calib swapped?");
    if (first != std::string::npos && text[first] != '[')
        throw InputError(path,
                         "is not JSON (it does not begin with '{'): give the detection JSON that "
                         "`projsurf detect --json` writes");
}

}  // namespace

DetectionFile readDetectionJson(const std::string &path) {
    const std::string text = readSmallTextFile(path, limits::kMaxJsonBytes, "JSON");
    requireJsonText(path, text);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception &e) {
        throw InputError(path, std::string("malformed JSON: ") + e.what());
    }
    DetectionFile out;
    try {
        if (!j.is_object() || !j.contains("found") || !j["found"].is_boolean())
            throw InputError(path, "missing boolean key 'found'");
        out.found = j["found"].get<bool>();
        if (!out.found) {
            out.reason = j.contains("reason") && j["reason"].is_string() ? j["reason"].get<std::string>() : "";
            throw InputError(path, "the detection found no surface" +
                                       (out.reason.empty() ? std::string() : " (" + out.reason + ")"));
        }
        const auto &rect = j.at("rectangle");
        const auto &corners = rect.at("corners");
        if (!corners.is_array() || corners.size() != 4)
            throw InputError(path, "'rectangle.corners' must hold 4 points");
        for (int i = 0; i < 4; ++i) {
            const auto &c = corners[i];
            if (!c.is_array() || c.size() != 3)
                throw InputError(path, "'rectangle.corners' must hold [x, y, z] points");
            for (int k = 0; k < 3; ++k) {
                if (!c[k].is_number()) throw InputError(path, "'rectangle.corners' holds a non-number");
                out.rectangle.corners[i][k] = c[k].get<double>();
            }
            if (!out.rectangle.corners[i].allFinite()) throw InputError(path, "'rectangle.corners' is not finite");
            if (out.rectangle.corners[i].norm() > limits::kMaxDetectionDistanceM)
                throw InputError(path,
                                 "'rectangle.corners' lie more than 1000 m from the camera: give them in metres "
                                 "(millimetres?)");
            if (!(out.rectangle.corners[i].z() > 0))
                throw InputError(path,
                                 "'rectangle.corners' lie behind the camera (z <= 0): a detection is on a "
                                 "surface the camera saw, in the camera's optical frame");
        }
        if (j.contains("plane") && j["plane"].is_object() && j["plane"].contains("coefficients")) {
            const auto &pc = j["plane"]["coefficients"];
            if (pc.is_array() && pc.size() == 4 && pc[0].is_number() && pc[1].is_number() && pc[2].is_number() &&
                pc[3].is_number())
                out.plane = makePlane(Eigen::Vector3d(pc[0].get<double>(), pc[1].get<double>(), pc[2].get<double>()),
                                      pc[3].get<double>());
        }
    } catch (const nlohmann::json::exception &e) {
        throw InputError(path, std::string("unexpected content: ") + e.what());
    }
    const auto &c = out.rectangle.corners;
    out.rectangle.width = (c[1] - c[0]).norm();
    out.rectangle.height = (c[3] - c[0]).norm();
    const double w2 = (c[2] - c[3]).norm(), h2 = (c[2] - c[1]).norm();
    if (!(out.rectangle.width > 1e-6 && out.rectangle.height > 1e-6))
        throw InputError(path, "'rectangle.corners' do not span a rectangle");
    const double tol = 1e-3 * std::max(out.rectangle.width, out.rectangle.height) + 1e-6;
    if (std::abs(w2 - out.rectangle.width) > tol || std::abs(h2 - out.rectangle.height) > tol ||
        std::abs((c[1] - c[0]).normalized().dot((c[3] - c[0]).normalized())) > 1e-3)
        throw InputError(path, "'rectangle.corners' are not the corners of a rectangle (TL, TR, BR, BL)");
    return out;
}

std::string nonFiniteJsonKey(const nlohmann::json &j, const std::string &prefix) {
    if (j.is_number_float()) return std::isfinite(j.get<double>()) ? "" : (prefix.empty() ? "(top)" : prefix);
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            const std::string k = nonFiniteJsonKey(*it, prefix.empty() ? it.key() : prefix + "." + it.key());
            if (!k.empty()) return k;
        }
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) {
            const std::string k = nonFiniteJsonKey(j[i], prefix + "[" + std::to_string(i) + "]");
            if (!k.empty()) return k;
        }
    }
    return "";
}

}  // namespace projsurf
