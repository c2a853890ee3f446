#pragma once
// Our chessboard calibration beside the published method re-run to convergence on the same
// captures (eval/procam/procam_reference.hpp), and beside the published XML (procam-calibration's
// calibration_result.xml, for information: it stopped after OpenCV's default 30 iterations):
// the table `eval --procam` prints and its JSON.
#include <string>
#include <vector>

#include "projsurf/calibration/stereo_fit.hpp"
#include "projsurf/io/formats/procam_xml.hpp"

namespace projsurf::eval {

struct ProcamComparison {
    double fx_pct = 0, fy_pct = 0;   ///< (ours - theirs) / theirs, %
    double cx_px = 0, cy_px = 0;     ///< ours - theirs, px
    double rotation_deg = 0;         ///< angle of R_ours R_theirs^T
    double translation_dir_deg = 0;  ///< angle between the translations
    double translation_ratio = 0;    ///< |t_ours| / |t_theirs| (both in m)
};

/// The published XML as a fit (translation times `published_unit_m`: its board was given in that unit, m).
StereoFit publishedFit(const PublishedProcam &published, double published_unit_m);

ProcamComparison compareProcam(const StereoFit &ours, const StereoFit &theirs);

/// The targets of issue 37 (fx, fy within 1 %, cx, cy within 30 px, rotation within 1 deg,
/// translation direction within 2 deg, stereo RMS <= 0.4 px) against the reference.
bool procamTargetsHold(const StereoFit &ours, const ProcamComparison &c);

struct ProcamTableInput {
    const StereoFit *ours = nullptr, *reference = nullptr, *published = nullptr;
    const StereoFit *reference_defaults = nullptr;  ///< the published method with OpenCV's default criteria
    ProcamComparison vs_reference, vs_published;
    double square_m = 0, decoded_board_share = 0;
    bool opencv_decoder = true;
};

/// The Markdown tables (the numbers; the targets) and the convergence and spread lines.
std::string procamTable(const ProcamTableInput &in);

/// {"projector": {"fx", "fy", "cx", "cy", "distortion": [5], "sigma": {...}}, "camera": {...},
/// "rotation": 3x3, "translation": [3] (m), "square_m", "reprojection_rms_px", "convergence":
/// [...], "spread": {...}, "decoded_board_share" (the mean over the poses),
/// "decoded_board_share_per_pose": [...], "reference": {the same keys: the published method
/// converged}, "difference": {against the reference}, "targets_hold", "published": {the XML},
/// "difference_published": {against it}}
/// InputError naming `path` (the file it goes to) when a number is not finite.
std::string procamJson(const std::string &path, const ProcamTableInput &in, const std::vector<double> &pose_shares);

}  // namespace projsurf::eval
