#include "projsurf/frontend/answer/continuous_json.hpp"

#include "projsurf/io/formats/detection_json.hpp"

namespace projsurf::frontend {

void addContinuousFrame(nlohmann::json &document, const ContinuousFrame &frame) {
    document["shown"] = frame.has_target ? rectangleToJson(frame.shown) : nlohmann::json(nullptr);
    document["event"] = toString(frame.event);
}

}  // namespace projsurf::frontend
