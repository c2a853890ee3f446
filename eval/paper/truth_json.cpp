#include "eval/paper/truth_json.hpp"

#include "projsurf/io/files/files.hpp"
#include "projsurf/types/plane.hpp"

namespace projsurf::eval {
namespace {

nlohmann::json vec(const Eigen::Vector3d &v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json planeJson(const Plane &plane) {
    const auto c = plane.coefficients();
    return {{"coefficients", {c[0], c[1], c[2], c[3]}}, {"orientation_deg", orientationDeg(plane)}};
}

}  // namespace

nlohmann::json truthToJson(const sim::GroundTruth &truth, const sim::Scenario &scenario, unsigned seed, bool noise) {
    nlohmann::json j;
    j["found"] = truth.found;
    j["aspect"] = truth.aspect;
    j["cell_m"] = truth.best.cell;
    j["scenario"] = {{"name", scenario.name},
                     {"description", scenario.description},
                     {"distance_m", scenario.distance},
                     {"angle_deg", scenario.angle_deg},
                     {"roll_deg", scenario.roll_deg},
                     {"pitch_deg", scenario.pitch_deg},
                     {"gravity", vec(scenario.gravity)},
                     {"seed", seed},
                     {"noise", noise}};
    if (truth.found) {
        const sim::SurfaceTruth &b = truth.best;
        j["plane"] = planeJson(b.plane);
        j["plane"]["surface"] = b.label;
        nlohmann::json corners = nlohmann::json::array();
        for (const auto &c : b.rectangle.corners) corners.push_back(vec(c));
        j["rectangle"] = {{"corners", corners},
                          {"width_m", b.rectangle.width},
                          {"height_m", b.rectangle.height},
                          {"area_m2", b.rectangle.area()}};
        if (b.has_footprint) {
            nlohmann::json f = nlohmann::json::array();
            for (const auto &c : b.footprint) f.push_back(vec(c));
            j["footprint"] = f;
        } else {
            j["footprint"] = nullptr;
        }
    } else {
        j["plane"] = nullptr;
        j["rectangle"] = nullptr;
        j["footprint"] = nullptr;
    }
    j["wall_plane"] = planeJson(scenario.wall);
    nlohmann::json surfaces = nlohmann::json::array();
    for (const auto &s : truth.surfaces) {
        const auto c = s.plane.coefficients();
        surfaces.push_back({{"surface", s.label},
                            {"coefficients", {c[0], c[1], c[2], c[3]}},
                            {"found", s.found},
                            {"area_m2", s.found ? s.rectangle.area() : 0.0},
                            {"free_area_m2", s.free_area}});
    }
    j["surfaces"] = surfaces;
    return j;
}

void writeTruthJson(const std::string &path, const sim::GroundTruth &truth, const sim::Scenario &scenario,
                    unsigned seed, bool noise) {
    writeFileAtomic(path, truthToJson(truth, scenario, seed, noise).dump(2) + "\n");
}

}  // namespace projsurf::eval
