#include "bench_common.hpp"

#include "projsurf/detection/gravity.hpp"

#include <sched.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::bench {

namespace fs = std::filesystem;

std::string defaultRealDir() { return std::string(PROJSURF_SOURCE_DIR) + "/../shared/data/real"; }

std::vector<BenchFrame> loadRealFrames(const std::string &dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(dir, "not a directory (pass --data DIR with the real frames)");
    std::vector<fs::path> folders;
    for (const auto &entry : fs::directory_iterator(dir, ec))
        if (entry.is_directory() && fs::exists(entry.path() / "depth.png") && fs::exists(entry.path() / "camera.yaml"))
            folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    if (folders.empty()) throw InputError(dir, "no frame folders (each needs depth.png and camera.yaml)");
    std::vector<BenchFrame> frames;
    for (const auto &folder : folders) {
        BenchFrame f;
        f.name = folder.filename().string();
        f.camera = readCamera((folder / "camera.yaml").string());
        const std::string depth_path = (folder / "depth.png").string();
        f.depth = readImage(depth_path, cv::IMREAD_ANYDEPTH);
        if (f.depth.type() != CV_16UC1) throw InputError(depth_path, "not a 16-bit single-channel depth image");
        if (f.depth.cols != f.camera.width || f.depth.rows != f.camera.height)
            throw InputError(depth_path, "size differs from camera.yaml");
        f.cloud = depthToCloud(f.depth, f.camera);
        f.finite = countFinite(f.cloud);
        if (const auto floor = estimateGravityFromFloor(f.cloud, f.gravity)) f.gravity = floor->gravity;
        frames.push_back(std::move(f));
    }
    return frames;
}

std::vector<BenchFrame> simulatorFrames(int max_frames) {
    struct Shot {
        const char *scenario;
        double angle_deg;
        std::vector<double> distances;
    };
    const std::vector<Shot> shots = {{"wall", 27.5, {1.0, 2.0, 3.0}},
                                     {"wall", 17.19, {1.0, 2.0, 3.0}},
                                     {"closet", -26.01, {1.5, 2.0, 3.0}},
                                     {"small_obstacles", 27.5, {1.0, 2.0, 3.0}},
                                     {"big_obstacle", 17.19, {1.0, 2.0, 3.0}}};
    const sim::SensorModel sensor;  // Kinect v1, VGA
    std::vector<BenchFrame> frames;
    unsigned seed = 1;
    for (const auto &shot : shots)
        for (const double d : shot.distances) {
            if (max_frames > 0 && static_cast<int>(frames.size()) >= max_frames) return frames;
            const sim::Scenario sc = sim::makeScenario(shot.scenario, d, shot.angle_deg);
            sim::RgbdFrame r = sim::renderFrame(sc.scene, sensor, seed++);
            BenchFrame f;
            std::ostringstream name;
            name << "sim " << shot.scenario << " " << d << " m " << shot.angle_deg << "°";
            f.name = name.str();
            f.camera = sensor.camera;
            f.depth = r.depth;
            f.cloud = std::move(r.cloud);
            f.finite = countFinite(f.cloud);
            f.gravity = sc.gravity;
            frames.push_back(std::move(f));
        }
    return frames;
}

BenchFrame resizeFrame(const BenchFrame &frame, int width, int height) {
    BenchFrame f;
    f.name = frame.name;
    const double sx = static_cast<double>(width) / frame.depth.cols;
    const double sy = static_cast<double>(height) / frame.depth.rows;
    f.camera = frame.camera;
    f.camera.width = width;
    f.camera.height = height;
    f.camera.fx *= sx;
    f.camera.fy *= sy;
    f.camera.cx = (frame.camera.cx + 0.5) * sx - 0.5;  // pixel centres at integers
    f.camera.cy = (frame.camera.cy + 0.5) * sy - 0.5;
    cv::resize(frame.depth, f.depth, cv::Size(width, height), 0, 0, cv::INTER_NEAREST);
    f.cloud = depthToCloud(f.depth, f.camera);
    f.finite = countFinite(f.cloud);
    f.gravity = frame.gravity;
    return f;
}

Stats summarize(std::vector<double> samples) {
    Stats s;
    s.n = samples.size();
    if (samples.empty()) return s;
    std::sort(samples.begin(), samples.end());
    auto quantile = [&](double q) {  // linear interpolation between order statistics
        const double pos = q * static_cast<double>(samples.size() - 1);
        const std::size_t i = static_cast<std::size_t>(std::floor(pos));
        const std::size_t j = std::min(i + 1, samples.size() - 1);
        return samples[i] + (pos - static_cast<double>(i)) * (samples[j] - samples[i]);
    };
    s.median = quantile(0.5);
    s.p10 = quantile(0.1);
    s.p90 = quantile(0.9);
    s.min = samples.front();
    s.max = samples.back();
    double sum = 0.0;
    for (const double v : samples) sum += v;
    s.mean = sum / static_cast<double>(samples.size());
    return s;
}

double peakRssMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: KiB
}

bool pinToCpu(int cpu) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return sched_setaffinity(0, sizeof(set), &set) == 0;
}

std::string allowedCpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0) return "?";
    std::ostringstream out;
    bool first = true;
    for (int c = 0; c < CPU_SETSIZE; ++c) {
        if (!CPU_ISSET(c, &set)) continue;
        int e = c;
        while (e + 1 < CPU_SETSIZE && CPU_ISSET(e + 1, &set)) ++e;
        out << (first ? "" : ",") << c;
        if (e > c) out << "-" << e;
        first = false;
        c = e;
    }
    return out.str();
}

double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    double a = 0, b = 0, c = 0;
    if (!(in >> a >> b >> c)) return "?";
    std::ostringstream out;
    out << a << " " << b << " " << c;
    return out.str();
}

std::string schedulingPolicy() {
    sched_param param{};
    const int policy = sched_getscheduler(0);
    sched_getparam(0, &param);
    switch (policy) {
    case SCHED_FIFO: return "SCHED_FIFO priority " + std::to_string(param.sched_priority);
    case SCHED_RR: return "SCHED_RR priority " + std::to_string(param.sched_priority);
    default: return "SCHED_OTHER (time-shared: on a busy machine the wall clock exceeds the CPU time)";
    }
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "unknown";
}

KeystoneWarp::KeystoneWarp(const Projector &projector, Kind kind) : kind_(kind) {
    // A picture with detail everywhere (so no path of the warp can skip work).
    in_.create(projector.height, projector.width, CV_8UC3);
    cv::randu(in_, cv::Scalar::all(0), cv::Scalar::all(255));
    cv::GaussianBlur(in_, in_, cv::Size(5, 5), 1.5);
    // A wall 2 m along the projector axis, turned 20 deg about the vertical; the biggest
    // upright rectangle of the picture's aspect (shrunk in 5 % steps) that the projector covers.
    const double yaw = 20.0 * M_PI / 180.0;
    const Eigen::Vector3d normal(std::sin(yaw), 0.0, -std::cos(yaw));
    const Eigen::Vector3d centre = projector.origin + 2.0 * projector.direction.normalized();
    const Plane wall = makePlane(normal, -normal.dot(centre));
    const PlaneFrame frame = makePlaneFrame(wall, Eigen::Vector3d(0, 1, 0), centre);
    const double aspect = static_cast<double>(projector.width) / projector.height;
    for (double h = 2.0 * 2.0 * std::tan(0.5 * projector.fov_v); h > 0.05; h *= 0.95) {
        const Eigen::Vector2d half(0.5 * h * aspect, 0.5 * h);
        const KeystoneResult k = computeKeystone(projector, makeRectangle(frame, -half, half), in_.size());
        if (k.keystone) {
            keystone_ = std::make_shared<const Keystone>(*k.keystone);
            break;
        }
    }
    if (!keystone_) throw std::runtime_error("keystone benchmark: no rectangle fits the projector");
    out_ = cv::Mat(keystone_->framebuffer, CV_8UC3, cv::Scalar::all(0));
    if (kind_ == Kind::Remap) {
        // Bounding box of the picture's quad in the framebuffer, and the inverse mapping.
        std::vector<cv::Point2f> quad;
        for (const auto &c : keystone_->picture_px)
            quad.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
        roi_ = cv::boundingRect(quad) & cv::Rect(0, 0, out_.cols, out_.rows);
        const cv::Matx33d inv = keystone_->homography.inv();
        cv::Mat mapx(roi_.size(), CV_32F), mapy(roi_.size(), CV_32F);
        for (int y = 0; y < roi_.height; ++y)
            for (int x = 0; x < roi_.width; ++x) {
                const cv::Vec3d p = inv * cv::Vec3d(x + roi_.x, y + roi_.y, 1.0);
                mapx.at<float>(y, x) = static_cast<float>(p[0] / p[2]);
                mapy.at<float>(y, x) = static_cast<float>(p[1] / p[2]);
            }
        cv::convertMaps(mapx, mapy, map1_, map2_, CV_16SC2);
    }
    if (kind_ == Kind::Warper || kind_ == Kind::WarperPlain || kind_ == Kind::WarperSsse3) {
        warper_ = std::make_shared<KeystoneWarper>(*keystone_);
        warper_->setSimd(kind_ == Kind::Warper        ? KeystoneWarper::Simd::Best
                         : kind_ == Kind::WarperSsse3 ? KeystoneWarper::Simd::Ssse3
                                                      : KeystoneWarper::Simd::Plain);
    }
}

void KeystoneWarp::run() {
    switch (kind_) {
    case Kind::Projsurf: out_ = warpToFramebuffer(in_, *keystone_); break;
    case Kind::Bare:
        cv::warpPerspective(in_, out_, cv::Mat(keystone_->homography), out_.size(), cv::INTER_LINEAR,
                            cv::BORDER_CONSTANT, cv::Scalar::all(0));
        break;
    case Kind::Remap: {
        cv::Mat roi = out_(roi_);
        cv::remap(in_, roi, map1_, map2_, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
        break;
    }
    case Kind::Warper:
    case Kind::WarperPlain:
    case Kind::WarperSsse3: warper_->warp(in_, out_); break;
    }
}

std::string KeystoneWarp::what() const {
    std::ostringstream out;
    out << (kind_ == Kind::Bare     ? "cv::warpPerspective alone (same homography, output preallocated)"
            : kind_ == Kind::Remap  ? "cv::remap, fixed-point maps over the quad's bounding box built once (experiment)"
            : kind_ == Kind::Warper ? "projsurf::KeystoneWarper built once per detection, warp per frame "
                                      "(keystone_warper.hpp; projsurf correct's video path)"
            : kind_ == Kind::WarperPlain ? "the same KeystoneWarper with its plain C++ blend instead of SIMD"
            : kind_ == Kind::WarperSsse3
                ? "the same KeystoneWarper with SSSE3 but not AVX2"
                : "projsurf::warpToFramebuffer (keystone.hpp; source positions worked out in every call)")
        << ", " << in_.cols << "x" << in_.rows << " BGR picture -> " << out_.cols << "x" << out_.rows << " framebuffer";
    return out.str();
}

}  // namespace projsurf::bench
