#pragma once
// Shared by the benchmark executables: test frames, statistics, machine facts, pinning,
// and the keystone warp workload.
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/keystone/keystone_warper.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::bench {

/// One depth frame as the detector sees it: the loaded cloud (file reading is not timed).
struct BenchFrame {
    std::string name;
    CameraIntrinsics camera;
    cv::Mat depth;  ///< CV_16UC1
    Cloud cloud;    ///< organized, camera frame
    std::size_t finite = 0;
    /// Camera frame. Simulated scenes: the scene's. Real frames are hand-held (rolled and
    /// pitched), so: from the floor, as `projsurf detect --gravity auto` and the eval gallery
    /// find it; a robot knows it from tf. Estimated once when loading, not timed.
    Eigen::Vector3d gravity{0.0, 1.0, 0.0};
};

/// ../shared/data/real next to the source tree (the repository root's sibling).
std::string defaultRealDir();

/// Every sub-folder of `dir` holding depth.png and camera.yaml, sorted by name, with gravity
/// from the floor where one is seen (else the level camera's). Throws
/// InputError when the folder is missing, holds no frame, or a frame is malformed.
std::vector<BenchFrame> loadRealFrames(const std::string &dir);

/// The simulator's paper scenes (section 4: uncluttered wall, closet, small and big
/// obstacles) at 1, 2 and 3 m (closet 1.5, 2, 3 m), Kinect v1 sensor model, fixed seeds.
/// `max_frames` > 0 keeps only the first ones (they are rendered on demand).
std::vector<BenchFrame> simulatorFrames(int max_frames = 0);

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
/// This process's scheduling policy, e.g. "SCHED_FIFO priority 10" (run under `chrt -f 10`
/// on a shared machine so that other processes cannot take the pinned core).
std::string schedulingPolicy();
/// "Model name" from /proc/cpuinfo.
std::string cpuModel();

/// The keystone workload: a BGR picture of the framebuffer's size shown in a representative
/// detected rectangle (a wall 2 m ahead, turned 20 deg), through projsurf's keystone
/// (computeKeystone once, warpToFramebuffer per frame), or through a bare cv::warpPerspective
/// with the same homography into a preallocated framebuffer (Bare), or by cv::remap over the
/// picture's bounding box with fixed-point maps built once per detection (Remap: what a
/// video loop could do; the rest of the framebuffer stays black from the first frame), or by
/// projsurf's KeystoneWarper built once per detection (Warper: what `projsurf correct` does
/// for a video; warpToFramebuffer works one out per call), the same with its plain C++ blend
/// instead of SIMD (WarperPlain) or with SSSE3 but not AVX2 (WarperSsse3).
class KeystoneWarp {
public:
    enum class Kind { Projsurf, Bare, Remap, Warper, WarperPlain, WarperSsse3 };
    explicit KeystoneWarp(const Projector &projector, Kind kind = Kind::Projsurf);
    void run();
    const cv::Mat &output() const { return out_; }
    std::string what() const;

private:
    Kind kind_ = Kind::Projsurf;
    cv::Mat in_, out_;
    cv::Mat map1_, map2_;  ///< Remap: CV_16SC2 + CV_16UC1 over roi_
    cv::Rect roi_;
    std::shared_ptr<const Keystone> keystone_;
    std::shared_ptr<KeystoneWarper> warper_;  ///< Warper*
};

}  // namespace projsurf::bench
