// projsurf_bench: per-stage timing of the detector against a stock-PCL pipeline of the
// paper's steps, on the same frames in the same run; keystone warp time; peak memory; and
// (--scale) time against the number of points. Prints Markdown tables on stdout (progress on
// stderr). Run pinned to one core (it pins itself to CPU 0 unless --cpu -1).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <pcl/pcl_config.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bench_blanking.hpp"
#include "bench_common.hpp"
#include "bench_plan.hpp"
#include "pcl_reference.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/projector.hpp"

namespace {

using namespace projsurf;
using namespace projsurf::bench;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

std::string fmt(double v) {
    char buf[32];
    if (!std::isfinite(v)) return "-";
    std::snprintf(buf, sizeof(buf), std::fabs(v) < 0.1 ? "%.3f" : (std::fabs(v) < 100 ? "%.2f" : "%.0f"), v);
    return buf;
}
std::string spread(const Stats &s) { return fmt(s.p10) + "–" + fmt(s.p90); }
std::string ratio(double stock, double ours) {
    if (!(ours > 0.0) || !std::isfinite(stock)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof(buf), stock / ours >= 10 ? "%.0fx" : "%.1fx", stock / ours);
    return buf;
}

// --- the three pipelines behind one interface --------------------------------------------

/// One timed run: wall-clock total and the stages the pipeline reports.
struct Run {
    double wall_ms = 0.0;
    double cpu_ms = 0.0;  ///< thread CPU time of the same run
    std::map<std::string, double> stages;
};

/// Outcome of a frame, for the accuracy side of the table.
struct Outcome {
    bool found = false;
    std::string reason;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    double area = 0.0;
    int outliers = 0, check_points = 0;
    int planes = 0;  ///< vertical planes the pipeline considered
};

struct Pipeline {
    std::string name;
    std::function<void(const BenchFrame &)> prepare;        ///< untimed per-frame setup
    std::function<Run(const BenchFrame &, Outcome &)> run;  ///< one timed detection
};

Pipeline oursPipeline(const std::string &name, const Projector &projector, Method method) {
    // One detector reused over the frame stream (each frame with its gravity), as the ROS node does.
    DetectorConfig config;
    config.method = method;
    auto detector = std::make_shared<SurfaceDetector>(projector, config);
    Pipeline p;
    p.name = name;
    p.prepare = [](const BenchFrame &) {};
    p.run = [detector](const BenchFrame &frame, Outcome &out) {
        Run r;
        const double c0 = threadCpuMs();
        const auto t0 = Clock::now();
        const Detection d = detector->detect(frame.cloud, frame.gravity);
        r.wall_ms = msSince(t0);
        r.cpu_ms = threadCpuMs() - c0;
        for (const auto &[key, ms] : d.timing_ms)
            if (key != "total") r.stages[key] = ms;
        out.found = d.found;
        out.reason = d.reason;
        out.normal = d.plane.normal;
        out.area = d.found ? d.rectangle.area() : 0.0;
        out.outliers = d.surface_check.outliers;
        out.check_points = d.surface_check.points;
        out.planes = static_cast<int>(d.debug.candidates.size());
        return r;
    };
    return p;
}

Pipeline stockPipeline(const Projector &projector) {
    auto stock = std::make_shared<std::unique_ptr<StockPipeline>>();
    auto cloud = std::make_shared<PclCloud::Ptr>();
    Pipeline p;
    p.name = "stock PCL";
    p.prepare = [stock, cloud, projector](const BenchFrame &frame) {
        *cloud = toPcl(frame.cloud);
        StockConfig config;
        config.gravity = frame.gravity;
        *stock = std::make_unique<StockPipeline>(projector, config);
    };
    p.run = [stock, cloud](const BenchFrame &, Outcome &out) {
        Run r;
        const double c0 = threadCpuMs();
        const auto t0 = Clock::now();
        const StockResult s = (*stock)->run(*cloud);
        r.wall_ms = msSince(t0);
        r.cpu_ms = threadCpuMs() - c0;
        for (const auto &[key, ms] : s.timing_ms)
            if (key != "total") r.stages[key] = ms;
        const double convex = r.stages.count("convex_hull") ? r.stages["convex_hull"] : 0.0;
        r.wall_ms -= convex;  // the alternative hull is not part of the pipeline
        r.cpu_ms -= convex;   // (approximately: its wall time)
        out.found = s.found;
        out.reason = s.reason;
        out.normal = s.plane.normal;
        out.area = s.found ? s.rectangle.area() : 0.0;
        out.outliers = s.outliers;
        out.check_points = s.check_points;
        out.planes = s.inliers > 0;
        return r;
    };
    return p;
}

struct Measured {
    std::vector<Run> runs;                 ///< every timed repetition of every frame
    std::vector<double> frame_median_ms;   ///< per frame
    std::vector<Outcome> outcomes;         ///< per frame (last repetition)
    std::vector<std::string> stage_order;  ///< first-seen order
};

void sortStages(std::vector<std::string> &stages);

Measured measure(Pipeline &p, const std::vector<BenchFrame> &frames, int warmup, int reps) {
    Measured m;
    for (const auto &frame : frames) {
        p.prepare(frame);
        Outcome out;
        for (int i = 0; i < warmup; ++i) p.run(frame, out);
        std::vector<double> walls;
        for (int i = 0; i < reps; ++i) {
            Run r = p.run(frame, out);
            walls.push_back(r.wall_ms);
            for (const auto &[key, ms] : r.stages)
                if (std::find(m.stage_order.begin(), m.stage_order.end(), key) == m.stage_order.end())
                    m.stage_order.push_back(key);
            m.runs.push_back(std::move(r));
        }
        m.frame_median_ms.push_back(summarize(walls).median);
        m.outcomes.push_back(out);
    }
    sortStages(m.stage_order);
    return m;
}

int moduleIndex(const std::string &key);

/// Pipeline order: by paper module, then by the known order of the stage names.
void sortStages(std::vector<std::string> &stages) {
    static const std::vector<std::string> known = {
        "sample",          "voxel_grid", "normals",      "ransac",      "planes",           "plane",
        "extract_project", "hull",       "concave_hull", "convex_hull", "workspace_raster", "framing",
        "free_space",      "rectangle",  "crop",         "outliers",    "surface_check"};
    auto rank = [&](const std::string &k) {
        const auto it = std::find(known.begin(), known.end(), k);
        return std::make_tuple(moduleIndex(k), static_cast<int>(it - known.begin()), k);
    };
    std::stable_sort(stages.begin(), stages.end(),
                     [&](const std::string &a, const std::string &b) { return rank(a) < rank(b); });
}

Stats wallStats(const Measured &m) {
    std::vector<double> v;
    for (const auto &r : m.runs) v.push_back(r.wall_ms);
    return summarize(v);
}
Stats cpuStats(const Measured &m) {
    std::vector<double> v;
    for (const auto &r : m.runs) v.push_back(r.cpu_ms);
    return summarize(v);
}
Stats stageStats(const Measured &m, const std::string &stage) {
    std::vector<double> v;
    for (const auto &r : m.runs) {
        const auto it = r.stages.find(stage);
        v.push_back(it == r.stages.end() ? 0.0 : it->second);
    }
    return summarize(v);
}

// --- paper modules, to put differently cut stages side by side ---------------------------

const std::vector<std::string> kModules = {"3.2.1 vertical plane finder", "3.2.2 corrected workspace finder",
                                           "3.2.3 surface checker", "other"};

/// The paper module a stage key belongs to (by name; keys from either pipeline).
std::string moduleOf(const std::string &key) {
    auto has = [&](const char *s) { return key.find(s) != std::string::npos; };
    if (key == "convex_hull") return "";  // the stock alternative, not in its total
    if (has("check") || has("crop") || has("outlier")) return kModules[2];
    if (has("voxel") || has("sampl") || has("ransac") || has("plane") || has("normal") || has("segment"))
        return kModules[0];
    if (has("hull") || has("fram") || has("free") || has("raster") || has("workspace") || has("rect") ||
        has("extract") || has("project") || has("grid") || has("occup"))
        return kModules[1];
    return kModules[3];
}

int moduleIndex(const std::string &key) {
    const std::string m = moduleOf(key);
    const auto it = std::find(kModules.begin(), kModules.end(), m);
    return m.empty() ? 1 : static_cast<int>(it - kModules.begin());
}

Stats moduleStats(const Measured &m, const std::string &module) {
    std::vector<double> v;
    for (const auto &r : m.runs) {
        double sum = 0.0;
        for (const auto &[key, ms] : r.stages)
            if (moduleOf(key) == module) sum += ms;
        v.push_back(sum);
    }
    return summarize(v);
}

// --- peak memory, one child process per pipeline -----------------------------------------

/// Peak RSS (MiB) of a child that runs `work` (forked after the frames are loaded, so the
/// frames are in every child's figure; compare with the baseline child).
double childPeakRssMiB(const std::function<void()> &work) {
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0) return NAN;
    if (pid == 0) {
        work();
        _exit(0);
    }
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return NAN;
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// --- the report ----------------------------------------------------------------------------

struct Options {
    std::string data;
    int reps = 30;
    int warmup = 3;
    int max_frames = 0;
    int cpu = 0;
    bool quick = false;
    bool scale = false;
    bool plan_only = false;
    bool sim = true;
    int scale_reps = 10;
};

void printHeader(const Options &o, bool pinned) {
    std::cout << "# projsurf benchmark\n\n";
    std::cout << "- CPU: " << cpuModel() << "; " << sysconf(_SC_NPROCESSORS_ONLN) << " online; "
              << (pinned ? "pinned to CPU " + std::to_string(o.cpu) : std::string("not pinned"))
              << " (allowed: " << allowedCpus() << "); OpenCV threads: " << cv::getNumThreads() << "\n";
    std::cout << "- Build: " << PROJSURF_BUILD_TYPE << "; PCL " << PCL_VERSION_PRETTY << "; OpenCV " << CV_VERSION
              << "\n";
    std::cout << "- Real frames folder: " << o.data << "\n";
    std::cout << "- Load average at start: " << loadAverage() << "; scheduling: " << schedulingPolicy() << "\n";
    if (std::string(PROJSURF_BUILD_TYPE) != "Release")
        std::cout << "- **Warning: not a Release build; the times below do not count.**\n";
    std::cout << "\n";
}

/// The stages table of one pipeline's runs `m`: each stage's median, spread and share of the
/// median total, the time outside the stages, and the total.
void printStageTable(const std::string &name, const Measured &m) {
    const Stats total = wallStats(m);
    std::cout << "### Stages: " << name << "\n\n";
    std::cout << "| stage | module | median ms | p10–p90 ms | share of median total |\n|---|---|---:|---:|---:|\n";
    for (const auto &stage : m.stage_order) {
        const Stats s = stageStats(m, stage);
        const std::string module = moduleOf(stage);
        std::cout << "| " << stage << " | " << (module.empty() ? "(alternative, not in total)" : module) << " | "
                  << fmt(s.median) << " | " << spread(s) << " | "
                  << (total.median > 0 && !module.empty() ? fmt(100.0 * s.median / total.median) + " %" : "-")
                  << " |\n";
    }
    {  // time between and around the stages (result assembly, debug output, copies)
        std::vector<double> rest;
        for (const auto &r : m.runs) {
            double sum = 0.0;
            for (const auto &[key, ms] : r.stages)
                if (!moduleOf(key).empty()) sum += ms;
            rest.push_back(r.wall_ms - sum);
        }
        const Stats s = summarize(rest);
        std::cout << "| (outside the stages) | | " << fmt(s.median) << " | " << spread(s) << " | "
                  << (total.median > 0 ? fmt(100.0 * s.median / total.median) + " %" : "-") << " |\n";
    }
    std::cout << "| **total (wall clock)** | | **" << fmt(total.median) << "** | " << spread(total) << " | |\n\n";
}

/// The per-frame table: each frame's median times and outcomes of the three pipelines (`results`
/// in the order default, paper mode, stock), and the plane angle between default and stock.
void printPerFrameTable(const std::vector<BenchFrame> &frames, const std::vector<Measured> &results) {
    std::cout << "### Per frame (median ms; outcome of the last repetition)\n\n";
    std::cout << "| frame | valid points | default ms | default planes | paper-mode ms | stock ms | stock / default "
                 "| default: area m² | paper mode: area m² | stock: area m² | plane angle default vs stock |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    auto outcome = [](const Outcome &o) {
        if (o.found) return fmt(o.area);
        return std::string("none (") + (o.reason.empty() ? "?" : o.reason) + ")";
    };
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const Outcome &a = results[0].outcomes[f], &b = results[2].outcomes[f];
        std::string angle = "-";
        if (a.normal.squaredNorm() > 0.25 && b.normal.squaredNorm() > 0.25 && a.found && b.found)
            angle = fmt(std::acos(std::min(1.0, std::fabs(a.normal.normalized().dot(b.normal.normalized())))) * 180.0 /
                        M_PI) +
                    "°";
        std::cout << "| " << frames[f].name << " | " << frames[f].finite << " | " << fmt(results[0].frame_median_ms[f])
                  << " | " << a.planes << " | " << fmt(results[1].frame_median_ms[f]) << " | "
                  << fmt(results[2].frame_median_ms[f]) << " | "
                  << ratio(results[2].frame_median_ms[f], results[0].frame_median_ms[f]) << " | " << outcome(a) << " | "
                  << outcome(results[1].outcomes[f]) << " | " << outcome(b) << " | " << angle << " |\n";
    }
    std::cout << "\n";
}

void reportFrameSet(const std::string &title, const std::vector<BenchFrame> &frames, const Options &o,
                    const Projector &projector) {
    std::vector<Pipeline> pipelines = {oursPipeline("projsurf default", projector, Method::Default),
                                       oursPipeline("projsurf paper mode", projector, Method::Paper),
                                       stockPipeline(projector)};
    std::vector<Measured> results;
    for (auto &p : pipelines) {
        std::cerr << "projsurf_bench: " << title << ": " << p.name << " ... (peak RSS so far " << fmt(peakRssMiB())
                  << " MiB)\n";
        results.push_back(measure(p, frames, o.warmup, o.reps));
    }
    const Measured &ours = results[0], &stock = results[2];

    std::size_t points = 0;
    for (const auto &f : frames) points += f.finite;
    std::cout << "## " << title << "\n\n";
    std::cout << frames.size() << " frames, " << frames.front().depth.cols << "x" << frames.front().depth.rows << ", "
              << points / frames.size() << " valid points per frame on average; " << o.reps
              << " timed repetitions per frame after " << o.warmup
              << " warm-ups; statistics over all frames x repetitions (ms).\n\n";

    std::cout << "### Total per frame (from a loaded cloud, surface check included)\n\n";
    std::cout << "| pipeline | median ms | p10–p90 ms | max ms | stock / this | CPU-time median ms |\n"
                 "|---|---:|---:|---:|---:|---:|\n";
    const Stats stock_total = wallStats(stock);
    for (std::size_t i = 0; i < pipelines.size(); ++i) {
        const Stats s = wallStats(results[i]);
        std::cout << "| " << pipelines[i].name << " | " << fmt(s.median) << " | " << spread(s) << " | " << fmt(s.max)
                  << " | " << ratio(stock_total.median, s.median) << " | " << fmt(cpuStats(results[i]).median)
                  << " |\n";
    }
    std::cout << "\nWall-clock times (steady_clock); the last column is the thread's CPU time for the same runs "
                 "(close to the wall clock when nothing else ran on the core).\n\n";

    std::cout << "### By paper module: projsurf default vs stock PCL\n\n";
    std::cout << "| module | ours median | ours p10–p90 | stock median | stock p10–p90 | stock / ours |\n"
                 "|---|---:|---:|---:|---:|---:|\n";
    for (const auto &module : kModules) {
        const Stats a = moduleStats(ours, module), b = moduleStats(stock, module);
        if (a.max == 0.0 && b.max == 0.0) continue;
        std::cout << "| " << module << " | " << fmt(a.median) << " | " << spread(a) << " | " << fmt(b.median) << " | "
                  << spread(b) << " | " << ratio(b.median, a.median) << " |\n";
    }
    std::cout << "| **total** | **" << fmt(wallStats(ours).median) << "** | " << spread(wallStats(ours)) << " | **"
              << fmt(stock_total.median) << "** | " << spread(stock_total) << " | **"
              << ratio(stock_total.median, wallStats(ours).median) << "** |\n\n";

    for (std::size_t i = 0; i < pipelines.size(); ++i) printStageTable(pipelines[i].name, results[i]);

    printPerFrameTable(frames, results);
}

void reportKeystone(const Options &o, const Projector &projector) {
    std::cout << "## Keystone warp\n\n";
    std::cout
        << "A picture of the framebuffer's size shown in a detected rectangle on a wall 2 m ahead turned 20°; "
           "per frame (the homography is computed once per detection). KeystoneWarper is the warp for a stream of "
           "frames; warpToFramebuffer is one picture per keystone (it also works out the source positions).\n\n";
    std::cout << "| warp | median ms | p10–p90 ms | max ms | target |\n|---|---:|---:|---:|---:|\n";
    for (const auto kind :
         {KeystoneWarp::Kind::Warper, KeystoneWarp::Kind::WarperSsse3, KeystoneWarp::Kind::WarperPlain,
          KeystoneWarp::Kind::Projsurf, KeystoneWarp::Kind::Bare, KeystoneWarp::Kind::Remap}) {
        KeystoneWarp warp(projector, kind);
        const int warmup = o.quick ? 0 : 10, reps = o.quick ? 1 : 300;
        for (int i = 0; i < warmup; ++i) warp.run();
        std::vector<double> v;
        for (int i = 0; i < reps; ++i) {
            const auto t0 = Clock::now();
            warp.run();
            v.push_back(msSince(t0));
        }
        const Stats s = summarize(v);
        std::cout << "| " << warp.what() << " | " << fmt(s.median) << " | " << spread(s) << " | " << fmt(s.max)
                  << " | ≤ 4 ms (60 fps) |\n";
    }
    std::cout << "\n";
}

void reportBlanking(const Options &o, const std::vector<BenchFrame> &real, const Projector &projector) {
    std::cout << "## Blanking what stands in the beam\n\n";
    std::cout << "people/beam_blanking: the framebuffer mask (1280x800) of what stands between the lens and the "
                 "detected plane, from one VGA cloud (one BeamBlanker reused, as the node does); wall-clock and "
                 "thread CPU time per cloud.\n\n";
    std::cout << "| cloud | blanked px | median ms | p10–p90 ms | max ms | CPU median ms | target |\n"
                 "|---|---:|---:|---:|---:|---:|---:|\n";
    BeamBlanker blanker(projector);
    for (const auto &c : blankingCases(real, projector)) {
        const int warmup = o.quick ? 0 : 10, reps = o.quick ? 1 : 200;
        for (int i = 0; i < warmup; ++i) blanker.compute(c.cloud, c.plane);
        std::vector<double> wall, cpu;
        for (int i = 0; i < reps; ++i) {
            const double c0 = threadCpuMs();
            const auto t0 = Clock::now();
            blanker.compute(c.cloud, c.plane);
            wall.push_back(msSince(t0));
            cpu.push_back(threadCpuMs() - c0);
        }
        const Stats s = summarize(wall);
        std::cout << "| " << c.name << " | " << blanker.blankedPixels() << " | " << fmt(s.median) << " | " << spread(s)
                  << " | " << fmt(s.max) << " | " << fmt(summarize(cpu).median) << " | ≤ 2 ms |\n";
    }
    std::cout << "\n";
}

std::string reportMemory(const std::vector<BenchFrame> &frames, const Projector &projector) {
    // Each child runs one pipeline over every frame twice (a stream) and exits.
    auto stream = [&](Pipeline p) {
        return [&frames, p]() mutable {
            Outcome out;
            for (int round = 0; round < 2; ++round)
                for (const auto &f : frames) {
                    p.prepare(f);
                    p.run(f, out);
                }
        };
    };
    const double base = childPeakRssMiB([] {});
    const std::vector<std::pair<std::string, std::function<void()>>> children = {
        {"projsurf default", stream(oursPipeline("", projector, Method::Default))},
        {"projsurf paper mode", stream(oursPipeline("", projector, Method::Paper))},
        {"stock PCL", stream(stockPipeline(projector))},
    };
    std::ostringstream out;
    out << "## Peak memory (getrusage ru_maxrss of one child process per pipeline)\n\n";
    out << "Each child is forked after the frames are loaded (before any timing) and runs one pipeline over "
           "every frame twice.\n\n";
    out << "| process | peak RSS MiB | over baseline MiB |\n|---|---:|---:|\n";
    out << "| baseline (frames loaded, no detection) | " << fmt(base) << " | 0 |\n";
    for (const auto &[name, work] : children) {
        const double peak = childPeakRssMiB(work);
        out << "| " << name << " | " << fmt(peak) << " | " << fmt(peak - base) << " |\n";
    }
    out << "\n";
    return out.str();
}

/// Least-squares line y = a + b x and its R².
struct Fit {
    double a = 0, b = 0, r2 = 0;
};
Fit fitLine(const std::vector<double> &x, const std::vector<double> &y) {
    const double n = static_cast<double>(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
        syy += y[i] * y[i];
    }
    Fit f;
    const double den = n * sxx - sx * sx;
    if (den == 0) return f;
    f.b = (n * sxy - sx * sy) / den;
    f.a = (sy - f.b * sx) / n;
    const double ss_tot = syy - sy * sy / n;
    double ss_res = 0;
    for (std::size_t i = 0; i < x.size(); ++i) ss_res += std::pow(y[i] - (f.a + f.b * x[i]), 2);
    f.r2 = ss_tot > 0 ? 1.0 - ss_res / ss_tot : 1.0;
    return f;
}

void reportScale(const std::vector<BenchFrame> &frames, const Options &o, const Projector &projector) {
    std::vector<std::pair<int, int>> sizes = {{160, 120}, {320, 240}, {640, 360}, {640, 480},
                                              {848, 480}, {960, 720}, {1280, 720}};
    if (o.quick) sizes = {{160, 120}, {320, 240}};
    const int reps = o.quick ? 1 : o.scale_reps, warmup = o.quick ? 0 : 2;
    std::cout << "## Time against the number of points\n\n";
    std::cout << "Each of the " << frames.size()
              << " frames' depth images resampled (nearest neighbour, intrinsics scaled) to the size; " << reps
              << " timed repetitions per frame after " << warmup << " warm-ups; median over frames x repetitions.\n\n";
    std::cout << "| size | pixels | valid points (mean) | default ms | default ns/pixel | stock ms | stock ns/pixel | "
                 "stock / default |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    std::vector<double> px, ours_ms, stock_ms;
    std::vector<Measured> ours_runs;
    for (const auto &[w, h] : sizes) {
        std::cerr << "projsurf_bench: scale " << w << "x" << h << " ...\n";
        std::vector<BenchFrame> resized;
        std::size_t finite = 0;
        for (const auto &f : frames) {
            resized.push_back(resizeFrame(f, w, h));
            finite += resized.back().finite;
        }
        Pipeline ours = oursPipeline("", projector, Method::Default), stock = stockPipeline(projector);
        ours_runs.push_back(measure(ours, resized, warmup, reps));
        const Stats a = wallStats(ours_runs.back());
        const Stats b = wallStats(measure(stock, resized, warmup, reps));
        const double pixels = static_cast<double>(w) * h;
        px.push_back(pixels);
        ours_ms.push_back(a.median);
        stock_ms.push_back(b.median);
        std::cout << "| " << w << "x" << h << " | " << static_cast<long>(pixels) << " | " << finite / frames.size()
                  << " | " << fmt(a.median) << " | " << fmt(1e6 * a.median / pixels) << " | " << fmt(b.median) << " | "
                  << fmt(1e6 * b.median / pixels) << " | " << ratio(b.median, a.median) << " |\n";
    }
    // Which of our stages depend on the number of points and which do not.
    std::vector<std::string> stages;
    for (const auto &m : ours_runs)
        for (const auto &k : m.stage_order)
            if (std::find(stages.begin(), stages.end(), k) == stages.end()) stages.push_back(k);
    sortStages(stages);
    std::cout << "\nprojsurf default, median ms per stage:\n\n| size |";
    for (const auto &k : stages) std::cout << " " << k << " |";
    std::cout << " total (wall) | total (CPU) |\n|---|";
    for (std::size_t i = 0; i < stages.size() + 2; ++i) std::cout << "---:|";
    std::cout << "\n";
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        std::cout << "| " << sizes[i].first << "x" << sizes[i].second << " |";
        for (const auto &k : stages) std::cout << " " << fmt(stageStats(ours_runs[i], k).median) << " |";
        std::cout << " " << fmt(wallStats(ours_runs[i]).median) << " | " << fmt(cpuStats(ours_runs[i]).median)
                  << " |\n";
    }
    const Fit fa = fitLine(px, ours_ms), fb = fitLine(px, stock_ms);
    std::cout << "\nLeast-squares line through the medians, t = a + b · pixels:\n\n";
    std::cout << "| pipeline | a (ms) | b (ns/pixel) | R² |\n|---|---:|---:|---:|\n";
    std::cout << "| projsurf default | " << fmt(fa.a) << " | " << fmt(fa.b * 1e6) << " | " << fmt(fa.r2) << " |\n";
    std::cout << "| stock PCL | " << fmt(fb.a) << " | " << fmt(fb.b * 1e6) << " | " << fmt(fb.r2) << " |\n\n";
}

/// The real frames of o.data (the first o.max_frames of them when that is set); none, with a
/// warning, when the folder is missing or unreadable and was not given with --data (which
/// throws the InputError instead).
std::vector<BenchFrame> realFramesOrNone(const Options &o, bool data_given) {
    std::vector<BenchFrame> real;
    try {
        real = loadRealFrames(o.data);
    } catch (const InputError &e) {
        if (data_given) throw;
        std::cerr << "projsurf_bench: warning: " << e.what() << "; using the simulator's scenes only\n";
    }
    if (o.max_frames > 0 && real.size() > static_cast<std::size_t>(o.max_frames)) real.resize(o.max_frames);
    return real;
}

}  // namespace

int main(int argc, char **argv) {
    Options o;
    o.data = defaultRealDir();
    CLI::App app{
        "projsurf_bench: detector stages vs a stock-PCL pipeline of the paper's steps, keystone warp, "
        "memory; Markdown on stdout"};
    auto *data_option =
        app.add_option("--data", o.data, "folder of real frames (sub-folders with depth.png + camera.yaml)");
    app.add_option("--reps", o.reps, "timed repetitions per frame")->check(CLI::Range(1, 100000));
    app.add_option("--warmup", o.warmup, "untimed repetitions per frame first")->check(CLI::Range(0, 100000));
    app.add_option("--frames", o.max_frames, "use only the first N frames (0 = all)")->check(CLI::Range(0, 100000));
    app.add_option("--cpu", o.cpu, "pin to this CPU (-1 = do not pin; then use taskset -c 0)")
        ->check(CLI::Range(-1, 1023));
    app.add_flag("--quick", o.quick, "smoke run: 1 frame, 1 repetition, no warm-up");
    app.add_flag("!--no-sim", o.sim, "skip the simulator's paper scenes");
    app.add_flag("--scale", o.scale, "time against the number of points, 160x120 ... 1280x720");
    app.add_flag("--plan-only", o.plan_only, "only the plan table (planStand per frame, 3 runs each)");
    app.add_option("--scale-reps", o.scale_reps, "repetitions per frame in --scale")->check(CLI::Range(1, 100000));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "projsurf_bench: " << e.what() << " (see --help)\n";
        return 2;
    }
    const bool data_given = data_option->count() > 0;
    if (o.quick) {
        o.reps = 1;
        o.warmup = 0;
        o.max_frames = 1;
    }
    cv::setNumThreads(1);  // one core: no OpenCV worker threads
    const bool pinned = o.cpu >= 0 && pinToCpu(o.cpu);
    if (o.cpu >= 0 && !pinned) std::cerr << "projsurf_bench: warning: could not pin to CPU " << o.cpu << "\n";
    try {
        // The real frames; without --data a missing default folder falls back to the simulator.
        const std::vector<BenchFrame> real = realFramesOrNone(o, data_given);
        std::vector<BenchFrame> simulated;
        if (o.sim || real.empty()) {
            std::cerr << "projsurf_bench: rendering the simulator's paper scenes ...\n";
            simulated = simulatorFrames(o.max_frames);
        }
        std::cerr << "projsurf_bench: " << real.size() << " real and " << simulated.size()
                  << " simulated frames (peak RSS so far " << fmt(peakRssMiB()) << " MiB)\n";
        const std::vector<BenchFrame> &any = real.empty() ? simulated : real;
        const Projector projector = sim::exampleProjector();  // the contract's example calibration
        printHeader(o, pinned);
        if (o.scale) {
            reportScale(any, o, projector);
        } else if (o.plan_only) {
            std::vector<BenchFrame> frames = real;
            frames.insert(frames.end(), simulated.begin(), simulated.end());
            reportPlan(frames, projector, o.quick ? 0 : 1, o.quick ? 1 : 3);
        } else {
            const std::string memory = reportMemory(any, projector);  // first: a clean parent to fork
            if (!real.empty()) reportFrameSet("Real frames (" + o.data + ")", real, o, projector);
            if (!simulated.empty())
                reportFrameSet("Simulator: the paper's scenes (Kinect v1 model)", simulated, o, projector);
            reportKeystone(o, projector);
            reportBlanking(o, real, projector);
            reportPlan(any, projector, o.quick ? 0 : 1, o.quick ? 1 : 3);
            std::cout << memory;
            std::cout << "Peak RSS of this benchmark process (libraries, every frame as loaded, all three pipelines): "
                      << fmt(peakRssMiB()) << " MiB.\n";
            std::cout << "Load average at the end: " << loadAverage() << ".\n";
        }
    } catch (const InputError &e) {
        std::cerr << "projsurf_bench: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "projsurf_bench: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
