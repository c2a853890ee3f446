#pragma once
// The blanking workload (people/beam_blanking): VGA clouds with the plane the picture was placed
// on. Simulated: an empty wall through a Kinect v1 unit, and a person (arm out) walking into
// the beam; real: the real frames with the plane the detector finds on each.
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "projsurf/people/beam_blanking.hpp"

namespace projsurf::bench {

struct BlankingCase {
    std::string name;
    Cloud cloud;
    Plane plane;
};

/// The simulated cases (rendered once, fixed seeds) plus one per real frame on which a plane is found.
std::vector<BlankingCase> blankingCases(const std::vector<BenchFrame> &real, const Projector &projector);

}  // namespace projsurf::bench
