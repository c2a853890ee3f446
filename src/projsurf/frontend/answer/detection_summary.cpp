#include "projsurf/frontend/answer/detection_summary.hpp"

#include <cstdio>

namespace projsurf::frontend {

std::string detectionSummary(const Detection &det) {
    if (!det.found)
        return "not found: " + (det.reason.empty() ? std::string("no projection surface found") : det.reason);
    const auto total = det.timing_ms.find("total");
    char buf[256];
    std::snprintf(buf, sizeof buf, "found %.2f x %.2f m (%.2f m^2) on a plane %.2f m away at %.1f deg in %.1f ms",
                  det.rectangle.width, det.rectangle.height, det.rectangle.area(), det.plane.d, det.orientation_deg,
                  total != det.timing_ms.end() ? total->second : 0.0);
    return buf;
}

}  // namespace projsurf::frontend
