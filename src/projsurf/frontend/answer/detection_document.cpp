#include "projsurf/frontend/answer/detection_document.hpp"

#include "projsurf/frontend/answer/candidates_json.hpp"
#include "projsurf/io/formats/detection_json.hpp"

namespace projsurf::frontend {

nlohmann::json detectionDocument(const Detection &det, const DetectorConfig &config, const Projector &projector,
                                 bool explain) {
    nlohmann::json j = detectionToJson(det, config, &projector);
    if (explain) j["candidates"] = candidatesToJson(det);
    return j;
}

}  // namespace projsurf::frontend
