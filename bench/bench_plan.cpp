#include "bench_plan.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

#include "projsurf/planning/stand_planner.hpp"

namespace projsurf::bench {

void reportPlan(const std::vector<BenchFrame> &frames, const Projector &projector, int warmup, int reps) {
    std::cout << "## Where to stand\n\n";
    std::cout << "planning/stand_planner: planStand on one VGA cloud (today's detection, every surface seen, the "
                 "stance search), default options (--max-move 2); wall-clock and thread CPU time per frame.\n\n";
    std::cout << "| frame | surfaces | pictures | median ms | max ms | CPU median ms | plan | target |\n"
                 "|---|---:|---:|---:|---:|---:|---|---:|\n";
    std::vector<double> all_cpu;
    for (const BenchFrame &f : frames) {
        PlanResult r;
        for (int i = 0; i < warmup; ++i) r = planStand(f.cloud, projector, DetectorConfig{}, f.gravity);
        std::vector<double> wall, cpu;
        for (int i = 0; i < reps; ++i) {
            const double c0 = threadCpuMs();
            const auto t0 = std::chrono::steady_clock::now();
            r = planStand(f.cloud, projector, DetectorConfig{}, f.gravity);
            wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            cpu.push_back(threadCpuMs() - c0);
        }
        const Stats w = summarize(wall), c = summarize(cpu);
        all_cpu.push_back(c.median);
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %d | %d | %.1f | %.1f | %.1f | %s | <= 100 ms |\n", f.name.c_str(),
                      r.surfaces, r.pictures_evaluated, w.median, w.max, c.median,
                      r.found ? (moveInWords(r.move) + ", " + std::to_string(r.predicted.area()).substr(0, 5) + " m^2")
                                    .c_str()
                              : ("not found: " + r.reason).c_str());
        std::cout << line;
    }
    const Stats s = summarize(all_cpu);
    std::printf("\nCPU median per frame over %zu frames: median %.1f ms, max %.1f ms.\n\n", all_cpu.size(), s.median,
                s.max);
}

}  // namespace projsurf::bench
