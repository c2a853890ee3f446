#pragma once
// The contract's detection JSON (`detect --json`) and its reader (`correct --detection`).
#include <nlohmann/json.hpp>
#include <string>

#include "projsurf/detector/detector.hpp"

namespace projsurf {

/// The contract's keys (found, reason, plane, rectangle, surface_check, timing_ms) plus
/// extensions (method, gravity, plane.yaw). With the projector, also the contract's `focus`
/// (people/focus.hpp; null when there is no rectangle).
nlohmann::json detectionToJson(const Detection &detection, const DetectorConfig &config,
                               const Projector *projector = nullptr);

/// A rectangle as the contract writes `rectangle`: corners (TL, TR, BR, BL; camera frame, m),
/// width_m, height_m, area_m2; null when it has no area.
nlohmann::json rectangleToJson(const Rectangle &rect);
/// The dotted key of the first number in `j` that is not finite (nlohmann writes NaN and
/// infinity as null), "" when every number is finite: what a writer checks before it writes.
std::string nonFiniteJsonKey(const nlohmann::json &j, const std::string &prefix = "");

/// What `correct` needs from a detection file.
struct DetectionFile {
    bool found = false;
    std::string reason;
    Plane plane;
    Rectangle rectangle;
};

/// Reads and validates a detection JSON; throws InputError naming the file and the problem
/// (missing keys, found: false, corners not a proper rectangle).
DetectionFile readDetectionJson(const std::string &path);

}  // namespace projsurf
