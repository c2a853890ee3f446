// projsurf correct: warp a picture (or every frame of a video) into the projector framebuffer so
// that it appears whole and undistorted in the detected rectangle (paper 3.3).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "cli/calibration_input.hpp"
#include "cli/commands.hpp"
#include "projsurf/frontend/render/framebuffer_render.hpp"
#include "projsurf/frontend/render/progress.hpp"
#include "projsurf/frontend/render/rectangle_blanking.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/quiet_stderr.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/formats/video_files.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/keystone/keystone_warper.hpp"
#include "projsurf/people/beam_blanking.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

struct CorrectOptions {
    std::string calib, detection, image, video, out, json;
    std::string cloud, depth, camera;  // the current cloud, for blanking what stands in the beam
    double fps = 0.0;                  // output frame rate for video; 0 = the input's (25 when unknown)
};

nlohmann::json corners(const Corners2 &c) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto &p : c) a.push_back({p.x(), p.y()});
    return a;
}

/// The blanking mask for the current cloud (contract "Blanking"), or empty without one.
using Blanking = frontend::RectangleBlanking;

Blanking blankingFor(const CorrectOptions &o, const Projector &projector, const DetectionFile &det) {
    if (o.cloud.empty() && o.depth.empty()) return {};
    const Cloud cloud = o.cloud.empty() ? readDepthCloud(o.depth, o.camera) : readCloud(o.cloud);
    return frontend::blankingBefore(projector, det.rectangle, cloud);
}

std::string keystoneJson(const Keystone &k, const std::string &method, const Blanking &blanking) {
    nlohmann::json j;
    nlohmann::json h = nlohmann::json::array();
    for (int r = 0; r < 3; ++r) h.push_back({k.homography(r, 0), k.homography(r, 1), k.homography(r, 2)});
    j["homography"] = h;
    j["homography_maps"] = "picture pixel -> framebuffer pixel (pixel centres at integers)";
    j["framebuffer_corners"] = corners(k.picture_px);
    j["corner_order"] = "top-left, top-right, bottom-right, bottom-left";
    j["rectangle_corners_px"] = corners(k.rectangle_px);
    j["framebuffer"] = {{"width", k.framebuffer.width}, {"height", k.framebuffer.height}};
    j["picture"] = {{"width", k.picture.width}, {"height", k.picture.height}};
    nlohmann::json shown = nlohmann::json::array();
    for (const auto &c : k.shown.corners) shown.push_back({c.x(), c.y(), c.z()});
    j["shown"] = {{"corners", shown}, {"width_m", k.shown.width}, {"height_m", k.shown.height}};
    j["method"] = method;
    if (!blanking.mask.empty()) j["blanked_pixels"] = blanking.pixels;
    return j.dump(2) + "\n";
}

/// The keystone of a picture of this size in the detected rectangle; the detection file is
/// named when the picture cannot be shown there.
frontend::FramebufferRender keystoneFor(const Projector &projector, const DetectionFile &det, cv::Size picture,
                                        const std::string &detection_path) {
    frontend::FramebufferRender r = frontend::keystoneFor(projector, det.rectangle, picture, kKeystoneTolerancePx);
    if (!r.keystone) throw InputError(detection_path, r.problem);
    return r;
}

/// " (letterboxed: ...)" when the picture leaves bars of the rectangle dark.
std::string letterboxNote(const frontend::FramebufferRender &r, const DetectionFile &det) {
    if (!r.letterboxed) return "";
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  " (letterboxed: the %dx%d picture fills %.2f x %.2f m of the %.2f x %.2f m rectangle)",
                  r.keystone->picture.width, r.keystone->picture.height, r.keystone->shown.width,
                  r.keystone->shown.height, det.rectangle.width, det.rectangle.height);
    return buf;
}

void runVideo(const CorrectOptions &o, const std::string &input, const Projector &projector, const DetectionFile &det,
              const Blanking &blanking) {
    FrameSource source(input);
    cv::Mat frame;
    if (!source.read(frame)) throw InputError(input, "no frame could be read");
    const frontend::FramebufferRender render = keystoneFor(projector, det, frame.size(), o.detection);
    const Keystone &k = *render.keystone;
    double fps = o.fps > 0 ? o.fps : source.fps();
    if (!(fps > 0 && fps < 1000)) fps = 25.0;  // image sequences carry no rate

    // Every output (the video or the frames, and the JSON) is written beside its target and
    // renamed only when all of them are complete.
    OutputGroup outputs;
    const bool sequence_out = isFramePattern(o.out);
    cv::VideoWriter writer;
    if (!sequence_out) writer = openVideoOutput(outputs.reserve(o.out), o.out, fps, k.framebuffer);
    frontend::ProgressLine progress("correct", "frames", frontend::stderrIsTerminal());
    long n = 0;
    KeystoneWarper warper(k);  // one keystone for every frame: source positions worked out once
    cv::Mat fb;
    do {
        if (frame.size() != k.picture)
            throw InputError(source.current(),
                             "frame " + std::to_string(n) + " has a different size from the first frame");
        warper.warp(frame, fb);
        if (!blanking.mask.empty()) applyBlanking(fb, blanking.mask);
        if (sequence_out) {
            if (static_cast<std::uint64_t>(n) >= limits::kMaxSequenceFrames)
                throw InputError(input, "more than " + std::to_string(limits::kMaxSequenceFrames) + " frames");
            char name[4096];
            // A sequence keeps its numbers (frames/0001.png -> out/0001.png).
            std::snprintf(name, sizeof name, o.out.c_str(), static_cast<int>(n + source.firstNumber()));
            outputs.addImage(name, fb);
        } else {
            QuietStderr quiet;
            writer.write(fb);
        }
        ++n;
        progress.update(n, source.count());
    } while (source.read(frame));
    if (!sequence_out) {
        QuietStderr quiet;
        writer.release();
    }
    if (!o.json.empty()) outputs.addFile(o.json, keystoneJson(k, "eq7", blanking));
    outputs.commit();
    progress.finish(n);
    std::cout << "projsurf correct: " << n << " frames -> " << o.out << letterboxNote(render, det) << "\n";
    // A video's header count can be an estimate (one frame off); more than that short is a
    // file that ends early.
    if (source.count() > 0 && n + 1 < source.count())
        std::cerr << "projsurf: warning: " << input << ": ended after " << n << " of the " << source.count()
                  << " frames its header announces (truncated?); the corrected video has " << n << "\n";
}

void run(const CorrectOptions &o) {
    if (!o.image.empty() && !o.video.empty()) throw InputError("--image", "give --image or --video, not both");
    if (!(o.fps == 0 || (o.fps >= 0.01 && o.fps <= 1000)))
        throw InputError("--fps", "must be 0 (the input's rate) or 0.01-1000 Hz");
    const std::string input = o.image.empty() ? o.video : o.image;
    if (input.empty()) throw InputError("correct", "--image (a picture, video or image-sequence pattern) is required");
    const bool video = !o.video.empty() || isVideoPath(input) || isFramePattern(input);
    // Validate every input and output location before any work.
    const Projector projector = readCalibrationWarned(o.calib);
    const DetectionFile det = readDetectionJson(o.detection);
    if (!o.cloud.empty() && !o.depth.empty()) throw InputError("arguments", "give --cloud or --depth, not both");
    if (!o.depth.empty() && o.camera.empty()) throw InputError("arguments", "--depth needs --camera camera.yaml");
    if (!o.camera.empty() && o.depth.empty()) throw InputError("arguments", "--camera goes with --depth");
    requireWritableLocation(o.out);
    if (!o.json.empty()) requireWritableLocation(o.json);
    if (video) {
        if (isFramePattern(o.out)) {
            if (!isValidFramePattern(o.out))
                throw InputError(o.out, "an output pattern needs exactly one frame-number field such as %04d");
            requireImageWriter(o.out);
        } else if (videoFourcc(o.out) == 0) {
            throw InputError(o.out,
                             "a corrected video needs a .avi, .mkv, .mp4 or .mov output (or a %04d.png pattern)");
        }
        const Blanking blanking = blankingFor(o, projector, det);
        runVideo(o, input, projector, det, blanking);
        if (!blanking.mask.empty()) std::cout << "projsurf correct: blanked_pixels " << blanking.pixels << "\n";
        return;
    }
    requireWritableFile(o.out);
    requireImageWriter(o.out);
    if (!o.json.empty()) requireWritableFile(o.json);
    const cv::Mat picture = readImage(input, cv::IMREAD_COLOR);
    const frontend::FramebufferRender fb =
        frontend::renderFramebuffer(projector, det.rectangle, picture, kKeystoneTolerancePx);
    if (!fb.keystone) throw InputError(o.detection, fb.problem);
    cv::Mat image = fb.image;
    const Blanking blanking = blankingFor(o, projector, det);
    if (!blanking.mask.empty()) applyBlanking(image, blanking.mask);
    // Both outputs, or neither.
    OutputGroup outputs;
    outputs.addImage(o.out, image);
    if (!o.json.empty()) outputs.addFile(o.json, keystoneJson(*fb.keystone, "eq7", blanking));
    outputs.commit();
    std::cout << "projsurf correct: " << picture.cols << "x" << picture.rows << " picture -> " << o.out << " ("
              << image.cols << "x" << image.rows << " framebuffer)" << (o.json.empty() ? "" : " and " + o.json)
              << letterboxNote(fb, det) << "\n";
    if (!blanking.mask.empty()) std::cout << "projsurf correct: blanked_pixels " << blanking.pixels << "\n";
}

}  // namespace

void addCorrectCommand(CLI::App &app) {
    auto opts = std::make_shared<CorrectOptions>();
    auto *sub = app.add_subcommand(
        "correct", "warp a picture or video into the projector framebuffer so it shows undistorted in the rectangle");
    sub->add_option("--calib", opts->calib, "projector calibration YAML")->required();
    sub->add_option("--detection", opts->detection, "detection JSON (projsurf detect --json)")->required();
    sub->add_option("--image", opts->image,
                    "picture to show (PNG, JPEG, ...); a video (.mp4 .avi .mkv .mov) or an image-sequence pattern "
                    "(frames/%04d.png) is corrected frame by frame");
    sub->add_option("--video", opts->video, "video or image-sequence pattern to correct frame by frame");
    sub->add_option("--out", opts->out,
                    "framebuffer image to write (calibration resolution); for a video: .avi (MJPG), .mp4/.mov "
                    "(mp4v), or a pattern such as out/%04d.png")
        ->required();
    sub->add_option("--json", opts->json, "also write the homography and the four framebuffer corners");
    sub->add_option("--fps", opts->fps, "frame rate of the corrected video (default: the input's, else 25)");
    sub->add_option("--cloud", opts->cloud,
                    "current point cloud (PCD or PLY): black out every pixel whose ray meets something between the "
                    "lens and the surface (a person walking in); the JSON adds blanked_pixels");
    sub->add_option("--depth", opts->depth, "current 16-bit depth PNG instead of --cloud; needs --camera");
    sub->add_option("--camera", opts->camera, "camera intrinsics YAML for --depth");
    sub->callback([opts] { run(*opts); });
}

}  // namespace projsurf::cli
