#pragma once
// The one table of the words for the detection method ("default", "paper") and the paper
// method's hull ("concave", "convex"): what the JSON, the overlay and every front end write,
// and what they read (frontend/settings/method_words.hpp adds the error a user sees).
#include <string_view>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf {

const char *methodName(Method method);
const char *hullName(HullKind hull);

/// The method or hull a word names; false (and `out` unchanged) for any other word.
bool methodFromName(std::string_view word, Method &out);
bool hullFromName(std::string_view word, HullKind &out);

}  // namespace projsurf
