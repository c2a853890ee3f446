// projsurf detect: find the biggest upright area a projector can use on a vertical surface.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "cli/commands.hpp"
#include "cli/parse.hpp"
#include "projsurf/core/gravity.hpp"
#include "projsurf/io/cloud_io.hpp"
#include "projsurf/io/detection_json.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/overlay.hpp"
#include "projsurf/io/rosbag_clouds.hpp"
#include "projsurf/io/yaml_files.hpp"

namespace projsurf::cli {
namespace {

constexpr double kTiltWarningDeg = 5.0;  ///< deg, a floor this far from level means the camera is not level

struct DetectOptions {
    std::string cloud, depth, camera, rgb, calib, aspect, json, overlay, gravity, method = "default",
        hull = "concave", bag, topic;
    DetectorConfig config;
};

/// detectSurface, with a library failure on this cloud (an OpenCV assertion) reported as
/// a problem of the input file, on one line.
Detection detectChecked(SurfaceDetector &detector, const Cloud &cloud, const Eigen::Vector3d &gravity,
                        const std::string &source) {
    try {
        return detector.detect(cloud, gravity);
    } catch (const cv::Exception &e) {
        throw InputError(source, "cannot be processed (" + e.func + ": " + e.err + ")");
    }
}

/// A level camera is assumed (no --gravity), but the floor says the camera is tilted.
void warnIfTilted(const Cloud &cloud) {
    const Eigen::Vector3d level = SurfaceDetector::levelGravity();
    const auto floor = estimateGravityFromFloor(cloud, level);
    if (!floor) return;
    const double deg = std::acos(std::clamp(floor->gravity.dot(level), -1.0, 1.0)) * 180.0 / M_PI;
    if (deg > kTiltWarningDeg)
        std::fprintf(stderr,
                     "projsurf: warning: the floor says the camera is tilted %.0f deg from level; give --gravity auto "
                     "(or the robot's gravity) so that the picture stands upright\n",
                     deg);
}

/// Depths that no RGB-D camera reads (median beyond 10 m or nearer than 0.2 m): a wrong
/// depth_scale in the camera file is the usual cause.
void warnIfImplausibleDepth(const Cloud &cloud, const std::string &camera_file) {
    std::vector<float> z;
    for (std::size_t i = 0; i < cloud.points.size(); i += 37)
        if (isFinite(cloud.points[i])) z.push_back(cloud.points[i].z());
    if (z.size() < 100) return;
    std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
    const float median = z[z.size() / 2];
    if (median > 10.0f || median < 0.2f)
        std::fprintf(stderr, "projsurf: warning: %s: the median depth is %.2f m, outside what RGB-D cameras read; "
                             "check its depth_scale (depth PNG units per metre)\n",
                     camera_file.c_str(), median);
}

/// Options the chosen method does not use.
void warnIfIgnored(const CLI::App &sub, Method method) {
    const std::vector<const char *> paper_only{"--hull", "--voxel-leaf", "--ransac-distance", "--max-outliers"};
    const std::vector<const char *> default_only{"--cell", "--max-planes", "--max-outlier-fraction"};
    for (const char *name : method == Method::Paper ? default_only : paper_only)
        if (sub.get_option(name)->count() > 0)
            std::fprintf(stderr, "projsurf: warning: %s is ignored by the %s method\n", name,
                         method == Method::Paper ? "paper" : "default");
}

/// --bag: one detection per cloud of the topic, one JSON object per line (JSON Lines), each
/// with a "bag" key (index, stamp, frame_id). With --json the file is written once all
/// messages were read (never a partial file); without, lines go to stdout as they come.
void runBag(const DetectOptions &o, const DetectorConfig &cfg, const Projector &projector, const Eigen::Vector3d &base_gravity,
            bool auto_gravity) {
    std::string lines;
    std::size_t found = 0;
    SurfaceDetector detector(projector, cfg);  // one for the whole bag: its buffers are reused
    const std::size_t n = forEachBagCloud(o.bag, o.topic, [&](const Cloud &cloud, const BagCloudInfo &info) {
        Eigen::Vector3d gravity = base_gravity;
        if (auto_gravity)
            if (const auto g = estimateGravityFromFloor(cloud, gravity)) gravity = g->gravity;
        const Detection det = detectChecked(detector, cloud, gravity, o.bag + ":" + o.topic + "#" + std::to_string(info.index));
        nlohmann::json j = detectionToJson(det, cfg, &projector);
        j["bag"] = {{"index", info.index}, {"stamp", info.stamp}, {"frame_id", info.frame_id}, {"topic", o.topic}};
        found += det.found ? 1 : 0;
        if (o.json.empty()) std::cout << j.dump() << "\n" << std::flush;
        else lines += j.dump() + "\n";
    });
    if (!o.json.empty()) {
        OutputGroup outputs;
        outputs.addFile(o.json, lines);
        outputs.commit();
        std::printf("%zu clouds on %s: %zu with a surface, %zu without\n", n, o.topic.c_str(), found, n - found);
    }
}

void run(const DetectOptions &o, const CLI::App &sub) {
    // Validate every input before any work, and before any output is written.
    if (!o.bag.empty()) {
        if (!o.cloud.empty() || !o.depth.empty()) throw InputError("arguments", "give only one of --cloud, --depth or --bag");
        if (o.topic.empty()) throw InputError("arguments", "--bag needs --topic (a sensor_msgs/PointCloud2 topic)");
        if (!o.overlay.empty() || !o.rgb.empty()) throw InputError("arguments", "--overlay and --rgb are for one cloud, not --bag");
    } else if (!o.topic.empty()) {
        throw InputError("arguments", "--topic goes with --bag");
    } else if (o.cloud.empty() == o.depth.empty()) {
        throw InputError("arguments", "give exactly one of --cloud FILE, --depth FILE or --bag FILE");
    }
    if (!o.depth.empty() && o.camera.empty()) throw InputError("arguments", "--depth needs --camera camera.yaml");
    DetectorConfig cfg = o.config;
    if (o.method == "paper") cfg.method = Method::Paper;
    else if (o.method == "default") cfg.method = Method::Default;
    else throw InputError("--method", "expected 'default' or 'paper', got '" + o.method + "'");
    if (o.hull == "concave") cfg.paper.hull = HullKind::Concave;
    else if (o.hull == "convex") cfg.paper.hull = HullKind::Convex;
    else throw InputError("--hull", "expected 'concave' or 'convex', got '" + o.hull + "'");
    warnIfIgnored(sub, cfg.method);
    const bool auto_gravity = o.gravity == "auto";
    Eigen::Vector3d gravity = SurfaceDetector::levelGravity();
    if (!o.gravity.empty() && !auto_gravity) gravity = parseVector3("--gravity", o.gravity);
    if (!o.aspect.empty()) cfg.aspect = parseAspect("--aspect", o.aspect);
    for (const auto &out : {o.json, o.overlay})
        if (!out.empty()) requireWritableFile(out);
    if (!o.overlay.empty()) requireImageWriter(o.overlay);

    const Projector projector = readCalibration(o.calib);
    if (!o.bag.empty()) return runBag(o, cfg, projector, gravity, auto_gravity);
    std::unique_ptr<CameraIntrinsics> camera;
    Cloud cloud;
    if (!o.cloud.empty()) {
        cloud = readCloud(o.cloud);
    } else {
        camera = std::make_unique<CameraIntrinsics>(readCamera(o.camera));
        cloud = readDepthCloud(o.depth, o.camera);
    }
    cv::Mat color;
    if (!o.rgb.empty()) {
        color = readImage(o.rgb, cv::IMREAD_COLOR);
        if (cloud.organized() && (color.cols != cloud.width || color.rows != cloud.height))
            throw InputError(o.rgb, "colour image is " + std::to_string(color.cols) + "x" + std::to_string(color.rows) +
                                        ", the cloud is " + std::to_string(cloud.width) + "x" + std::to_string(cloud.height));
    }

    if (auto_gravity) {
        // No IMU: take "down" from the floor when one is in view, else keep a level camera.
        if (const auto g = estimateGravityFromFloor(cloud, gravity)) gravity = g->gravity;
        else std::fprintf(stderr, "projsurf: warning: --gravity auto found no floor; assuming a level camera\n");
    } else if (o.gravity.empty()) {
        warnIfTilted(cloud);
    }
    if (!o.depth.empty()) warnIfImplausibleDepth(cloud, o.camera);
    SurfaceDetector detector(projector, cfg);
    const Detection det = detectChecked(detector, cloud, gravity, o.cloud.empty() ? o.depth : o.cloud);
    const nlohmann::json j = detectionToJson(det, cfg, &projector);
    // Both outputs, or neither: written beside their targets, renamed once both are there.
    OutputGroup outputs;
    if (!o.json.empty()) outputs.addFile(o.json, j.dump(2) + "\n");
    if (!o.overlay.empty()) outputs.addImage(o.overlay, renderOverlay(cloud, det, cfg, camera.get(), color));
    outputs.commit();
    if (o.json.empty()) {
        std::cout << j.dump(2) << "\n";
    } else if (det.found) {
        std::printf("found: %.2f x %.2f m (%.2f m^2) on a plane %.2f m away at %.1f deg; %.1f ms\n", det.rectangle.width,
                    det.rectangle.height, det.rectangle.area(), det.plane.d, det.orientation_deg, det.timing_ms.at("total"));
    } else {
        std::printf("not found: %s\n", det.reason.c_str());
    }
}

}  // namespace

void addDetectCommand(CLI::App &app) {
    auto o = std::make_shared<DetectOptions>();
    auto *sub = app.add_subcommand("detect", "Find the biggest upright projection area on a vertical surface");
    sub->add_option("--cloud", o->cloud, "Point cloud (PCD or PLY, camera optical frame, metres)");
    sub->add_option("--depth", o->depth, "16-bit depth PNG (0 = no reading); needs --camera");
    sub->add_option("--camera", o->camera, "Camera intrinsics YAML for --depth");
    sub->add_option("--bag", o->bag, "ROS 1 bag: detect on every cloud of --topic, one JSON line per message");
    sub->add_option("--topic", o->topic, "sensor_msgs/PointCloud2 topic in --bag");
    sub->add_option("--rgb", o->rgb, "Colour PNG registered to the cloud, for the overlay");
    sub->add_option("--calib", o->calib, "Projector calibration YAML")->required();
    sub->add_option("--aspect", o->aspect, "Picture aspect ratio W:H (default: the framebuffer's)");
    sub->add_option("--json", o->json, "Write the detection JSON here (else it goes to stdout)");
    sub->add_option("--overlay", o->overlay, "Write a picture of what was detected here (PNG)");
    sub->add_option("--gravity", o->gravity, "Gravity in the camera frame gx,gy,gz (default 0,1,0), or 'auto' (from the floor)");
    sub->add_option("--method", o->method, "default | paper (the paper's steps, for reproduction)");
    sub->add_option("--hull", o->hull, "paper method: concave | convex hull of the plane");
    auto &c = o->config;
    sub->add_option("--max-tilt", c.max_tilt, "Vertical tolerance, rad (paper 3.2.1)")->check(CLI::Range(0.0, 1.5));
    sub->add_option("--seed", c.seed, "RANSAC random seed");
    sub->add_option("--voxel-leaf", c.paper.voxel_leaf, "paper: voxel side, m")->check(CLI::Range(0.001, 1.0));
    sub->add_option("--ransac-distance", c.paper.ransac_distance, "paper: RANSAC inlier distance, m")->check(CLI::Range(0.001, 1.0));
    sub->add_option("--max-outliers", c.paper.max_outliers, "paper: outliers that reject a surface")->check(CLI::NonNegativeNumber);
    sub->add_option("--cell", c.free_space.cell, "default: free-space raster cell, m")->check(CLI::Range(0.002, 0.5));
    sub->add_option("--max-planes", c.planes.max_planes, "default: vertical planes considered")->check(CLI::Range(1, 20));
    sub->add_option("--max-outlier-fraction", c.check.max_outlier_fraction, "default: outlier share that rejects an area")
        ->check(CLI::Range(0.0, 1.0));
    sub->callback([o, sub] { run(*o, *sub); });
}

}  // namespace projsurf::cli
