// projsurf verify: the closed-loop check. The framebuffer `correct` wrote is projected and
// captured; verify finds the picture in the colour image, lifts its corners through the depth
// and reports where they landed against where the calibration sends the framebuffer on the
// surface seen (what passes or fails: the calibration), against the detection's corners (which
// also carry the depth sensor's noise), and eq. 8.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <opencv2/imgcodecs.hpp>

#include "cli/calibration_input.hpp"
#include "cli/commands.hpp"
#include "projsurf/calibration/projected_picture.hpp"
#include "projsurf/frontend/settings/resolution.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/keystone/keystone.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

struct VerifyOptions {
    std::string calib, detection, framebuffer, captures, json, write_card, resolution = "1280,800";
    /// m; not given: calibrationTolerance (5 mm, or 0.3 deg seen from the projector where that
    /// is more).
    std::optional<double> tolerance;
};

std::string vec3(const Eigen::Vector3d &v) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "[%.5f, %.5f, %.5f]", v.x(), v.y(), v.z());
    return buf;
}

/// --write-card: the test card at --resolution, and what to do with it.
void writeVerificationCard(const VerifyOptions &o) {
    const cv::Size wh = frontend::parseResolution("--resolution", o.resolution, 8);
    requireWritableFile(o.write_card);
    requireImageWriter(o.write_card);
    writeImageAtomic(o.write_card, verificationCard(wh.width, wh.height));
    std::cout << "projsurf verify: test card -> " << o.write_card << "; correct it (projsurf correct --image "
              << o.write_card << " ...), project the framebuffer, capture rgb.png and depth.png\n";
}

void checkVerifyArguments(const VerifyOptions &o) {
    for (const auto &[name, value] : {std::pair<const char *, const std::string &>{"--calib", o.calib},
                                      {"--detection", o.detection},
                                      {"--framebuffer", o.framebuffer},
                                      {"--captures", o.captures}})
        if (value.empty()) throw CLI::RequiredError(name);
    if (o.tolerance && !(*o.tolerance > 0 && *o.tolerance < 1))
        throw InputError("--tolerance", "must be between 0 and 1 m");
    if (!o.json.empty()) requireWritableFile(o.json);
}

/// Everything verify reads, checked against each other before any work.
struct VerifyInputs {
    Projector projector;
    DetectionFile det;
    Corners2 lit{};  ///< the framebuffer's lit corners
    CameraIntrinsics camera;
    cv::Mat rgb, depth;
};

VerifyInputs readVerifyInputs(const VerifyOptions &o) {
    VerifyInputs in;
    in.projector = readCalibrationWarned(o.calib);
    in.det = readDetectionJson(o.detection);
    const cv::Mat fb =
        readImageOfSize(o.framebuffer, cv::IMREAD_COLOR, in.projector.width, in.projector.height, "the calibration");
    const fs::path dir(o.captures);
    in.camera = readCamera((dir / "camera.yaml").string());
    const std::string rgb_path = (dir / "rgb.png").string(), depth_path = (dir / "depth.png").string();
    in.rgb = readImageOfSize(rgb_path, cv::IMREAD_COLOR, in.camera.width, in.camera.height, "camera.yaml");
    in.depth = readImageOfSize(depth_path, cv::IMREAD_UNCHANGED, in.camera.width, in.camera.height, "camera.yaml");
    if (in.depth.type() != CV_16UC1) throw InputError(depth_path, "expected a 16-bit single-channel depth PNG");
    const auto lit = litFramebufferCorners(fb);
    if (!lit) throw InputError(o.framebuffer, "is all black: nothing was projected");
    in.lit = *lit;
    // The detection must fit this calibration, as `correct` requires (a detection made with
    // another projector can lie behind this one, or beyond its framebuffer).
    if (const KeystoneResult fits = computeKeystone(in.projector, in.det.rectangle, fb.size()); !fits.keystone)
        throw InputError(o.calib, "cannot light the detection in " + o.detection + ": " + fits.problem);
    return in;
}

/// Where the picture was meant to land: the detection's rectangle, letterboxed to the
/// picture's aspect (the lit framebuffer corners cast onto the detected plane).
Rectangle meantRectangle(const VerifyInputs &in) {
    Corners3 cast;
    for (int i = 0; i < 4; ++i) {
        const auto hit = castToWall(in.projector, in.lit[i], in.det.plane);
        if (!hit) return in.det.rectangle;
        cast[i] = *hit;
    }
    const double w = 0.5 * ((cast[1] - cast[0]).norm() + (cast[2] - cast[3]).norm());
    const double h = 0.5 * ((cast[3] - cast[0]).norm() + (cast[2] - cast[1]).norm());
    const double aspect = w / h, rect_aspect = in.det.rectangle.width / in.det.rectangle.height;
    if (std::abs(aspect / rect_aspect - 1.0) > 0.02) return letterbox(in.det.rectangle, aspect);
    return in.det.rectangle;
}

/// Every number written is finite, or nothing is written (a degenerate camera.yaml or depth
/// can leave the found corners at NaN or infinity, and NaN compares as passing).
void requireFiniteLanding(const VerifyOptions &o, const FoundPicture &found, const Rectangle &meant,
                          const LandingCheck &check, const ShapeErrors &eq8) {
    bool finite = std::isfinite(eq8.horizontal_pct) && std::isfinite(eq8.vertical_pct) &&
                  std::isfinite(eq8.diagonal_pct) && std::isfinite(check.detection_off_m);
    for (int i = 0; i < 4; ++i)
        finite = finite && found.corners[i].allFinite() && meant.corners[i].allFinite() &&
                 check.expected[i].allFinite() && std::isfinite(check.detection_error_m[i]) &&
                 std::isfinite(check.calibration_error_m[i]);
    if (!finite)
        throw InputError(o.captures,
                         "the picture's corners measured in rgb.png and depth.png are not finite "
                         "numbers (check camera.yaml's intrinsics and depth_scale)");
}

/// verify's answer: the JSON it writes, and whether the check passed.
struct VerifyAnswer {
    std::string json;
    bool passed = true;
};

/// The found picture's JSON: its corners, where they were expected, the errors, and the verdict.
std::string landingJson(const FoundPicture &found, const LandingCheck &check, const ShapeErrors &eq8, double tolerance,
                        bool passed) {
    std::string corners, errors, calib_errors, expected;
    auto list = [](std::string &to, int i, double v) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%s%.4f", i ? ", " : "", v);
        to += buf;
    };
    for (int i = 0; i < 4; ++i) {
        corners += (i ? ", " : "") + vec3(found.corners[i]);
        expected += (i ? ", " : "") + vec3(check.expected[i]);
        list(errors, i, check.detection_error_m[i]);
        list(calib_errors, i, check.calibration_error_m[i]);
    }
    char buf[1200];
    std::snprintf(buf, sizeof buf,
                  "{\"found\": true, \"corners\": [%s], \"corner_error_m\": [%s], \"max_corner_error_m\": %.4f, "
                  "\"keystone_pct\": {\"horizontal\": %.3f, \"vertical\": %.3f, \"diagonal\": %.3f}, "
                  "\"expected_corners\": [%s], \"calibration_error_m\": [%s], \"max_calibration_error_m\": %.4f, "
                  "\"detection_off_m\": %.4f, \"tolerance_m\": %.4f, \"passed\": %s}\n",
                  corners.c_str(), errors.c_str(), check.max_detection_error_m, eq8.horizontal_pct, eq8.vertical_pct,
                  eq8.diagonal_pct, expected.c_str(), calib_errors.c_str(), check.max_calibration_error_m,
                  check.detection_off_m, tolerance, passed ? "true" : "false");
    return buf;
}

/// The picture was found: where its corners landed against where the calibration sends them.
/// Passed: the calibration's error alone. The detection's corners carry the depth sensor's
/// noise, which is no fault of the calibration; it is reported apart.
VerifyAnswer judgeLanding(const VerifyOptions &o, const VerifyInputs &in, const FoundPicture &found,
                          const Rectangle &meant) {
    const auto check = checkLanding(in.projector, in.lit, found, meant.corners);
    if (!check)
        throw InputError(o.calib, "casts the framebuffer's corners off the surface seen in " + o.captures +
                                      " (behind the projector, or along it): not this projector's calibration?");
    const ShapeErrors eq8 = shapeErrors(found.corners);
    requireFiniteLanding(o, found, meant, *check, eq8);
    const double worst = check->max_calibration_error_m;
    const double tolerance = o.tolerance.value_or(calibrationTolerance(in.projector, check->expected));
    VerifyAnswer answer;
    answer.passed = worst <= tolerance;
    answer.json = landingJson(found, *check, eq8, tolerance, answer.passed);
    std::printf(
        "projsurf verify: picture found; corners landed %.1f mm from where the calibration sends them on the "
        "surface seen, at worst (tolerance %.1f mm): %s\n"
        "  the detection's corners: %.1f mm from where the picture landed; they lie up to %.1f mm off the "
        "surface seen (the depth sensor's noise in the detection, not the calibration's error)\n"
        "  eq. 8: horizontal %.2f %%, vertical %.2f %%, diagonal %.2f %%\n",
        worst * 1000, tolerance * 1000, answer.passed ? "passed" : "FAILED", check->max_detection_error_m * 1000,
        check->detection_off_m * 1000, eq8.horizontal_pct, eq8.vertical_pct, eq8.diagonal_pct);
    return answer;
}

void run(const VerifyOptions &o) {
    if (!o.write_card.empty()) {
        writeVerificationCard(o);
        return;
    }
    checkVerifyArguments(o);
    const VerifyInputs in = readVerifyInputs(o);
    const Rectangle meant = meantRectangle(in);
    const FoundPicture found = findProjectedPicture(in.rgb, in.depth, in.camera);
    VerifyAnswer answer;  // not found: `found: false`, exit 0 (the contract); found off target: exit 3
    if (!found.found) {
        answer.json = "{\"found\": false, \"reason\": \"" + found.reason + "\", \"passed\": false}\n";
        std::cout << "projsurf verify: picture not found: " << found.reason << "\n";
    } else {
        answer = judgeLanding(o, in, found, meant);
    }
    if (!o.json.empty()) writeFileAtomic(o.json, answer.json);
    if (!answer.passed) throw ExitStatus{kExitCheckFailed};  // like calibrate's redo: written, but the check failed
}

}  // namespace

void addVerifyCommand(CLI::App &app) {
    auto o = std::make_shared<VerifyOptions>();
    auto *sub = app.add_subcommand("verify",
                                   "closed-loop check: find the projected picture in the colour image and "
                                   "report where its corners landed");
    sub->add_option("--calib", o->calib, "projector calibration YAML");
    sub->add_option("--detection", o->detection, "detection JSON the framebuffer was corrected for");
    sub->add_option("--framebuffer", o->framebuffer,
                    "the framebuffer correct wrote (of the test card) and was projected");
    sub->add_option("--captures", o->captures,
                    "folder with camera.yaml, rgb.png, depth.png taken while it was projected");
    sub->add_option("--json", o->json, "write the result JSON here");
    sub->add_option("--tolerance", o->tolerance,
                    "corner tolerance, m (default: 0.005, or 0.3 deg seen from the projector where that is more: "
                    "0.010 at 2 m)");
    sub->add_option("--write-card", o->write_card, "write the test card (PNG) at --resolution and nothing else");
    sub->add_option("--resolution", o->resolution, "test card width,height, px (--write-card)")->capture_default_str();
    sub->callback([o] { run(*o); });
}

}  // namespace projsurf::cli
