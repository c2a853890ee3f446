// projsurf calibrate: find the projector's central axis from captures of the calibration
// picture (paper 3.1) and write the calibration YAML (contract keys + fit report); or, with
// --write-picture, write that picture (black, one white disc in the centre).
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>

#include "cli/commands.hpp"
#include "projsurf/calibration/calibration.hpp"
#include "projsurf/calibration/calibration_picture.hpp"
#include "projsurf/calibration/decoded_points.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/frontend/inputs/chessboard_calibration.hpp"
#include "projsurf/frontend/settings/resolution.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/formats/pattern_files.hpp"
#include "projsurf/io/formats/procam_captures.hpp"
#include "projsurf/io/reports/calibration_report.hpp"
#include "projsurf/io/reports/chessboard_report.hpp"
#include "projsurf/io/reports/structured_report.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/types/lens_model_check.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct CalibrateOptions {
    std::string captures;
    std::string out;
    std::string write_picture;
    std::string fov = "39.3,24.0";        // deg, Aaxa P300 (paper 3.1.2)
    std::string resolution = "1280,800";  // px, Aaxa P300
    int threshold = 50;                   // paper 3.1.1
    double square_m = 0;                  // chessboard mode: the printed square's edge, m (no default: measure it)
    bool resolution_given = false;
};

/// "A,B" -> two finite numbers; InputError naming the option otherwise.
std::pair<double, double> parseTwo(const std::string &option, const std::string &text) {
    std::stringstream ss(text);
    double a = 0, b = 0;
    char comma = 0;
    if (!(ss >> a >> comma >> b) || comma != ',' || !std::isfinite(a) || !std::isfinite(b) || !(ss >> std::ws).eof())
        throw InputError(option, "expected two numbers separated by a comma, got '" + text + "'");
    return {a, b};
}

std::string utcNow() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string fmt(const char *format, double a, double b = 0, double c = 0, double d = 0) {
    char buf[200];
    std::snprintf(buf, sizeof buf, format, a, b, c, d);
    return buf;
}

/// The calibration picture at the projector's resolution. The disc's radius is H / 8 (100 px
/// at 1280x800): the picture the simulated calibrations are made and tested with; see
/// docs/calibration.md for why that size.
void writePicture(const CalibrateOptions &o) {
    if (!o.captures.empty() || !o.out.empty())
        throw InputError("--write-picture",
                         "only writes the calibration picture; run calibrate --captures DIR --out "
                         "calib.yaml separately");
    const auto [w, h] = frontend::parseResolution("--resolution", o.resolution);
    requireWritableLocation(o.write_picture);
    if (!cv::haveImageWriter(o.write_picture))
        throw InputError(o.write_picture, "cannot write an image with this extension (use .png)");
    const double radius = h / 8.0;
    writeImageAtomic(o.write_picture, calibrationPicture(w, h, radius));
    std::cout << "projsurf calibrate: calibration picture " << w << "x" << h
              << fmt(", white disc of radius %.1f px at (%.1f, %.1f) -> ", radius, 0.5 * (w - 1), 0.5 * (h - 1))
              << o.write_picture << "\n"
              << "  show it full screen on the projector (projsurf show --image " << o.write_picture
              << "), capture it from 3 or more robot positions; see docs/calibration.md\n";
}

/// Structured light (contract, "Structured-light calibration"): decode every pose, lift
/// through its depth, fit the full model, write it with the residuals.
void runStructured(const CalibrateOptions &o, int res_w, int res_h) {
    const fs::path dir(o.captures);
    const std::string list_path = (dir / "patterns.yaml").string();
    const PatternList list = readPatternList(list_path);
    if (o.resolution_given && (res_w != list.width || res_h != list.height))
        throw InputError(list_path, "patterns are " + std::to_string(list.width) + "x" + std::to_string(list.height) +
                                        " but --resolution says " + std::to_string(res_w) + "x" +
                                        std::to_string(res_h));
    const CameraIntrinsics camera = readCamera((dir / "camera.yaml").string());
    // One pose in memory at a time (listPoseFolders checked what that takes); the lifted
    // points of every pose are kept for the fit.
    const std::vector<std::string> poses = listPoseFolders(o.captures, list, camera.width, camera.height);
    // Kept per pose: the projector is fitted again with each left out once (the spread).
    std::vector<std::vector<ProjectorCorrespondence>> pairs_per_pose;
    std::size_t pair_count = 0;
    std::vector<int> decoded;
    for (const auto &pose_dir : poses) {
        PoseCaptures pose = readPoseCaptures(pose_dir, list, camera.width, camera.height);
        const GrayDecoding d = decodeGray(pose.colour, list.width, list.height);
        pose.colour.clear();
        pairs_per_pose.emplace_back();
        liftDecoding(d, pose.depth, camera, pairs_per_pose.back());
        pair_count += pairs_per_pose.back().size();
        decoded.push_back(d.decoded);
    }
    ProjectorFitConfig cfg;
    cfg.width = list.width;
    cfg.height = list.height;
    const ProjectorFit fit = fitProjectorPoses(pairs_per_pose, cfg);
    if (!fit.ok) throw InputError(o.captures, fit.problem);

    writeStructuredCalibration(o.out, fit, o.captures, static_cast<int>(poses.size()), utcNow());

    const Projector &p = fit.projector;
    std::cout << "projsurf calibrate: structured light, " << poses.size() << " pose(s), " << pair_count
              << " decoded pixels with depth -> " << o.out << "\n";
    for (std::size_t k = 0; k < poses.size(); ++k)
        std::cout << "  " << poses[k] << ": " << decoded[k] << " camera pixels decoded\n";
    std::cout << fmt("  intrinsics fx %.1f fy %.1f cx %.1f cy %.1f px", p.fx(), p.fy(), p.cx(), p.cy())
              << fmt(", k1 %.4f k2 %.4f\n", p.distortion[0], p.distortion[1])
              << fmt("  origin [%.4f, %.4f, %.4f] m", p.origin.x(), p.origin.y(), p.origin.z())
              << fmt(", axis [%.5f, %.5f, %.5f]\n", p.axis().x(), p.axis().y(), p.axis().z())
              << fmt("  reprojection rms %.3f px, max %.2f px over %.0f inliers", fit.rms_px, fit.max_px,
                     static_cast<double>(fit.inliers))
              << fmt(" (framebuffer coverage %.0f %%, relief %.0f mm)\n", fit.coverage * 100, fit.relief_m * 1000);
    for (const auto &c : fit.convergence) std::cout << "  fit " << describeConvergence(c) << "\n";
    std::cout << "  spread: " << describeSpread(fit.spread) << "\n";
    for (const auto &w : projectorFitWarnings(fit)) std::cerr << "projsurf: warning: " << w << "\n";
}

/// Chessboard mode: procam-style poses (capture_<k>/graycode_<NN>.png), no depth.
void runChessboard(const CalibrateOptions &o, int res_w, int res_h) {
    if (!(o.square_m > 0 && o.square_m < 10))
        throw InputError("--square-m", "the chessboard mode needs the printed square's edge in metres (0 < s < 10)");
    std::optional<std::pair<int, int>> resolution;
    if (o.resolution_given) resolution = std::make_pair(res_w, res_h);
    const ProcamFolder folder = readProcamFolder(o.captures, resolution);
    const frontend::ChessboardCalibration cal = frontend::calibrateChessboard(folder, o.square_m);
    ChessboardReport report;
    report.captures_dir = o.captures;
    report.created_utc = utcNow();
    report.poses = static_cast<int>(folder.poses.size());
    report.square_m = o.square_m;
    report.decoded_board_share = cal.decoded_board_share;
    writeChessboardCalibration(o.out, cal.fit, cal.width, cal.height, report);
    const StereoFit &f = cal.fit;
    std::cout << "projsurf calibrate: chessboard, " << folder.poses.size() << " pose(s), board " << cal.inner.width
              << "x" << cal.inner.height << " inner corners, projector " << cal.width << "x" << cal.height << " -> "
              << o.out << "\n";
    for (const auto &p : cal.poses)
        std::cout << "  " << p.dir << ": "
                  << (p.board ? std::to_string(p.carried) + "/" + std::to_string(p.corners) + " corners carried" +
                                    fmt(", board %.1f %% decoded", 100 * p.board_share)
                              : std::string("no chessboard found"))
                  << "\n";
    std::cout << fmt("  projector fx %.1f fy %.1f cx %.1f cy %.1f px", f.projector.fx, f.projector.fy, f.projector.cx,
                     f.projector.cy)
              << fmt(", camera fx %.1f fy %.1f px\n", f.camera.fx, f.camera.fy)
              << fmt("  translation [%.4f, %.4f, %.4f] m", f.translation[0], f.translation[1], f.translation[2])
              << fmt(" (P_proj = R P_cam + t); reprojection rms %.3f px (camera %.3f, projector %.3f)\n", f.rms_px,
                     f.camera.rms_px, f.projector.rms_px);
    for (const auto &c : f.convergence) std::cout << "  fit " << describeConvergence(c) << "\n";
    std::cout << "  spread: " << describeSpread(f.spread) << "\n";
    for (const auto &w : stereoWarnings(f)) std::cerr << "projsurf: warning: " << w << "\n";
}

/// The projector's lens as given (--fov-deg in degrees, --resolution), refused by the lens
/// check every reader applies: nothing is written that could not be read.
struct LensArguments {
    double fov_h_deg = 0, fov_v_deg = 0;
    int width = 0, height = 0;
};

LensArguments lensArguments(const CalibrateOptions &o) {
    const auto [fov_h, fov_v] = parseTwo("--fov-deg", o.fov);
    if (!(fov_h > 0 && fov_h < kMaxLensFovDeg && fov_v > 0 && fov_v < kMaxLensFovDeg))
        throw InputError("--fov-deg",
                         "angles must be between 0 and " + std::to_string(static_cast<int>(kMaxLensFovDeg)) + " degrees");
    const auto [res_w, res_h] = frontend::parseResolution("--resolution", o.resolution);
    Projector lens;  // the check reads radians
    lens.width = static_cast<int>(res_w);
    lens.height = static_cast<int>(res_h);
    lens.fov_h = fov_h * kDeg;
    lens.fov_v = fov_v * kDeg;
    const std::string problem = lensModelProblem(lens);
    if (!problem.empty()) throw InputError("--fov-deg", problem);
    return {fov_h, fov_v, lens.width, lens.height};
}

/// The disc mode's captures: capture_<k>_rgb.png with its capture_<k>_depth.png, k = 0..N-1.
struct DiscCaptures {
    std::vector<CaptureImages> images;
    std::vector<std::string> rgb_paths, depth_paths;
    std::vector<std::string> names;  ///< the colour images' file names
};

/// N, the number of capture_<k>_rgb.png in `dir`; refused when a number is out of range or
/// missing, when the captures together are too big, or when there are fewer than 3.
int discCaptureCount(const fs::path &dir, const std::string &captures_arg, const CameraIntrinsics &camera) {
    std::error_code ec;
    std::map<int, std::string> found;
    const std::regex pattern(R"(capture_(\d+)_rgb\.png)");
    for (const auto &entry : fs::directory_iterator(dir, ec)) {
        std::smatch m;
        const std::string name = entry.path().filename().string();
        if (!std::regex_match(name, m, pattern)) continue;
        const std::string number = m[1];
        if (number.size() > 6 || std::stoi(number) >= static_cast<int>(limits::kMaxCaptures))
            throw InputError((dir / name).string(), "capture number out of range (captures are numbered 0.." +
                                                        std::to_string(limits::kMaxCaptures - 1) + ")");
        found[std::stoi(number)] = name;
    }
    const int n = static_cast<int>(found.size());
    if (static_cast<std::uint64_t>(n) * camera.width * camera.height > limits::kMaxCapturePixels)
        throw InputError(captures_arg, std::to_string(n) + " captures of " + std::to_string(camera.width) + " x " +
                                           std::to_string(camera.height) + " pixels exceed the limit of " +
                                           std::to_string(limits::kMaxCapturePixels) + " pixels in all");
    for (int k = 0; k < n; ++k)
        if (!found.count(k))
            throw InputError((dir / ("capture_" + std::to_string(k) + "_rgb.png")).string(),
                             "missing (captures must be numbered 0.." + std::to_string(n - 1) + ")");
    if (n < 3)
        throw InputError(captures_arg, "found " + std::to_string(n) +
                                           " capture(s) (capture_k_rgb.png), need at least 3 taken at different "
                                           "distances from the wall");
    return n;
}

DiscCaptures readDiscCaptures(const fs::path &dir, int n, const CameraIntrinsics &camera) {
    DiscCaptures captures;
    for (int k = 0; k < n; ++k) {
        const std::string rgb = (dir / ("capture_" + std::to_string(k) + "_rgb.png")).string();
        const std::string dep = (dir / ("capture_" + std::to_string(k) + "_depth.png")).string();
        CaptureImages c;
        c.color = readImageOfSize(rgb, cv::IMREAD_COLOR, camera.width, camera.height, "camera.yaml");
        c.depth = readImageOfSize(dep, cv::IMREAD_UNCHANGED, camera.width, camera.height, "camera.yaml");
        if (c.depth.type() != CV_16UC1) throw InputError(dep, "expected a 16-bit single-channel depth PNG");
        captures.images.push_back(c);
        captures.rgb_paths.push_back(rgb);
        captures.depth_paths.push_back(dep);
        captures.names.push_back(fs::path(rgb).filename().string());
    }
    return captures;
}

/// The paper's calibration (3.1) of the captures; a failure is the input error of the file it
/// failed on.
Calibration calibrateDisc(const CalibrateOptions &o, const LensArguments &lens, const DiscCaptures &captures,
                          const CameraIntrinsics &camera) {
    CalibrationConfig config;
    config.disc.threshold = o.threshold;
    config.width = lens.width;
    config.height = lens.height;
    config.fov_h = lens.fov_h_deg * kDeg;
    config.fov_v = lens.fov_v_deg * kDeg;
    const Calibration cal = calibrateProjector(captures.images, camera, config);
    switch (cal.failure) {
    case CalibrationFailure::None: break;
    case CalibrationFailure::NoDisc:
        throw InputError(captures.rgb_paths.at(cal.failed_capture),
                         cal.message + (cal.message.find("threshold") != std::string::npos ? " (--threshold)" : ""));
    case CalibrationFailure::SizeMismatch: throw InputError(captures.rgb_paths.at(cal.failed_capture), cal.message);
    case CalibrationFailure::NoDepth: throw InputError(captures.depth_paths.at(cal.failed_capture), cal.message);
    default: throw InputError(o.captures, cal.message);
    }
    return cal;
}

/// The axis, each capture's disc and residual, a warning for each capture with more than one
/// bright blob, and the fit with its verdict.
void printDiscCalibration(const std::string &out, const Calibration &cal, const DiscCaptures &captures) {
    const int n = static_cast<int>(captures.names.size());
    const Eigen::Vector3d &d = cal.projector.direction, &og = cal.projector.origin;
    std::cout << "projsurf calibrate: " << n << " captures -> " << out << "\n"
              << fmt("  axis direction [%.5f, %.5f, %.5f]", d.x(), d.y(), d.z())
              << fmt(", origin (z = 0, A.1) [%.4f, %.4f, %.4f] m\n", og.x(), og.y(), og.z());
    for (int k = 0; k < n; ++k) {
        const CaptureResult &r = cal.captures[k];
        std::cout << "  " << captures.names[k]
                  << fmt(": disc at (%.2f, %.2f) px, radius %.1f px", r.disc.centroid.x(), r.disc.centroid.y(),
                         r.disc.radius_px)
                  << fmt(" -> [%.4f, %.4f, %.4f] m", r.lifted.point->x(), r.lifted.point->y(), r.lifted.point->z())
                  << fmt(", residual %.2f mm\n", r.residual_m * 1000);
    }
    for (int k = 0; k < n; ++k)
        if (cal.captures[k].disc.candidates > 1)
            std::cerr << "projsurf: warning: " << captures.rgb_paths[k] << ": " << cal.captures[k].disc.candidates
                      << " bright blobs; used the largest round one"
                      << fmt(" at (%.0f, %.0f) px", cal.captures[k].disc.centroid.x(),
                             cal.captures[k].disc.centroid.y())
                      << " (raise --threshold or darken the room if that is not the disc)\n";
    std::cout << fmt("  fit: residual rms %.2f mm, max %.2f mm, centroids span %.2f m along the axis",
                     cal.axis.rms_m * 1000, cal.axis.max_m * 1000, cal.axis.spread_m)
              << ": " << calibrationVerdict(cal.axis) << "\n";
}

/// Verdict redo: the calibration is written (to look at), but not to be used: exit 3, so a
/// script stops here.
void stopWhenTheCapturesDisagree(const std::string &out, const Calibration &cal) {
    if (calibrationVerdict(cal.axis) != "redo") return;
    std::cerr << "projsurf: error: " << out << ": written, but the captures disagree by up to "
              << fmt("%.1f mm", cal.axis.max_m * 1000)
              << " from one line (verdict redo); check the robot did not turn the projector between captures "
                 "and take them again\n";
    throw ExitStatus{kExitRedo};
}

/// The disc mode (paper 3.1): camera.yaml and capture_<k>_rgb.png / capture_<k>_depth.png.
void runDisc(const CalibrateOptions &o, const LensArguments &lens) {
    const fs::path dir(o.captures);
    std::error_code ec;
    if (!fs::exists(dir / "camera.yaml", ec))
        throw InputError((dir / "camera.yaml").string(),
                         "no such file (the disc mode needs it; structured light with depth needs patterns.yaml + "
                         "pose_<k>/ beside it; the chessboard mode needs capture_<k>/graycode_<NN>.png instead)");
    const CameraIntrinsics camera = readCamera((dir / "camera.yaml").string());
    const int n = discCaptureCount(dir, o.captures, camera);
    const DiscCaptures captures = readDiscCaptures(dir, n, camera);
    const Calibration cal = calibrateDisc(o, lens, captures, camera);
    CalibrationProvenance prov;
    prov.capture_names = captures.names;
    prov.captures_dir = o.captures;
    prov.threshold = o.threshold;
    prov.created_utc = utcNow();
    writeCalibrationReport(o.out, cal, prov);
    printDiscCalibration(o.out, cal, captures);
    stopWhenTheCapturesDisagree(o.out, cal);
}

void run(const CalibrateOptions &o) {
    if (!o.write_picture.empty()) return writePicture(o);
    if (o.captures.empty()) throw CLI::RequiredError("--captures");
    if (o.out.empty()) throw CLI::RequiredError("--out");
    // Arguments first, then every input, before any work; the output only at the end.
    const LensArguments lens = lensArguments(o);
    if (o.threshold < 0 || o.threshold > 254) throw InputError("--threshold", "must be between 0 and 254");
    std::error_code ec;
    if (!fs::is_directory(o.captures, ec)) throw InputError(o.captures, "not a directory");
    requireWritableLocation(o.out);
    const fs::path dir(o.captures);
    // patterns.yaml in any form (a broken link or a loop included) means structured light:
    // its reader says what is wrong with it, or which pose folder is missing.
    const bool structured = fs::symlink_status(dir / "patterns.yaml", ec).type() != fs::file_type::not_found;
    const bool chessboard = !structured && isProcamFolder(o.captures);
    // An option of another mode would be ignored: said, not ignored (as eval --published without --procam).
    if (o.square_m != 0 && !chessboard)
        throw InputError("--square-m", "is for the chessboard mode (capture_<k>/graycode_<NN>.png); " + o.captures +
                                           " is a " + (structured ? "structured-light" : "disc-mode") + " folder");
    if (structured) return runStructured(o, lens.width, lens.height);
    if (chessboard) return runChessboard(o, lens.width, lens.height);
    runDisc(o, lens);
}

}  // namespace

void addCalibrateCommand(CLI::App &app) {
    auto opts = std::make_shared<CalibrateOptions>();
    auto *sub = app.add_subcommand(
        "calibrate",
        "find the projector's axis from captures of the calibration picture (--write-picture: write that picture)");
    sub->footer(
        "Exit status: 0 when the calibration is written and its fit is good or acceptable; 3 when it is "
        "written but the captures disagree (fit.verdict: redo; take them again before using it, see "
        "docs/calibration.md); 2 for bad input (nothing written).");
    sub->add_option(
        "--captures", opts->captures,
        "folder with camera.yaml and capture_k_rgb.png / capture_k_depth.png, k = 0..N-1 (N >= 3); or "
        "with patterns.yaml and pose_k/ (structured light, see projsurf patterns); or with capture_k/graycode_NN.png "
        "(chessboard mode, OpenCV's Gray-code order, no depth: needs --square-m); required unless --write-picture");
    sub->add_option("--out", opts->out, "calibration YAML to write; required unless --write-picture");
    sub->add_option("--write-picture", opts->write_picture,
                    "write the calibration picture (black, one white disc in the centre) at --resolution "
                    "to this PNG, and nothing else");
    sub->add_option("--fov-deg", opts->fov, "projector's full horizontal,vertical field of view, deg")
        ->capture_default_str();
    auto *res = sub->add_option("--resolution", opts->resolution, "projector framebuffer width,height, px")
                    ->capture_default_str();
    sub->add_option("--square-m", opts->square_m, "chessboard mode: the printed square's edge, m");
    sub->add_option("--threshold", opts->threshold, "grey level that separates the disc from the background (0-254)")
        ->capture_default_str();
    sub->callback([opts, res] {
        opts->resolution_given = res->count() > 0;
        run(*opts);
    });
}

}  // namespace projsurf::cli
