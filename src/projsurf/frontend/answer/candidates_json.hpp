#pragma once
// `--explain`'s answer: every vertical plane a detection considered, its size and distance, and
// why it lost, as the JSON key `candidates` (detect --json, the node's result, Python's dict)
// and as lines for a terminal.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "projsurf/detection/detection.hpp"

namespace projsurf::frontend {

/// The JSON key `candidates`: one object per plane considered, in the order they were found
/// (docs/interface.md, "Why the picture is where it is").
nlohmann::json candidatesToJson(const Detection &det);

/// One line per candidate for a terminal: "candidate 2: 3.12 m away, seen 2.40 x 1.10 m: shadowed ...".
std::vector<std::string> candidateLines(const Detection &det);

}  // namespace projsurf::frontend
