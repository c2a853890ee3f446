#include "projsurf/io/yaml/fit_quality_yaml.hpp"

namespace projsurf {

YAML::Node convergenceNode(const std::vector<FitConvergence> &fits) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const auto &c : fits) {
        YAML::Node n;
        n["fit"] = c.fit;
        n["iterations"] = c.iterations;
        n["cap"] = c.cap;
        n["last_step"] = c.last_step;
        n["last_step_px"] = c.last_step_px;
        n["on_cap"] = c.on_cap;
        n.SetStyle(YAML::EmitterStyle::Flow);
        out.push_back(n);
    }
    return out;
}

YAML::Node spreadNode(const PoseSpread &s) {
    YAML::Node n;
    n["method"] = "leave_one_pose_out";
    n["poses"] = s.poses;
    n["failed"] = s.failed;
    n["on_cap"] = s.on_cap;
    n["fx_pct"] = s.fx_pct;
    n["fy_pct"] = s.fy_pct;
    n["cx_px"] = s.cx_px;
    n["cy_px"] = s.cy_px;
    n["rotation_deg"] = s.rotation_deg;
    n["translation_direction_deg"] = s.translation_dir_deg;
    n["origin_mm"] = s.origin_mm;
    n["jackknife_se"]["fx_pct"] = s.se_fx_pct;
    n["jackknife_se"]["fy_pct"] = s.se_fy_pct;
    n["jackknife_se"]["cx_px"] = s.se_cx_px;
    n["jackknife_se"]["cy_px"] = s.se_cy_px;
    return n;
}

}  // namespace projsurf
