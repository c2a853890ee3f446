#pragma once
// The one serialiser of a detection for every front end: `detect --json` (and --bag's lines),
// the node's ~result and ~continuous messages, and Python's dict (which converts this tree).
#include <nlohmann/json.hpp>

#include "projsurf/detector/detector.hpp"

namespace projsurf::frontend {

/// The contract's detection JSON (io/formats/detection_json.hpp, with the projector's `focus`) and,
/// with `explain`, the `candidates` list (frontend/answer/candidates_json.hpp).
nlohmann::json detectionDocument(const Detection &det, const DetectorConfig &config, const Projector &projector,
                                 bool explain);

}  // namespace projsurf::frontend
