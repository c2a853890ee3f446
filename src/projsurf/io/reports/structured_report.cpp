#include "projsurf/io/reports/structured_report.hpp"

#include <yaml-cpp/yaml.h>

#include "projsurf/io/files/files.hpp"
#include "projsurf/io/yaml/fit_quality_yaml.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf {

void writeStructuredCalibration(const std::string &path, const ProjectorFit &fit, const std::string &captures_dir,
                                int poses, const std::string &created_utc) {
    YAML::Node root;
    root["projector"] = calibrationNode(fit.projector);
    YAML::Node r = root["projector"]["residuals"];
    r["method"] = "structured_light";
    r["reprojection_rms_px"] = fit.rms_px;
    r["reprojection_max_px"] = fit.max_px;
    r["points"] = static_cast<int>(fit.points);
    r["inliers"] = static_cast<int>(fit.inliers);
    r["framebuffer_coverage"] = fit.coverage;
    r["relief_m"] = fit.relief_m;
    r["distortion_terms"] = fit.distortion_terms;
    r["convergence"] = convergenceNode(fit.convergence);
    r["spread"] = spreadNode(fit.spread);
    root["projector"]["captures"]["dir"] = captures_dir;
    root["projector"]["captures"]["poses"] = poses;
    root["projector"]["created_utc"] = created_utc;
    writeFileAtomic(path, calibrationYamlText(path, root));  // read back as every reader reads it first
}

}  // namespace projsurf
