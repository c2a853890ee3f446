#include "projsurf/frontend/answer/candidates_json.hpp"

#include <cmath>

#include "projsurf/types/formatted.hpp"

namespace projsurf::frontend {
namespace {

double round6(double v) { return std::round(v * 1e6) / 1e6; }

nlohmann::json vec(const Eigen::Vector3d &v) {
    return nlohmann::json::array({round6(v.x()), round6(v.y()), round6(v.z())});
}

/// The JSON names of the cell states, in CellState order.
constexpr const char *kCellNames[kCellStates] = {"free",  "no_reading", "seen_through", "shadowed",  "edge",
                                                 "glare", "too_dark",   "textured",     "saturated", "proud"};

nlohmann::json candidateJson(const CandidateOutcome &o, const Rectangle &winner) {
    nlohmann::json j;
    j["verdict"] = outcomeName(o);
    j["reason"] = outcomeWords(o, winner);
    j["distance_m"] = round6(std::abs(o.plane.d));
    j["normal"] = vec(o.plane.normal);
    j["inliers"] = o.inliers;
    nlohmann::json corners = nlohmann::json::array();
    for (const auto &c : o.seen) corners.push_back(vec(c));
    j["seen"] = {{"width_m", round6(o.seen_width)}, {"height_m", round6(o.seen_height)}, {"corners", corners}};
    if (o.rectangle.area() > 0.0)
        j["rectangle"] = {{"width_m", round6(o.rectangle.width)},
                          {"height_m", round6(o.rectangle.height)},
                          {"area_m2", round6(o.rectangle.area())}};
    else
        j["rectangle"] = nullptr;
    double counted = 0.0;
    for (double s : o.beam_cells) counted += s;
    if (counted > 0.0) {
        nlohmann::json cells;
        for (int s = 0; s < kCellStates; ++s) cells[kCellNames[s]] = std::round(o.beam_cells[s] * 1000.0) / 1000.0;
        j["beam_cells"] = cells;
    }
    return j;
}

}  // namespace

nlohmann::json candidatesToJson(const Detection &det) {
    const Rectangle winner = winningRectangle(det.candidates, det.rectangle);
    nlohmann::json list = nlohmann::json::array();
    for (const CandidateOutcome &o : det.candidates) list.push_back(candidateJson(o, winner));
    return list;
}

std::vector<std::string> candidateLines(const Detection &det) {
    const Rectangle winner = winningRectangle(det.candidates, det.rectangle);
    std::vector<std::string> lines;
    for (std::size_t k = 0; k < det.candidates.size(); ++k) {
        const CandidateOutcome &o = det.candidates[k];
        lines.push_back("candidate " + std::to_string(k + 1) + ": " + formatted("%.2f m away", std::abs(o.plane.d)) +
                        ", seen " + formatted("%.2f", o.seen_width) + " x " + formatted("%.2f m", o.seen_height) +
                        ": " + outcomeWords(o, winner));
    }
    return lines;
}

}  // namespace projsurf::frontend
