#include "bench_common.hpp"

#include <sched.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/yaml_files.hpp"

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

KeystoneWarp::KeystoneWarp(int width, int height) {
    // A picture with detail everywhere (so no path of the warp can skip work).
    in_.create(height, width, CV_8UC3);
    cv::randu(in_, cv::Scalar::all(0), cv::Scalar::all(255));
    cv::GaussianBlur(in_, in_, cv::Size(5, 5), 1.5);
    // Framebuffer corners -> the corrected quad of a wall seen 20 deg off-axis and a little
    // from below: what a detection at ~2 m typically asks for.
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    const std::vector<cv::Point2f> src = {{0, 0}, {w, 0}, {w, h}, {0, h}};
    const std::vector<cv::Point2f> dst = {
        {0.10f * w, 0.08f * h}, {0.86f * w, 0.15f * h}, {0.84f * w, 0.88f * h}, {0.12f * w, 0.95f * h}};
    homography_ = cv::getPerspectiveTransform(src, dst);
    out_.create(height, width, CV_8UC3);
}

void KeystoneWarp::run() {
    cv::warpPerspective(in_, out_, homography_, out_.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
}

std::string KeystoneWarp::what() const {
    std::ostringstream out;
    out << "cv::warpPerspective, " << in_.cols << "x" << in_.rows << " BGR, bilinear, black border";
    return out.str();
}

}  // namespace projsurf::bench
