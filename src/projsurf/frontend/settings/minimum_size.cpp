#include "projsurf/frontend/settings/minimum_size.hpp"

#include "projsurf/types/formatted.hpp"

namespace projsurf::frontend {

MinimumSize defaultMinimumSize(Method method) {
    if (method == Method::Paper) return MinimumSize{0.0, 0.0};
    return MinimumSize{};
}

namespace {

/// m: a rectangle this much under the minimum is the minimum, rounded (a width of 15 raster
/// cells computes as 0.15 - 1e-10 m).
constexpr double kRounding = 1e-6;

}  // namespace

std::string belowMinimum(const Rectangle &r, const MinimumSize &minimum, const std::string &subject,
                         const std::string &width_option, const std::string &area_option) {
    if (r.width < minimum.width - kRounding) {
        const auto [width, limit] = limitPair(r.width, minimum.width);
        return subject + ", " + width + " x " + formatted("%.3f", r.height) + " m, is narrower than " + width_option +
               " " + limit + " m";
    }
    if (r.area() < minimum.area - kRounding * kRounding) {
        const auto [area, limit] = limitPair(r.area(), minimum.area, 4);
        return subject + ", " + formatted("%.3f", r.width) + " x " + formatted("%.3f", r.height) + " m (" + area +
               " m^2), is smaller than " + area_option + " " + limit + " m^2";
    }
    return "";
}

bool enforceMinimumSize(Detection &det, const MinimumSize &minimum, const std::string &width_option,
                        const std::string &area_option) {
    for (CandidateOutcome &o : det.candidates) {
        if (o.verdict != CandidateVerdict::Chosen && o.verdict != CandidateVerdict::SmallerRectangle) continue;
        const std::string why = belowMinimum(o.rectangle, minimum, "its rectangle", width_option, area_option);
        if (why.empty()) continue;
        o.verdict = CandidateVerdict::TooSmall;
        o.detail = "too small: " + why;
    }
    if (!det.found) return false;
    const std::string why = belowMinimum(det.rectangle, minimum, "the largest area", width_option, area_option);
    if (why.empty()) return false;
    det.found = false;
    det.reason = why;
    return true;
}

}  // namespace projsurf::frontend
