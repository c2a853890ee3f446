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
#include <unistd.h>

#include "cli/commands.hpp"
#include "projsurf/core/keystone.hpp"
#include "projsurf/core/keystone_warper.hpp"
#include "projsurf/io/detection_json.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/video_files.hpp"
#include "projsurf/io/yaml_files.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

struct CorrectOptions {
    std::string calib, detection, image, video, out, json;
    double fps = 0.0;  // output frame rate for video; 0 = the input's (25 when unknown)
};

nlohmann::json corners(const Corners2 &c) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto &p : c) a.push_back({p.x(), p.y()});
    return a;
}

std::string keystoneJson(const Keystone &k, const std::string &method) {
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
    return j.dump(2) + "\n";
}

/// Progress on stderr: on a terminal one line redrawn in place, [#####.....] 50% 120/240 frames;
/// in a log, a line every 10%.
class Progress {
  public:
    explicit Progress(long total) : total_(total), tty_(::isatty(2) != 0) {}
    void update(long done) {
        if (total_ <= 0) {
            if (tty_ && done % 25 == 0) std::cerr << "\rcorrect: " << done << " frames" << std::flush;
            return;
        }
        const int pct = static_cast<int>(std::min<long>(100, 100 * done / total_));
        if (tty_) {
            if (pct == last_) return;
            const int bar = pct / 4;
            std::cerr << "\rcorrect: [" << std::string(bar, '#') << std::string(25 - bar, '.') << "] " << pct << "% "
                      << done << "/" << total_ << " frames" << std::flush;
        } else {
            if (pct / 10 == last_ / 10 && last_ >= 0) return;
            std::cerr << "correct: " << pct << "% (" << done << "/" << total_ << " frames)\n";
        }
        last_ = pct;
    }
    void finish(long done) {
        if (tty_) std::cerr << "\rcorrect: " << done << " frames done" << std::string(40, ' ') << "\n";
    }

  private:
    long total_;
    bool tty_;
    int last_ = -1;
};

/// Removes the temporary outputs unless released (never a partial output).
struct TempFiles {
    std::vector<std::string> paths;
    bool keep = false;
    ~TempFiles() {
        if (keep) return;
        std::error_code ec;
        for (const auto &p : paths) fs::remove(p, ec);
    }
};

Keystone keystoneFor(const Projector &projector, const DetectionFile &det, cv::Size picture,
                     const std::string &detection_path) {
    const KeystoneResult r = computeKeystone(projector, det.rectangle, picture);
    if (!r.keystone) throw InputError(detection_path, r.problem);
    return *r.keystone;
}

void runVideo(const CorrectOptions &o, const std::string &input, const Projector &projector,
              const DetectionFile &det) {
    cv::VideoCapture cap = openVideoInput(input);
    cv::Mat frame;
    bool first = false;
    try {
        first = cap.read(frame) && !frame.empty();
    } catch (const cv::Exception &) {
    }
    if (!first) throw InputError(input, "no frame could be read");
    if (frame.channels() == 1) cv::cvtColor(frame, frame, cv::COLOR_GRAY2BGR);
    if (frame.channels() == 4) cv::cvtColor(frame, frame, cv::COLOR_BGRA2BGR);
    const Keystone k = keystoneFor(projector, det, frame.size(), o.detection);
    double fps = o.fps > 0 ? o.fps : cap.get(cv::CAP_PROP_FPS);
    if (!(fps > 0 && fps < 1000)) fps = 25.0;  // image sequences carry no rate
    const long total = static_cast<long>(cap.get(cv::CAP_PROP_FRAME_COUNT));

    TempFiles temps;
    const bool sequence_out = isFramePattern(o.out);
    cv::VideoWriter writer;
    std::string tmp_video;
    std::vector<std::pair<std::string, std::string>> renames;  // tmp -> final
    if (!sequence_out) {
        const fs::path out(o.out);
        tmp_video = (out.parent_path() / ("." + out.stem().string() + ".tmp-" + std::to_string(::getpid()) +
                                          out.extension().string()))
                        .string();
        temps.paths.push_back(tmp_video);
        writer = openVideoOutput(tmp_video, o.out, fps, k.framebuffer);
    }
    Progress progress(total);
    long n = 0;
    KeystoneWarper warper(k);  // one keystone for every frame: source positions worked out once
    cv::Mat fb;
    do {
        if (frame.channels() == 1) cv::cvtColor(frame, frame, cv::COLOR_GRAY2BGR);
        if (frame.channels() == 4) cv::cvtColor(frame, frame, cv::COLOR_BGRA2BGR);
        if (frame.size() != k.picture)
            throw InputError(input, "frame " + std::to_string(n) + " has a different size from the first frame");
        if (frame.depth() != CV_8U) frame.convertTo(frame, CV_8U, 1.0 / 257.0);
        warper.warp(frame, fb);
        if (sequence_out) {
            char name[4096];
            std::snprintf(name, sizeof name, o.out.c_str(), static_cast<int>(n));
            const std::string tmp =
                std::string(name) + ".tmp-" + std::to_string(::getpid()) + fs::path(name).extension().string();
            temps.paths.push_back(tmp);
            bool ok = false;
            try {
                ok = cv::imwrite(tmp, fb);
            } catch (const cv::Exception &) {
            }
            if (!ok) throw InputError(name, "cannot write this frame");
            renames.emplace_back(tmp, name);
        } else {
            writer.write(fb);
        }
        ++n;
        progress.update(n);
    } while (cap.read(frame) && !frame.empty());
    progress.finish(n);
    if (!sequence_out) {
        writer.release();
        renames.emplace_back(tmp_video, o.out);
    }
    if (!o.json.empty()) {
        writeFileAtomic(o.json, keystoneJson(k, "eq7"));
    }
    for (const auto &[tmp, final_path] : renames) {
        std::error_code ec;
        fs::rename(tmp, final_path, ec);
        if (ec) throw InputError(final_path, "cannot write: " + ec.message());
    }
    temps.keep = true;
    std::cout << "projsurf correct: " << n << " frames -> " << o.out << "\n";
}

void run(const CorrectOptions &o) {
    if (!o.image.empty() && !o.video.empty()) throw InputError("--image", "give --image or --video, not both");
    const std::string input = o.image.empty() ? o.video : o.image;
    if (input.empty()) throw InputError("correct", "--image (a picture, video or image-sequence pattern) is required");
    const bool video = !o.video.empty() || isVideoPath(input) || isFramePattern(input);
    // Validate every input and output location before any work.
    const Projector projector = readCalibration(o.calib);
    const DetectionFile det = readDetectionJson(o.detection);
    requireWritableLocation(o.out);
    if (!o.json.empty()) requireWritableLocation(o.json);
    if (video) {
        if (isFramePattern(o.out)) {
            if (!isValidFramePattern(o.out))
                throw InputError(o.out, "an output pattern needs exactly one frame-number field such as %04d");
            if (!cv::haveImageWriter(o.out)) throw InputError(o.out, "cannot write images with this extension");
        } else if (videoFourcc(o.out) == 0) {
            throw InputError(o.out, "a corrected video needs a .avi, .mkv, .mp4 or .mov output (or a %04d.png pattern)");
        }
        runVideo(o, input, projector, det);
        return;
    }
    bool can_write = false;
    try {
        can_write = cv::haveImageWriter(o.out);
    } catch (const cv::Exception &) {
    }
    if (!can_write) throw InputError(o.out, "cannot write an image with this extension (use .png)");
    const cv::Mat picture = readImage(input, cv::IMREAD_COLOR);
    const Keystone k = keystoneFor(projector, det, picture.size(), o.detection);
    const cv::Mat fb = warpToFramebuffer(picture, k);
    writeImageAtomic(o.out, fb);
    if (!o.json.empty()) writeFileAtomic(o.json, keystoneJson(k, "eq7"));
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
    sub->callback([opts] { run(*opts); });
}

}  // namespace projsurf::cli
