#include "eval/procam/procam_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/formats/detection_json.hpp"

namespace projsurf::eval {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::string line(const char *format, double a = 0, double b = 0, double c = 0, double d = 0) {
    char buf[300];
    std::snprintf(buf, sizeof buf, format, a, b, c, d);
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

nlohmann::json fitJson(const StereoFit &o) {
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
    j["reprojection_rms_px"] = o.rms_px;
    j["camera_rms_px"] = o.camera.rms_px;
    j["projector_rms_px"] = o.projector.rms_px;
    nlohmann::json conv = nlohmann::json::array();
    for (const auto &c : o.convergence)
        conv.push_back({{"fit", c.fit},
                        {"iterations", c.iterations},
                        {"cap", c.cap},
                        {"last_step", c.last_step},
                        {"last_step_px", c.last_step_px},
                        {"on_cap", c.on_cap}});
    j["convergence"] = conv;
    const PoseSpread &s = o.spread;
    j["spread"] = {{"poses", s.poses},         {"failed", s.failed},
                   {"on_cap", s.on_cap},       {"fx_pct", s.fx_pct},
                   {"fy_pct", s.fy_pct},       {"cx_px", s.cx_px},
                   {"cy_px", s.cy_px},         {"rotation_deg", s.rotation_deg},
                   {"translation_direction_deg", s.translation_dir_deg},
                   {"origin_mm", s.origin_mm}, {"jackknife_se_fx_pct", s.se_fx_pct},
                   {"jackknife_se_fy_pct", s.se_fy_pct}, {"jackknife_se_cx_px", s.se_cx_px},
                   {"jackknife_se_cy_px", s.se_cy_px}};
    return j;
}

nlohmann::json differenceJson(const ProcamComparison &c) {
    return {{"projector_fx_pct", c.fx_pct},
            {"projector_fy_pct", c.fy_pct},
            {"projector_cx_px", c.cx_px},
            {"projector_cy_px", c.cy_px},
            {"rotation_deg", c.rotation_deg},
            {"translation_direction_deg", c.translation_dir_deg},
            {"translation_length_ratio", c.translation_ratio}};
}

std::string spreadCell(const PoseSpread &s) {
    if (s.poses == 0) return "n/a";
    return line("fx %.2f %%, fy %.2f %%, cx %.1f px, cy %.1f px, ", s.fx_pct, s.fy_pct, s.cx_px, s.cy_px) +
           line("rotation %.2f deg, translation %.2f deg", s.rotation_deg, s.translation_dir_deg);
}

std::string yes(bool b) { return b ? "yes" : "no"; }

}  // namespace

StereoFit publishedFit(const PublishedProcam &p, double unit_m) {
    StereoFit f;
    f.ok = true;
    f.projector.fx = p.proj_fx, f.projector.fy = p.proj_fy, f.projector.cx = p.proj_cx, f.projector.cy = p.proj_cy;
    f.projector.distortion = p.proj_distortion;
    f.camera.fx = p.cam_fx, f.camera.fy = p.cam_fy, f.camera.cx = p.cam_cx, f.camera.cy = p.cam_cy;
    f.camera.distortion = p.cam_distortion;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) f.rotation(i, j) = p.rotation(i, j);
        f.translation[i] = p.translation[i] * unit_m;
    }
    f.rms_px = p.rms;
    return f;
}

ProcamComparison compareProcam(const StereoFit &o, const StereoFit &p) {
    ProcamComparison c;
    c.fx_pct = 100 * (o.projector.fx - p.projector.fx) / p.projector.fx;
    c.fy_pct = 100 * (o.projector.fy - p.projector.fy) / p.projector.fy;
    c.cx_px = o.projector.cx - p.projector.cx;
    c.cy_px = o.projector.cy - p.projector.cy;
    const Eigen::Matrix3d d = rotationOf(o) * rotationOf(p).transpose();
    c.rotation_deg = std::acos(std::clamp(0.5 * (d.trace() - 1), -1.0, 1.0)) * kDeg;
    const Eigen::Vector3d tp = translationOf(p), to = translationOf(o);
    c.translation_dir_deg = std::acos(std::clamp(to.normalized().dot(tp.normalized()), -1.0, 1.0)) * kDeg;
    c.translation_ratio = to.norm() / tp.norm();
    return c;
}

bool procamTargetsHold(const StereoFit &o, const ProcamComparison &c) {
    return std::abs(c.fx_pct) <= 1 && std::abs(c.fy_pct) <= 1 && std::abs(c.cx_px) <= 30 && std::abs(c.cy_px) <= 30 &&
           c.rotation_deg <= 1 && c.translation_dir_deg <= 2 && o.rms_px <= 0.4 && o.spread.poses > 0;
}

std::string procamTable(const ProcamTableInput &in) {
    const StereoFit &o = *in.ours, &r = *in.reference, &p = *in.published;
    const ProcamComparison &c = in.vs_reference, &cp = in.vs_published;
    std::string s =
        "| | ours | published method, converged | difference | published XML (information) |\n"
        "|---|---:|---:|---:|---:|\n";
    s += line("| projector fx (px) | %.1f | %.1f | %+.2f %% |", o.projector.fx, r.projector.fx, c.fx_pct) +
         line(" %.1f (%+.2f %%) |\n", p.projector.fx, cp.fx_pct);
    s += line("| projector fy (px) | %.1f | %.1f | %+.2f %% |", o.projector.fy, r.projector.fy, c.fy_pct) +
         line(" %.1f (%+.2f %%) |\n", p.projector.fy, cp.fy_pct);
    s += line("| projector cx (px) | %.1f | %.1f | %+.1f px |", o.projector.cx, r.projector.cx, c.cx_px) +
         line(" %.1f (%+.1f px) |\n", p.projector.cx, cp.cx_px);
    s += line("| projector cy (px) | %.1f | %.1f | %+.1f px |", o.projector.cy, r.projector.cy, c.cy_px) +
         line(" %.1f (%+.1f px) |\n", p.projector.cy, cp.cy_px);
    s += line("| camera fx (px) | %.1f | %.1f | %+.2f %% |", o.camera.fx, r.camera.fx,
              100 * (o.camera.fx - r.camera.fx) / r.camera.fx) +
         line(" %.1f |\n", p.camera.fx);
    s += line("| camera cx (px) | %.1f | %.1f | %+.1f px |", o.camera.cx, r.camera.cx, o.camera.cx - r.camera.cx) +
         line(" %.1f |\n", p.camera.cx);
    s += line("| camera cy (px) | %.1f | %.1f | %+.1f px |", o.camera.cy, r.camera.cy, o.camera.cy - r.camera.cy) +
         line(" %.1f |\n", p.camera.cy);
    s += line("| rotation | | | %.2f deg | (%.2f deg) |\n", c.rotation_deg, cp.rotation_deg);
    const Eigen::Vector3d to = translationOf(o), tr = translationOf(r), tp = translationOf(p);
    s += line("| translation (m) | [%.4f, %.4f, %.4f] |", to.x(), to.y(), to.z()) +
         line(" [%.4f, %.4f, %.4f] |", tr.x(), tr.y(), tr.z()) +
         line(" %.2f deg, length x %.3f |", c.translation_dir_deg, c.translation_ratio) +
         line(" [%.4f, %.4f, %.4f] (%.2f deg) |\n", tp.x(), tp.y(), tp.z(), cp.translation_dir_deg);
    s += line("| stereo reprojection RMS (px) | %.3f | %.3f | | %.3f |\n", o.rms_px, r.rms_px, p.rms_px);
    s += "| leave-one-pose-out spread | " + spreadCell(o.spread) + " | " + spreadCell(r.spread) + " | | |\n";
    s += line("\nsquare %.4f m; ours: %.0f views, %.0f corners, ", in.square_m, static_cast<double>(o.views),
              static_cast<double>(o.points));
    s += line("camera RMS %.3f px, projector RMS %.3f px, decoded share of the board %.1f %%; ", o.camera.rms_px,
              o.projector.rms_px, 100 * in.decoded_board_share);
    s += line("reference: %.0f corners carried, ", static_cast<double>(r.points));
    s += std::string(in.opencv_decoder ? "OpenCV's GrayCodePattern decoder (opencv_contrib structured_light)"
                                       : "projsurf's decoder (opencv_contrib structured_light not found at build)") +
         "\n";
    s += "spread: the largest change of a leave-one-pose-out fit from the all-pose fit\n";
    if (in.reference_defaults) {
        const StereoFit &d = *in.reference_defaults;
        const ProcamComparison dp = compareProcam(d, p);
        s += line("the published method with OpenCV's default criteria (as the script ran): projector fx %.1f, fy %.1f, "
                  "cx %.1f, cy %.1f px, ",
                  d.projector.fx, d.projector.fy, d.projector.cx, d.projector.cy) +
             line("stereo RMS %.3f px; against the published XML: fx %+.2f %%, cx %+.1f px, cy %+.1f px, ", d.rms_px,
                  dp.fx_pct, dp.cx_px, dp.cy_px) +
             line("rotation %.2f deg, translation direction %.2f deg\n", dp.rotation_deg, dp.translation_dir_deg);
        for (const auto &f : d.convergence) s += "  " + describeConvergence(f) + "\n";
    }
    for (const auto &f : o.convergence) s += "ours " + describeConvergence(f) + "\n";
    for (const auto &f : r.convergence) s += "reference " + describeConvergence(f) + "\n";
    s += "\n| target (issue 37, against the converged published method) | measured | holds |\n|---|---:|---|\n";
    s += line("| projector fx, fy within 1 %% | %+.2f %%, %+.2f %% |", c.fx_pct, c.fy_pct) +
         " " + yes(std::abs(c.fx_pct) <= 1 && std::abs(c.fy_pct) <= 1) + " |\n";
    s += line("| projector cx, cy within 30 px | %+.1f, %+.1f px |", c.cx_px, c.cy_px) + " " +
         yes(std::abs(c.cx_px) <= 30 && std::abs(c.cy_px) <= 30) + " |\n";
    s += line("| rotation within 1 deg | %.2f deg |", c.rotation_deg) + " " + yes(c.rotation_deg <= 1) + " |\n";
    s += line("| translation direction within 2 deg | %.2f deg |", c.translation_dir_deg) + " " +
         yes(c.translation_dir_deg <= 2) + " |\n";
    s += line("| stereo reprojection RMS <= 0.4 px | %.3f px |", o.rms_px) + " " + yes(o.rms_px <= 0.4) + " |\n";
    s += "| jackknife spread reported | " + spreadCell(o.spread) + " | " + yes(o.spread.poses > 0) + " |\n";
    return s;
}

std::string procamJson(const std::string &path, const ProcamTableInput &in, const std::vector<double> &pose_shares) {
    nlohmann::json j = fitJson(*in.ours);
    j["square_m"] = in.square_m;
    j["decoded_board_share"] = in.decoded_board_share;
    j["decoded_board_share_per_pose"] = pose_shares;
    j["reference"] = fitJson(*in.reference);
    j["reference"]["decoder"] = in.opencv_decoder ? "opencv_structured_light" : "projsurf";
    j["difference"] = differenceJson(in.vs_reference);
    j["targets_hold"] = procamTargetsHold(*in.ours, in.vs_reference);
    nlohmann::json pub = fitJson(*in.published);
    for (const char *key : {"convergence", "spread", "camera_rms_px", "projector_rms_px"}) pub.erase(key);
    pub["projector"].erase("sigma");
    j["published"] = pub;
    if (in.reference_defaults) {
        nlohmann::json d = fitJson(*in.reference_defaults);
        d.erase("spread");
        j["reference_opencv_defaults"] = d;
    }
    j["difference_published"] = differenceJson(in.vs_published);
    // Never a null where a number belongs (a fit or a comparison that came out NaN).
    if (const std::string key = nonFiniteJsonKey(j); !key.empty())
        throw InputError(path, "'" + key + "' is not finite (the fit or the published calibration is degenerate): "
                               "nothing written");
    return j.dump(2) + "\n";
}

}  // namespace projsurf::eval
