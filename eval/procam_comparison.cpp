#include "eval/procam_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "projsurf/io/detection_json.hpp"
#include "projsurf/io/errors.hpp"

namespace projsurf::eval {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::string line(const char *format, double a, double b, double c) {
    char buf[200];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

nlohmann::json matrixJson(const Eigen::Matrix3d &m) {
    nlohmann::json out = nlohmann::json::array();
    for (int r = 0; r < 3; ++r) out.push_back({m(r, 0), m(r, 1), m(r, 2)});
    return out;
}

Eigen::Matrix3d rotationOf(const StereoFit &f) {
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = f.rotation(i, j);
    return r;
}

Eigen::Vector3d translationOf(const StereoFit &f) { return {f.translation[0], f.translation[1], f.translation[2]}; }

}  // namespace

ProcamComparison compareProcam(const StereoFit &o, const PublishedProcam &p, double unit_m) {
    ProcamComparison c;
    c.fx_pct = 100 * (o.projector.fx - p.proj_fx) / p.proj_fx;
    c.fy_pct = 100 * (o.projector.fy - p.proj_fy) / p.proj_fy;
    c.cx_px = o.projector.cx - p.proj_cx;
    c.cy_px = o.projector.cy - p.proj_cy;
    const Eigen::Matrix3d d = rotationOf(o) * p.rotation.transpose();
    c.rotation_deg = std::acos(std::clamp(0.5 * (d.trace() - 1), -1.0, 1.0)) * kDeg;
    const Eigen::Vector3d tp = p.translation * unit_m;
    const Eigen::Vector3d to = translationOf(o);
    c.translation_dir_deg = std::acos(std::clamp(to.normalized().dot(tp.normalized()), -1.0, 1.0)) * kDeg;
    c.translation_ratio = to.norm() / tp.norm();
    return c;
}

std::string procamTable(const StereoFit &o, const PublishedProcam &p, const ProcamComparison &c, double unit_m,
                        double square_m, double share) {
    std::string s = "| | ours | published | difference |\n|---|---:|---:|---:|\n";
    s += line("| projector fx (px) | %.1f | %.1f | %+.2f %% |\n", o.projector.fx, p.proj_fx, c.fx_pct);
    s += line("| projector fy (px) | %.1f | %.1f | %+.2f %% |\n", o.projector.fy, p.proj_fy, c.fy_pct);
    s += line("| projector cx (px) | %.1f ± %.1f | %.1f |", o.projector.cx, o.projector.sigma[2], p.proj_cx);
    s += line(" %+.1f px |\n", c.cx_px, 0, 0);
    s += line("| projector cy (px) | %.1f ± %.1f | %.1f |", o.projector.cy, o.projector.sigma[3], p.proj_cy);
    s += line(" %+.1f px |\n", c.cy_px, 0, 0);
    s += line("| camera fx (px) | %.1f | %.1f | %+.2f %% |\n", o.camera.fx, p.cam_fx,
              100 * (o.camera.fx - p.cam_fx) / p.cam_fx);
    s += line("| camera fy (px) | %.1f | %.1f | %+.2f %% |\n", o.camera.fy, p.cam_fy,
              100 * (o.camera.fy - p.cam_fy) / p.cam_fy);
    s += line("| camera cx (px) | %.1f | %.1f | %+.1f px |\n", o.camera.cx, p.cam_cx, o.camera.cx - p.cam_cx);
    s += line("| camera cy (px) | %.1f | %.1f | %+.1f px |\n", o.camera.cy, p.cam_cy, o.camera.cy - p.cam_cy);
    s += line("| rotation | | | %.2f deg |\n", c.rotation_deg, 0, 0);
    const Eigen::Vector3d tp = p.translation * unit_m;
    const Eigen::Vector3d to = translationOf(o);
    s += line("| translation (m) | [%.4f, %.4f, %.4f] |", to.x(), to.y(), to.z());
    s += line(" [%.4f, %.4f, %.4f] |", tp.x(), tp.y(), tp.z());
    s += line(" %.2f deg, length x %.3f |\n", c.translation_dir_deg, c.translation_ratio, 0);
    s += line("| stereo reprojection RMS (px) | %.3f | %.3f | |\n", o.rms_px, p.rms, 0);
    s += line("\n± one standard deviation of the projector's own fit (its covariance); ", 0, 0, 0);
    s += line("square %.4f m; %.0f views, %.0f corners; ", square_m, static_cast<double>(o.views),
              static_cast<double>(o.points));
    s += line("camera RMS %.3f px, projector RMS %.3f px; decoded share of the board %.1f %%\n", o.camera.rms_px,
              o.projector.rms_px, 100 * share);
    return s;
}

std::string procamJson(const std::string &path, const StereoFit &o, const PublishedProcam &p,
                       const ProcamComparison &c, double unit_m, double square_m, double share,
                       const std::vector<double> &pose_shares) {
    nlohmann::json j;
    j["projector"] = {{"fx", o.projector.fx},
                      {"fy", o.projector.fy},
                      {"cx", o.projector.cx},
                      {"cy", o.projector.cy},
                      {"distortion", o.projector.distortion},
                      {"sigma",
                       {{"fx", o.projector.sigma[0]},
                        {"fy", o.projector.sigma[1]},
                        {"cx", o.projector.sigma[2]},
                        {"cy", o.projector.sigma[3]}}}};
    j["camera"] = {{"fx", o.camera.fx},
                   {"fy", o.camera.fy},
                   {"cx", o.camera.cx},
                   {"cy", o.camera.cy},
                   {"distortion", o.camera.distortion}};
    j["rotation"] = matrixJson(rotationOf(o));
    j["translation"] = {o.translation[0], o.translation[1], o.translation[2]};
    j["square_m"] = square_m;
    j["reprojection_rms_px"] = o.rms_px;
    j["camera_rms_px"] = o.camera.rms_px;
    j["projector_rms_px"] = o.projector.rms_px;
    j["decoded_board_share"] = share;
    j["decoded_board_share_per_pose"] = pose_shares;
    const Eigen::Vector3d tp = p.translation * unit_m;
    j["published"] = {
        {"projector",
         {{"fx", p.proj_fx},
          {"fy", p.proj_fy},
          {"cx", p.proj_cx},
          {"cy", p.proj_cy},
          {"distortion", p.proj_distortion}}},
        {"camera",
         {{"fx", p.cam_fx}, {"fy", p.cam_fy}, {"cx", p.cam_cx}, {"cy", p.cam_cy}, {"distortion", p.cam_distortion}}},
        {"rotation", matrixJson(p.rotation)},
        {"translation", {tp.x(), tp.y(), tp.z()}},
        {"reprojection_rms_px", p.rms}};
    j["difference"] = {{"projector_fx_pct", c.fx_pct},
                       {"projector_fy_pct", c.fy_pct},
                       {"projector_cx_px", c.cx_px},
                       {"projector_cy_px", c.cy_px},
                       {"rotation_deg", c.rotation_deg},
                       {"translation_direction_deg", c.translation_dir_deg},
                       {"translation_length_ratio", c.translation_ratio}};
    // Never a null where a number belongs (a fit or a comparison that came out NaN).
    if (const std::string key = nonFiniteJsonKey(j); !key.empty())
        throw InputError(path, "'" + key + "' is not finite (the fit or the published calibration is degenerate): "
                                           "nothing written");
    return j.dump(2) + "\n";
}

}  // namespace projsurf::eval
