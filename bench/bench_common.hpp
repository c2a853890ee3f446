#pragma once
// Shared by the benchmark executables: test frames, statistics, machine facts, pinning,
// and the keystone warp workload.
#include <opencv2/core.hpp>
#include <memory>
#include <string>
#include <vector>

#include "projsurf/core/camera.hpp"
#include "projsurf/core/cloud.hpp"
#include "projsurf/core/keystone.hpp"
#include "projsurf/core/projector.hpp"

namespace projsurf::bench {

/// One depth frame as the detector sees it: the loaded cloud (file reading is not timed).
struct BenchFrame {
    std::string name;
    CameraIntrinsics camera;
    cv::Mat depth;  ///< CV_16UC1
    Cloud cloud;    ///< organized, camera frame
    std::size_t finite = 0;
};

/// ../shared/data/real next to the source tree (the repository root's sibling).
std::string defaultRealDir();

/// Every sub-folder of `dir` holding depth.png and camera.yaml, sorted by name. Throws
/// InputError when the folder is missing, holds no frame, or a frame is malformed.
std::vector<BenchFrame> loadRealFrames(const std::string &dir);

/// The frame resampled (nearest neighbour) to width x height, intrinsics scaled to match.
BenchFrame resizeFrame(const BenchFrame &frame, int width, int height);

/// Summary of a set of samples (ms).
struct Stats {
    double median = 0.0, p10 = 0.0, p90 = 0.0, mean = 0.0, min = 0.0, max = 0.0;
    std::size_t n = 0;
};
Stats summarize(std::vector<double> samples);

/// Peak resident set of this process so far (getrusage), MiB.
double peakRssMiB();

/// Pins the calling thread (and threads it creates later) to one CPU; false on failure.
bool pinToCpu(int cpu);
/// The CPUs this process may run on, e.g. "0" or "0-1".
std::string allowedCpus();
/// CPU time of the calling thread, ms (CLOCK_THREAD_CPUTIME_ID): what the work cost even
/// when other processes share the core.
double threadCpuMs();
/// The 1, 5 and 15 minute load averages, as /proc/loadavg shows them.
std::string loadAverage();
/// "Model name" from /proc/cpuinfo.
std::string cpuModel();

/// The keystone workload: a BGR picture of the framebuffer's size shown in a representative
/// detected rectangle (a wall 2 m ahead, turned 20 deg), through projsurf's keystone
/// (computeKeystone once, warpToFramebuffer per frame), or through a bare cv::warpPerspective
/// with the same homography into a preallocated framebuffer (`bare`).
class KeystoneWarp {
public:
    explicit KeystoneWarp(const Projector &projector, bool bare = false);
    void run();
    const cv::Mat &output() const { return out_; }
    std::string what() const;

private:
    bool bare_ = false;
    cv::Mat in_, out_;
    std::shared_ptr<const Keystone> keystone_;
};

}  // namespace projsurf::bench
