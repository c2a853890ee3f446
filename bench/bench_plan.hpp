#pragma once
// The plan workload (planning/stand_planner): planStand on each frame, today's detection
// included, with the default options; wall-clock and thread CPU time per frame.
#include <vector>

#include "bench_common.hpp"

namespace projsurf::bench {

/// Prints the "Where to stand" table: per frame the median and the max over `reps` runs
/// (after `warmup` untimed ones), and the plan found.
void reportPlan(const std::vector<BenchFrame> &frames, const Projector &projector, int warmup, int reps);

}  // namespace projsurf::bench
