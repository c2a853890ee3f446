#include "projsurf/frontend/settings/suitability_mode.hpp"

#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

SuitabilityMode parseSuitabilityMode(const std::string &what, const std::string &word) {
    if (word == "off") return SuitabilityMode::Off;
    if (word == "avoid" || word.empty()) return SuitabilityMode::Avoid;
    if (word == "prefer") return SuitabilityMode::Prefer;
    throw InputError(what, "expected 'off', 'avoid' or 'prefer', got '" + word + "'");
}

}  // namespace projsurf::frontend
