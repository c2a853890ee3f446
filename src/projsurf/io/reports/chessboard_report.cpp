#include "projsurf/io/reports/chessboard_report.hpp"

#include <yaml-cpp/yaml.h>

#include "projsurf/io/files/files.hpp"
#include "projsurf/io/yaml/fit_quality_yaml.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf {

void writeChessboardCalibration(const std::string &path, const StereoFit &fit, int width, int height,
                                const ChessboardReport &report) {
    YAML::Node root;
    root["projector"] = calibrationNode(stereoProjector(fit, width, height));
    YAML::Node r = root["projector"]["residuals"];
    r["method"] = "chessboard_structured_light";
    r["reprojection_rms_px"] = fit.rms_px;
    r["camera_rms_px"] = fit.camera.rms_px;
    r["projector_rms_px"] = fit.projector.rms_px;
    r["views"] = static_cast<int>(fit.views);
    r["corners"] = static_cast<int>(fit.points);
    r["decoded_board_share"] = report.decoded_board_share;
    r["convergence"] = convergenceNode(fit.convergence);
    r["spread"] = spreadNode(fit.spread);
    YAML::Node cam = root["projector"]["camera"];
    cam["fx"] = fit.camera.fx;
    cam["fy"] = fit.camera.fy;
    cam["cx"] = fit.camera.cx;
    cam["cy"] = fit.camera.cy;
    for (double d : fit.camera.distortion) cam["distortion"].push_back(d);
    cam["distortion"].SetStyle(YAML::EmitterStyle::Flow);
    root["projector"]["captures"]["dir"] = report.captures_dir;
    root["projector"]["captures"]["poses"] = report.poses;
    root["projector"]["captures"]["square_m"] = report.square_m;
    root["projector"]["created_utc"] = report.created_utc;
    writeFileAtomic(path, calibrationYamlText(path, root));  // read back as every reader reads it first
}

}  // namespace projsurf
