#include "projsurf/frontend/answer/detect_answer.hpp"

#include <opencv2/core.hpp>

#include "projsurf/io/files/errors.hpp"

namespace projsurf::frontend {

Detection detectAnswer(SurfaceDetector &detector, const Cloud &cloud, const Eigen::Vector3d &gravity,
                       const MinimumSize &minimum, const std::string &source, const std::string &width_option,
                       const std::string &area_option) {
    Detection det;
    try {
        det = detector.detect(cloud, gravity);
    } catch (const cv::Exception &e) {
        throw InputError(source, "cannot be processed (" + e.func + ": " + e.err + ")");
    }
    enforceMinimumSize(det, minimum, width_option, area_option);
    return det;
}

GravityDetection detectWithGravity(SurfaceDetector &detector, const Cloud &cloud, const GravityChoice &choice,
                                   const MinimumSize &minimum, const std::string &source,
                                   const std::string &width_option, const std::string &area_option) {
    GravityDetection out;
    out.gravity = resolveGravity(choice, cloud);
    out.detection = detectAnswer(detector, cloud, out.gravity.gravity, minimum, source, width_option, area_option);
    return out;
}

}  // namespace projsurf::frontend
