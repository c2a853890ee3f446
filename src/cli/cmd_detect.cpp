// projsurf detect: find the biggest upright area a projector can use on a vertical surface.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "cli/calibration_input.hpp"
#include "cli/colour_input.hpp"
#include "cli/commands.hpp"
#include "projsurf/detection/gravity.hpp"
#include "projsurf/frontend/answer/candidates_json.hpp"
#include "projsurf/frontend/answer/continuous_json.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/answer/detection_document.hpp"
#include "projsurf/frontend/answer/detection_summary.hpp"
#include "projsurf/frontend/inputs/bag_frames.hpp"
#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/frontend/render/overlay.hpp"
#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/depth_range_check.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/detector_config_keys.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/gravity_warnings.hpp"
#include "projsurf/frontend/settings/ignored_settings.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"
#include "projsurf/frontend/settings/method_words.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/frontend/settings/shared_settings.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace projsurf::cli {
namespace {

struct DetectOptions {
    std::string cloud, depth, camera, rgb, calib, aspect, json, overlay, gravity,
        method = "default", hull = "concave", bag, topic, info_topic, suitability, config_file;
    bool print_config = false, explain = false, steady = false;
    std::map<std::string, std::string> shared;  ///< the pipeline flags' words, by the settings' shared names
    double min_width = -1.0, min_area = -1.0;   ///< m, m^2; < 0: the method's default (frontend/settings/minimum_size.hpp)
};

/// Options the chosen method does not use (frontend/settings/ignored_settings.hpp).
void warnIfIgnored(const CLI::App &sub, Method method) {
    auto given = [&](const std::string &setting) { return sub.get_option(frontend::optionName(setting))->count() > 0; };
    for (const std::string &w : frontend::ignoredSettingWarnings(method, given, frontend::optionName))
        std::fprintf(stderr, "projsurf: warning: %s\n", w.c_str());
}

/// "paper: " for a setting only the paper method uses, "default: " for one only the default uses.
std::string methodOf(const std::string &setting) {
    auto ignoredBy = [&](Method method) {
        const std::vector<std::string> ignored = frontend::settingsIgnoredBy(method);
        return std::find(ignored.begin(), ignored.end(), setting) != ignored.end();
    };
    return ignoredBy(Method::Default) ? "paper: " : ignoredBy(Method::Paper) ? "default: " : "";
}

/// The detector's settings: the defaults, then --config's file, then the flags given.
DetectorConfig detectorConfig(const DetectOptions &o, const CLI::App &sub) {
    DetectorConfig cfg;
    if (!o.config_file.empty()) frontend::readDetectorConfig(o.config_file, cfg);
    auto given = [&](const std::string &setting) { return sub.get_option(frontend::optionName(setting))->count() > 0; };
    if (given("method")) cfg.method = frontend::parseMethod("--method", o.method);
    if (given("hull")) cfg.paper.hull = frontend::parseHull("--hull", o.hull);
    if (given("suitability")) cfg.suitability.mode = frontend::parseSuitabilityMode("--suitability", o.suitability);
    if (!o.aspect.empty()) cfg.aspect = frontend::parseAspect("--aspect", o.aspect);
    for (const std::string &setting : frontend::sharedNumberSettings())
        if (given(setting))
            frontend::setSharedSetting(cfg, setting, o.shared.at(setting), frontend::optionName(setting));
    return cfg;
}

/// --bag: one detection per cloud (or depth image) of the topic (frontend/inputs/bag_frames.hpp), one
/// JSON object per line (JSON Lines), each with a "bag" key (index, stamp, frame_id, topic).
/// With --json the file is written once all messages were read (never a partial file);
/// without, lines go to stdout as they come. --steady: continuous mode over the messages
/// (tracking/continuous_tracker.hpp), each line with `shown` and `event`; the camera is taken
/// to stand still (its pose the identity), as a bag of the camera alone gives nothing better.
void runBag(const DetectOptions &o, const DetectorConfig &cfg, const Projector &projector,
            const frontend::GravityChoice &gravity, const frontend::MinimumSize &minimum) {
    std::string lines;
    std::size_t found = 0;
    SurfaceDetector detector(projector, cfg);  // one for the whole bag: its buffers are reused
    ContinuousTracker steady(continuousSettings(projector, cfg));
    frontend::BagRequest request;
    request.bag = o.bag;
    request.topic = o.topic;
    request.info_topic = o.info_topic;
    auto detectOne = [&](const Cloud &cloud, const BagCloudInfo &info, const std::string &topic) {
        const Detection det = frontend::detectWithGravity(detector, cloud, gravity, minimum,
                                                          o.bag + ":" + topic + "#" + std::to_string(info.index) +
                                                              withSettings(o.config_file))
                                  .detection;
        nlohmann::json j = frontend::detectionDocument(det, cfg, projector, o.explain);
        if (o.steady) frontend::addContinuousFrame(j, steady.update(det, cloud, Eigen::Isometry3d::Identity()));
        j["bag"] = {{"index", info.index}, {"stamp", info.stamp}, {"frame_id", info.frame_id}, {"topic", topic}};
        found += det.found ? 1 : 0;
        if (o.json.empty())
            std::cout << j.dump() << "\n" << std::flush;
        else
            lines += j.dump() + "\n";
    };
    const frontend::BagFrames read = frontend::forEachBagFrame(request, detectOne);
    if (!read.warning.empty()) std::fprintf(stderr, "projsurf: warning: %s\n", read.warning.c_str());
    if (!o.json.empty()) {
        OutputGroup outputs;
        outputs.addFile(o.json, lines);
        outputs.commit();
        std::printf("%zu %s on %s: %zu with a surface, %zu without\n", read.count, read.what, read.topic.c_str(), found,
                    read.count - found);
    }
}

/// Exactly one input (--cloud, --depth or --bag) and only the options that go with it; refused
/// before any work, and before any output is written.
void checkDetectInputs(const DetectOptions &o) {
    if (o.calib.empty()) throw InputError("--calib is required (see projsurf detect --help)");
    if (!o.bag.empty()) {
        if (!o.cloud.empty() || !o.depth.empty())
            throw InputError("arguments", "give only one of --cloud, --depth or --bag");
        if (!o.overlay.empty() || !o.rgb.empty())
            throw InputError("arguments", "--overlay and --rgb are for one cloud, not --bag");
    } else if (!o.topic.empty() || !o.info_topic.empty()) {
        throw InputError("arguments", "--topic and --camera-info-topic go with --bag");
    } else if (o.steady) {
        throw InputError("arguments", "--steady goes with --bag (a stream of frames); one cloud has nothing to hold");
    } else if (o.cloud.empty() == o.depth.empty()) {
        throw InputError("arguments", "give exactly one of --cloud FILE, --depth FILE or --bag FILE");
    }
    if (!o.depth.empty() && o.camera.empty()) throw InputError("arguments", "--depth needs --camera camera.yaml");
}

void checkDetectOutputs(const DetectOptions &o) {
    for (const auto &out : {o.json, o.overlay})
        if (!out.empty()) requireWritableFile(out);
    if (!o.overlay.empty()) requireImageWriter(o.overlay);
}

/// --calib's projector, with a warning when its fit's verdict is redo.
Projector detectionProjector(const std::string &calib) {
    const Projector projector = readCalibrationWarned(calib);
    if (readCalibrationVerdict(calib) == "redo")
        std::fprintf(stderr,
                     "projsurf: warning: %s: its captures disagree (fit verdict redo); the picture may land "
                     "off the detected area until you calibrate again\n",
                     calib.c_str());
    return projector;
}

/// The method's smallest picture worth showing, or --min-width / --min-area where given.
frontend::MinimumSize minimumSize(const DetectOptions &o, Method method) {
    frontend::MinimumSize minimum = frontend::defaultMinimumSize(method);
    if (o.min_width >= 0.0) minimum.width = o.min_width;
    if (o.min_area >= 0.0) minimum.area = o.min_area;
    return minimum;
}

/// One frame to detect on: the cloud (of --cloud, or of --depth through --camera's camera)
/// and --rgb's colour where it is registered to it (judged by `registration`).
struct DetectInput {
    std::unique_ptr<CameraIntrinsics> camera;  ///< with --depth only
    Cloud cloud;
    cv::Mat color;  ///< empty without --rgb, or when its colour was not used
};

DetectInput readDetectInput(const DetectOptions &o, const RegistrationOptions &registration) {
    DetectInput in;
    if (!o.cloud.empty()) {
        in.cloud = readCloud(o.cloud);
    } else {
        std::vector<std::string> camera_warnings;
        in.camera = std::make_unique<CameraIntrinsics>(readCamera(o.camera, &camera_warnings));
        for (const std::string &w : camera_warnings) std::fprintf(stderr, "projsurf: warning: %s\n", w.c_str());
        in.cloud = readDepthCloud(o.depth, o.camera);
    }
    if (!o.rgb.empty()) in.color = attachColourFile(in.cloud, o.rgb, registration);
    return in;
}

void warnIfSuitabilityHasNoColour(const DetectOptions &o, const Cloud &cloud, Method method) {
    if (!o.suitability.empty() && o.suitability != "off" && !cloud.hasColour() && method == Method::Default)
        std::fprintf(stderr, "projsurf: warning: %s\n",
                     frontend::suitabilityWithoutColourWarning("--suitability " + o.suitability, "--rgb").c_str());
}

const frontend::GravityWords kGravityWords{"--gravity", "--gravity auto"};

/// What the answer says about the gravity used (no floor for --gravity auto, a camera that is
/// not level, a gravity that does not fit the cloud) and about the cloud's depth range.
void warnAboutGravityAndDepth(const DetectOptions &o, const frontend::GravityChoice &gravity_choice,
                              const frontend::GravityDetection &answer, const Cloud &cloud) {
    const frontend::GravityUsed used{gravity_choice, o.gravity.empty(), answer.gravity};
    for (const std::string &w : frontend::gravityUsedWarnings(kGravityWords, used, cloud))
        std::fprintf(stderr, "projsurf: warning: %s\n", w.c_str());
    if (const auto w = frontend::depthRangeWarning(cloud, o.depth.empty() ? o.cloud : o.camera, !o.depth.empty()))
        std::fprintf(stderr, "projsurf: warning: %s\n", w->c_str());
}

/// The JSON (to --json, else stdout) and the overlay: both files, or neither, written beside
/// their targets and renamed once both are there; with --json, the summary on stdout.
void writeDetection(const DetectOptions &o, const Detection &det, const DetectorConfig &cfg, const Projector &projector,
                    const DetectInput &in) {
    const nlohmann::json j = frontend::detectionDocument(det, cfg, projector, o.explain);
    OutputGroup outputs;
    if (!o.json.empty()) outputs.addFile(o.json, j.dump(2) + "\n");
    if (!o.overlay.empty())
        outputs.addImage(o.overlay, renderOverlay(in.cloud, det, cfg, in.camera.get(), in.color, o.explain));
    outputs.commit();
    if (o.json.empty()) {
        std::cout << j.dump(2) << "\n";
    } else {
        std::printf("%s\n", frontend::detectionSummary(det).c_str());
        if (o.explain)
            for (const std::string &line : frontend::candidateLines(det)) std::printf("%s\n", line.c_str());
    }
}

void run(const DetectOptions &o, const CLI::App &sub) {
    if (o.print_config) {  // the settings only: no input is needed or read
        std::cout << frontend::detectorConfigYaml(detectorConfig(o, sub));
        return;
    }
    checkDetectInputs(o);
    const DetectorConfig cfg = detectorConfig(o, sub);
    warnIfIgnored(sub, cfg.method);
    const frontend::GravityChoice gravity_choice = frontend::parseGravityChoice("--gravity", o.gravity);
    checkDetectOutputs(o);
    const Projector projector = detectionProjector(o.calib);
    const frontend::MinimumSize minimum = minimumSize(o, cfg.method);
    if (!o.bag.empty()) return runBag(o, cfg, projector, gravity_choice, minimum);
    const DetectInput in = readDetectInput(o, cfg.suitability.registration);
    warnIfSuitabilityHasNoColour(o, in.cloud, cfg.method);
    SurfaceDetector detector(projector, cfg);
    const frontend::GravityDetection answer =
        frontend::detectWithGravity(detector, in.cloud, gravity_choice, minimum,
                                    (o.cloud.empty() ? o.depth : o.cloud) + withSettings(o.config_file));
    warnAboutGravityAndDepth(o, gravity_choice, answer, in.cloud);
    writeDetection(o, answer.detection, cfg, projector, in);
}

}  // namespace

void addDetectCommand(CLI::App &app) {
    auto o = std::make_shared<DetectOptions>();
    auto *sub = app.add_subcommand("detect", "Find the biggest upright projection area on a vertical surface");
    sub->add_option("--cloud", o->cloud, "Point cloud (PCD or PLY, camera optical frame, metres)");
    sub->add_option("--depth", o->depth, "16-bit depth PNG (0 = no reading); needs --camera");
    sub->add_option("--camera", o->camera, "Camera intrinsics YAML for --depth");
    sub->add_option("--bag", o->bag,
                    "ROS 1 bag: detect on every cloud (or depth image) of --topic, one JSON line per message");
    sub->add_option("--topic", o->topic,
                    "--bag's sensor_msgs/PointCloud2 topic, or depth sensor_msgs/Image topic (16UC1 mm or 32FC1 m); "
                    "optional when the bag has one such topic");
    sub->add_option("--camera-info-topic", o->info_topic,
                    "--bag's camera_info for a depth topic (default: camera_info beside it, or the bag's only one)");
    sub->add_option("--rgb", o->rgb,
                    "Colour PNG registered to the cloud (checked): surface suitability and the overlay");
    sub->add_option(
        "--suitability", o->suitability,
        "With registered colour: off | avoid (default: no picture over dark, glaring, textured or saturated wall) | "
        "prefer (trade a little area for a cleaner wall; docs/suitability.md)");
    sub->add_option("--calib", o->calib, "Projector calibration YAML (required)");
    sub->add_option("--aspect", o->aspect, "Picture aspect ratio W:H (default: the framebuffer's)");
    sub->add_option("--json", o->json, "Write the detection JSON here (else it goes to stdout)");
    sub->add_option("--overlay", o->overlay, "Write a picture of what was detected here (PNG)");
    sub->add_flag("--steady", o->steady,
                  "With --bag: continuous mode over its messages, each line with `shown` (the rectangle to show, "
                  "kept steady) and `event`; the camera is taken to stand still");
    sub->add_flag("--explain", o->explain,
                  "Say why the picture is where it is: every vertical plane considered, its distance and size, and "
                  "why it lost (JSON key candidates, one line each after the summary, outlined on the overlay)");
    sub->add_option("--gravity", o->gravity,
                    "Gravity in the camera frame gx,gy,gz (default 0,1,0), or 'auto' (from the floor)");
    sub->add_option("--method", o->method, "default | paper (the paper's steps, for reproduction)");
    sub->add_option("--hull", o->hull, "paper method: concave | convex hull of the plane");
    sub->add_option("--min-width", o->min_width,
                    "Narrowest picture worth showing, m (default 0.15: text stays readable at 1.5 m; 0 with --method "
                    "paper); below it: found false with the reason")
        ->check(CLI::Range(0.0, 100.0));
    sub->add_option("--min-area", o->min_area,
                    "Smallest picture worth showing, m^2 (default 0.012; 0 with --method paper)")
        ->check(CLI::Range(0.0, 10000.0));
    sub->add_option("--config", o->config_file,
                    "Detector settings YAML: any key --print-config writes (docs/interface.md); the flags below "
                    "override it");
    sub->add_flag("--print-config", o->print_config,
                  "Write the detector settings in effect (defaults, then --config, then the flags) as YAML to "
                  "stdout and exit; nothing else is needed or read");
    // The shared settings: doc and range from the key table, checked by it in detectorConfig().
    for (const std::string &setting : frontend::sharedNumberSettings()) {
        const frontend::ConfigKey &key = frontend::sharedSettingKey(setting);
        sub->add_option(frontend::optionName(setting), o->shared[setting],
                        methodOf(setting) + frontend::sharedSettingHelp(setting))
            ->type_name(key.type == frontend::KeyType::Double ? "FLOAT" : "INT");
    }
    sub->callback([o, sub] { run(*o, *sub); });
}

}  // namespace projsurf::cli
