#pragma once
// Our chessboard calibration beside a published one (procam-calibration's XML): the table
// `eval --procam` prints and its JSON.
#include <string>
#include <vector>

#include "projsurf/calibration/stereo_fit.hpp"
#include "projsurf/io/procam_xml.hpp"

namespace projsurf::eval {

struct ProcamComparison {
    double fx_pct = 0, fy_pct = 0;   ///< (ours - published) / published, %
    double cx_px = 0, cy_px = 0;     ///< ours - published, px
    double rotation_deg = 0;         ///< angle of R_ours R_published^T
    double translation_dir_deg = 0;  ///< angle between the translations
    double translation_ratio = 0;    ///< |t_ours| / |t_published| (both in m)
};

/// `published_unit_m`: the XML translation's unit in metres (its board was given in it).
ProcamComparison compareProcam(const StereoFit &ours, const PublishedProcam &published, double published_unit_m);

/// The Markdown table (ours, published, difference) and the summary lines.
std::string procamTable(const StereoFit &ours, const PublishedProcam &published, const ProcamComparison &c,
                        double published_unit_m, double square_m, double decoded_board_share);

/// {"projector": {"fx", "fy", "cx", "cy", "distortion": [5]}, "camera": {"fx", "fy", "cx",
/// "cy"}, "rotation": 3x3, "translation": [3] (m), "square_m", "reprojection_rms_px",
/// "decoded_board_share" (the mean over the poses), "decoded_board_share_per_pose": [...],
/// "published": {...the same keys...}, "difference": {...}}
/// InputError naming `path` (the file it goes to) when a number is not finite.
std::string procamJson(const std::string &path, const StereoFit &ours, const PublishedProcam &published,
                       const ProcamComparison &c,
                       double published_unit_m, double square_m, double decoded_board_share,
                       const std::vector<double> &pose_shares);

}  // namespace projsurf::eval
