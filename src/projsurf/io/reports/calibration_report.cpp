#include "projsurf/io/reports/calibration_report.hpp"
#include "projsurf/io/yaml/yaml_numbers.hpp"

#include <yaml-cpp/yaml.h>
#include <cstdio>

#include "projsurf/io/files/files.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf {
namespace {

/// Calibration numbers carry 10 significant digits.
YAML::Node num(double v) { return yamlNumber(v, 10); }
YAML::Node flow(std::initializer_list<double> values) { return yamlNumbers(values, 10); }

YAML::Node flow(const Eigen::Vector3d &v) { return flow({v.x(), v.y(), v.z()}); }

YAML::Node rays(const std::array<Eigen::Vector3d, 4> &r) {
    YAML::Node n;
    for (const auto &v : r) n.push_back(flow(v));
    return n;
}

}  // namespace

std::string calibrationVerdict(const AxisFit &axis) {
    if (axis.max_m <= 0.005) return "good";        // 5 mm: centroid noise of a Kinect at 1-3 m
    if (axis.max_m <= 0.015) return "acceptable";  // 15 mm: ~0.3 deg over a 3 m baseline
    return "redo";
}

std::string calibrationReportYaml(const Calibration &cal, const CalibrationProvenance &prov) {
    YAML::Node root;
    YAML::Node p = calibrationNode(cal.projector);  // the contract's keys ...
    const Projector &pr = cal.projector;            // ... with readable numbers
    p["fov_deg"] = flow({pr.fov_h * 180.0 / 3.14159265358979323846, pr.fov_v * 180.0 / 3.14159265358979323846});
    p["axis"]["origin"] = flow(pr.origin);
    p["axis"]["direction"] = flow(pr.direction.normalized());
    // Unit directions from axis.origin through the framebuffer's outer corners, ordered
    // top-left, top-right, bottom-right, bottom-left. `pinhole` is the contract's model (used by
    // projsurf); `paper` is the Appendix's Euler-Rodrigues construction, for comparison.
    p["corner_rays"]["order"] = "top-left, top-right, bottom-right, bottom-left";
    p["corner_rays"]["pinhole"] = rays(cal.pinhole_rays);
    p["corner_rays"]["paper"] = rays(cal.paper_rays);
    root["projector"] = p;

    YAML::Node c;
    c["tool"] = "projsurf calibrate";
    c["created_utc"] = prov.created_utc;
    c["captures_dir"] = prov.captures_dir;
    c["captures_used"] = static_cast<int>(cal.captures.size());
    c["threshold"] = prov.threshold;
    c["origin_note"] =
        "axis.origin is the point of the fitted axis with z = 0 (paper, eq. A.1): the lens position "
        "along the axis is a convention, not measured; fov_deg and resolution come from the "
        "command line, not from the captures";
    c["fit"]["method"] = "least-squares 3-D line (principal axis) through the disc centroids";
    c["fit"]["rms_residual_m"] = num(cal.axis.rms_m);
    c["fit"]["max_residual_m"] = num(cal.axis.max_m);
    c["fit"]["spread_along_axis_m"] = num(cal.axis.spread_m);
    c["fit"]["verdict"] = calibrationVerdict(cal.axis);
    for (std::size_t k = 0; k < cal.captures.size(); ++k) {
        const CaptureResult &r = cal.captures[k];
        YAML::Node n;
        n["rgb"] = k < prov.capture_names.size() ? prov.capture_names[k] : std::string();
        n["centroid_px"] = flow({r.disc.centroid.x(), r.disc.centroid.y()});
        n["disc_radius_px"] = num(r.disc.radius_px);
        n["disc_circularity"] = num(r.disc.circularity);
        n["bright_blobs"] = r.disc.candidates;
        n["centroid_m"] = flow(*r.lifted.point);
        n["depth_readings"] = r.lifted.valid_points;
        n["depth_region_px"] = r.lifted.region_points;
        n["depth_inliers"] = r.lifted.inliers;
        n["local_plane_rms_m"] = num(r.lifted.plane_rms_m);
        n["residual_m"] = num(r.residual_m);
        c["captures"].push_back(n);
    }
    root["calibration"] = c;

    YAML::Emitter out;
    out.SetDoublePrecision(9);
    out << root;
    return std::string(out.c_str()) + "\n";
}

void writeCalibrationReport(const std::string &path, const Calibration &cal, const CalibrationProvenance &prov) {
    const std::string text = calibrationReportYaml(cal, prov);
    checkCalibrationText(path, text);  // read back as every reader reads it first
    writeFileAtomic(path, text);
}

}  // namespace projsurf
