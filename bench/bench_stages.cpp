// projsurf_bench_stages: Google Benchmark, one benchmark per stage. Every benchmark cycles
// through the real frames (one frame per iteration), so a time is "per VGA frame, averaged
// over the frames". Our detector's stages are reported as counters (<stage>_ms) of the
// detect benchmarks, since the detector times them itself; the stock-PCL stages are separate
// benchmarks, each fed the previous stage's output computed beforehand.
//
//   projsurf_bench_stages [--data=DIR] [Google Benchmark flags, e.g. --benchmark_filter=stock]
// Pins itself to CPU 0 (set PROJSURF_BENCH_NO_PIN=1 to leave affinity alone).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "bench_blanking.hpp"
#include "bench_common.hpp"
#include "pcl_reference.hpp"
#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/detection/rectangle_search.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/camera.hpp"

namespace {

using namespace projsurf;
using namespace projsurf::bench;

std::string g_data_dir;

const std::vector<BenchFrame> &frames() {
    static const std::vector<BenchFrame> f = loadRealFrames(g_data_dir);
    return f;
}

/// The stock pipeline's intermediate results for one frame, computed once.
struct StockStages {
    std::string name;
    PclCloud::Ptr cloud, voxels, projected;
    SacPlane sac;
    std::vector<std::vector<Eigen::Vector3d>> hull;
    PlaneFrame frame;
    FreeRaster raster;
    Rectangle rect;
    PclCloud::Ptr cropped;
    bool has_plane = false, has_raster = false, has_rect = false;
    StockConfig config;  ///< with the frame's gravity
};

const std::vector<StockStages> &stockStages() {
    static const std::vector<StockStages> all = [] {
        const Projector projector = sim::exampleProjector();
        std::vector<StockStages> out;
        for (const auto &f : frames()) {
            StockStages s;
            s.name = f.name;
            s.config.gravity = f.gravity;
            const StockConfig &config = s.config;
            s.cloud = toPcl(f.cloud);
            s.voxels = voxelGrid(s.cloud, config.voxel_leaf);
            s.sac = segmentVerticalPlane(s.voxels, config);
            s.has_plane = s.sac.inliers.size() >= 3;
            if (s.has_plane) {
                s.projected = extractAndProject(s.voxels, s.sac);
                s.hull = concaveHull(s.projected, config.alpha);
                Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
                double n = 0;
                for (const auto &loop : s.hull)
                    for (const auto &p : loop) {
                        anchor += p;
                        n += 1;
                    }
                const Plane plane = makePlane(s.sac.coefficients.head<3>(), s.sac.coefficients[3]);
                s.frame = makePlaneFrame(plane, config.gravity,
                                         n > 0 ? Eigen::Vector3d(anchor / n) : plane.project({0, 0, 2}));
                s.raster = rasterFreeSpace(s.frame, s.hull, projector, config.cell);
                s.has_raster = s.raster.ok;
            }
            if (s.has_raster) {
                const auto cells = largestAspectRect(s.raster.free, projector.aspect(), s.raster.prefer);
                if (cells) {
                    const double c = s.raster.cell;
                    const Eigen::Vector2d lo(s.raster.origin.x() + cells->col * c,
                                             s.raster.origin.y() - (cells->row + cells->rows) * c);
                    const Eigen::Vector2d hi(lo.x() + cells->cols * c, s.raster.origin.y() - cells->row * c);
                    s.rect = makeRectangle(s.frame, lo, hi);
                    s.has_rect = true;
                    s.cropped = cropToRectangle(s.cloud, s.frame, s.rect);
                }
            }
            out.push_back(std::move(s));
        }
        return out;
    }();
    return all;
}

/// The frames whose stock pipeline reached a given stage.
std::vector<const StockStages *> reaching(bool StockStages::*flag) {
    std::vector<const StockStages *> out;
    for (const auto &s : stockStages())
        if (!flag || s.*flag) out.push_back(&s);
    return out;
}

void setFrameCounters(benchmark::State &state, std::size_t used) {
    state.counters["frames"] = static_cast<double>(used);
}

// --- ours ----------------------------------------------------------------------------------

void detectBench(benchmark::State &state, Method method) {
    const auto &f = frames();
    DetectorConfig config;
    config.method = method;
    SurfaceDetector detector(sim::exampleProjector(), config);  // one for the stream, each frame with its gravity
    std::map<std::string, double> sums;
    double found = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i++ % f.size();
        Detection d = detector.detect(f[k].cloud, f[k].gravity);
        benchmark::DoNotOptimize(d);
        for (const auto &[key, ms] : d.timing_ms) sums[key] += ms;
        found += d.found;
    }
    for (const auto &[key, sum] : sums)
        state.counters[key + "_ms"] = benchmark::Counter(sum, benchmark::Counter::kAvgIterations);
    state.counters["found"] = benchmark::Counter(found, benchmark::Counter::kAvgIterations);
    setFrameCounters(state, f.size());
}
void BM_OursDefaultDetect(benchmark::State &state) { detectBench(state, Method::Default); }

/// The real frames whose colour (rgb.png) passes the registration check, colour attached
/// (reading and checking are not timed).
const std::vector<BenchFrame> &colourFrames() {
    static const std::vector<BenchFrame> out = [] {
        std::vector<BenchFrame> kept;
        for (const auto &f : frames()) {
            const std::string path = g_data_dir + "/" + f.name + "/rgb.png";
            const cv::Mat bgr = std::filesystem::exists(path) ? cv::imread(path, cv::IMREAD_COLOR) : cv::Mat();
            if (bgr.empty() || !checkColourRegistration(f.cloud, bgr, RegistrationOptions{}).registered) continue;
            BenchFrame c = f;
            if (attachColour(c.cloud, bgr)) kept.push_back(std::move(c));
        }
        return kept;
    }();
    return out;
}

/// Surface suitability: the default detection on the frames with registered
/// colour, Arg 0 with --suitability off, 1 avoid, 2 prefer; its cost is the suitability_ms
/// counter plus the difference of the totals.
void BM_OursDefaultDetectColour(benchmark::State &state) {
    const auto &f = colourFrames();
    DetectorConfig config;
    config.suitability.mode =
        std::array{SuitabilityMode::Off, SuitabilityMode::Avoid, SuitabilityMode::Prefer}[state.range(0)];
    SurfaceDetector detector(sim::exampleProjector(), config);
    std::map<std::string, double> sums;
    std::size_t i = 0;
    for (auto _ : state) {
        if (f.empty()) break;
        const std::size_t k = i++ % f.size();
        Detection d = detector.detect(f[k].cloud, f[k].gravity);
        benchmark::DoNotOptimize(d);
        for (const auto &[key, ms] : d.timing_ms) sums[key] += ms;
    }
    for (const auto &[key, sum] : sums)
        state.counters[key + "_ms"] = benchmark::Counter(sum, benchmark::Counter::kAvgIterations);
    setFrameCounters(state, f.size());
}
void BM_OursPaperDetect(benchmark::State &state) { detectBench(state, Method::Paper); }

void BM_DepthToCloud(benchmark::State &state) {  // not part of the detection time
    const auto &f = frames();
    std::size_t i = 0;
    for (auto _ : state) {
        const BenchFrame &fr = f[i++ % f.size()];
        Cloud c = depthToCloud(fr.depth, fr.camera);
        benchmark::DoNotOptimize(c.points.data());
    }
    setFrameCounters(state, f.size());
}

// --- stock PCL, stage by stage --------------------------------------------------------------

void BM_StockVoxelGrid(benchmark::State &state) {
    const auto s = reaching(nullptr);
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(voxelGrid(s[i++ % s.size()]->cloud, StockConfig{}.voxel_leaf));
    setFrameCounters(state, s.size());
}
void BM_StockRansac(benchmark::State &state) {
    const auto s = reaching(nullptr);
    std::size_t i = 0;
    for (auto _ : state) {
        const StockStages *x = s[i++ % s.size()];
        benchmark::DoNotOptimize(segmentVerticalPlane(x->voxels, x->config));
    }
    setFrameCounters(state, s.size());
}
void BM_StockExtractProject(benchmark::State &state) {
    const auto s = reaching(&StockStages::has_plane);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    std::size_t i = 0;
    for (auto _ : state) {
        const StockStages *x = s[i++ % s.size()];
        benchmark::DoNotOptimize(extractAndProject(x->voxels, x->sac));
    }
    setFrameCounters(state, s.size());
}
void BM_StockConcaveHull(benchmark::State &state) {
    const auto s = reaching(&StockStages::has_plane);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(concaveHull(s[i++ % s.size()]->projected, StockConfig{}.alpha));
    setFrameCounters(state, s.size());
}
void BM_StockConvexHull(benchmark::State &state) {
    const auto s = reaching(&StockStages::has_plane);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(convexHull(s[i++ % s.size()]->projected));
    setFrameCounters(state, s.size());
}
void BM_StockWorkspaceRaster(benchmark::State &state) {
    const auto s = reaching(&StockStages::has_plane);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    const Projector projector;
    std::size_t i = 0;
    for (auto _ : state) {
        const StockStages *x = s[i++ % s.size()];
        benchmark::DoNotOptimize(rasterFreeSpace(x->frame, x->hull, projector, StockConfig{}.cell));
    }
    setFrameCounters(state, s.size());
}
void BM_SharedRectangleSearch(benchmark::State &state) {  // projsurf core, on the stock rasters
    const auto s = reaching(&StockStages::has_raster);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    const double aspect = sim::exampleProjector().aspect();
    std::size_t i = 0;
    for (auto _ : state) {
        const StockStages *x = s[i++ % s.size()];
        benchmark::DoNotOptimize(largestAspectRect(x->raster.free, aspect, x->raster.prefer));
    }
    setFrameCounters(state, s.size());
}
void BM_StockCrop(benchmark::State &state) {
    const auto s = reaching(&StockStages::has_rect);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    std::size_t i = 0;
    for (auto _ : state) {
        const StockStages *x = s[i++ % s.size()];
        benchmark::DoNotOptimize(cropToRectangle(x->cloud, x->frame, x->rect));
    }
    setFrameCounters(state, s.size());
}
void BM_StockOutliers(benchmark::State &state) {
    const auto s = reaching(&StockStages::has_rect);
    if (s.empty()) return state.SkipWithError("no frame reached this stage");
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(countOutliers(*s[i++ % s.size()]->cropped, 0.05));
    setFrameCounters(state, s.size());
}
void BM_StockTotal(benchmark::State &state) {
    const auto s = reaching(nullptr);
    std::vector<StockPipeline> stock;  // one per frame: each frame's gravity
    for (const StockStages *x : s) {
        StockConfig config = x->config;
        config.convex_too = false;  // the alternative hull is not part of the pipeline's time
        stock.emplace_back(sim::exampleProjector(), config);
    }
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i++ % s.size();
        benchmark::DoNotOptimize(stock[k].run(s[k]->cloud));
    }
    setFrameCounters(state, s.size());
}

// --- keystone ------------------------------------------------------------------------------

void BM_KeystoneWarp1280x800(benchmark::State &state) {
    // 0: projsurf::warpToFramebuffer, 1: bare cv::warpPerspective, 2: cv::remap with maps built once,
    // 3: projsurf::KeystoneWarper built once, 4: the same with its plain C++ blend, 5: SSSE3 only
    KeystoneWarp warp(sim::exampleProjector(), static_cast<KeystoneWarp::Kind>(state.range(0)));
    for (auto _ : state) {
        warp.run();
        benchmark::DoNotOptimize(warp.output().data);
    }
}

// --- blanking -------------------------------------------------------------------------------

void BM_BeamBlanking(benchmark::State &state) {
    // One VGA cloud per iteration, cycling through the blanking cases (bench_blanking.hpp).
    static const std::vector<BlankingCase> cases = blankingCases(frames(), sim::exampleProjector());
    BeamBlanker blanker(sim::exampleProjector());
    std::size_t k = 0;
    for (auto _ : state) {
        const auto &c = cases[k++ % cases.size()];
        benchmark::DoNotOptimize(blanker.compute(c.cloud, c.plane).data);
    }
    state.counters["clouds"] = static_cast<double>(cases.size());
}

// --- scale: time against the number of pixels ---------------------------------------------

/// The real frames resampled to width x height; one size cached at a time.
const std::vector<BenchFrame> &resized(int width, int height) {
    static std::pair<int, int> size{0, 0};
    static std::vector<BenchFrame> cache;
    if (size != std::make_pair(width, height)) {
        cache.clear();
        for (const auto &f : frames()) cache.push_back(resizeFrame(f, width, height));
        size = {width, height};
    }
    return cache;
}

void BM_ScaleOursDefault(benchmark::State &state) {
    const auto &f = resized(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    SurfaceDetector detector(sim::exampleProjector(), DetectorConfig{});
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i++ % f.size();
        benchmark::DoNotOptimize(detector.detect(f[k].cloud, f[k].gravity));
    }
    state.SetComplexityN(state.range(0) * state.range(1));
}
void BM_ScaleStock(benchmark::State &state) {
    const auto &f = resized(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    std::vector<PclCloud::Ptr> clouds;
    std::vector<StockPipeline> stock;
    for (const auto &fr : f) {
        clouds.push_back(toPcl(fr.cloud));
        StockConfig config;
        config.convex_too = false;
        config.gravity = fr.gravity;
        stock.emplace_back(sim::exampleProjector(), config);
    }
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i++ % clouds.size();
        benchmark::DoNotOptimize(stock[k].run(clouds[k]));
    }
    state.SetComplexityN(state.range(0) * state.range(1));
}

void scaleArgs(benchmark::internal::Benchmark *b) {
    for (const auto &[w, h] : std::vector<std::pair<int, int>>{
             {160, 120}, {320, 240}, {640, 360}, {640, 480}, {848, 480}, {960, 720}, {1280, 720}})
        b->Args({w, h});
}

}  // namespace

BENCHMARK(BM_OursDefaultDetect)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursDefaultDetectColour)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursPaperDetect)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DepthToCloud)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockVoxelGrid)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockRansac)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockExtractProject)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockConcaveHull)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockConvexHull)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockWorkspaceRaster)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SharedRectangleSearch)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockCrop)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockOutliers)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StockTotal)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BeamBlanking)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_KeystoneWarp1280x800)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Arg(4)
    ->Arg(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ScaleOursDefault)
    ->Apply(scaleArgs)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ScaleStock)->Apply(scaleArgs)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char **argv) {
    g_data_dir = defaultRealDir();
    if (const char *env = std::getenv("PROJSURF_REAL_DIR")) g_data_dir = env;
    std::vector<char *> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strncmp(argv[i], "--data=", 7) == 0)
            g_data_dir = argv[i] + 7;
        else
            args.push_back(argv[i]);
    }
    int n = static_cast<int>(args.size());
    cv::setNumThreads(1);
    const char *no_pin = std::getenv("PROJSURF_BENCH_NO_PIN");
    if (!(no_pin && *no_pin == '1') && !pinToCpu(0)) std::cerr << "projsurf_bench_stages: could not pin to CPU 0\n";
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 2;
    try {
        frames();  // load (and validate) before timing anything
    } catch (const InputError &e) {
        std::cerr << "projsurf_bench_stages: error: " << e.what() << "\n";
        return 2;
    }
    benchmark::AddCustomContext("cpu_affinity", allowedCpus());
    benchmark::AddCustomContext("frames_dir", g_data_dir);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
