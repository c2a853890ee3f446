#pragma once
// How noisy a depth frame is at each depth, as one number a sensor model and a real frame can
// share: the RMS distance of each window's points to the plane fitted to them (least squares),
// median over the windows whose median depth falls in a band. A small window sees a flat patch
// of almost anything (a wall, a door, a table's side), so the median is the sensor's noise plus
// the little curvature the window holds, whatever the scene; windows across a depth step are
// the minority the median ignores.
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf::sim {

struct WindowNoiseOptions {
    int window = 24;         ///< px, window side (24 px = 11 cm at 2.5 m on a VGA Kinect)
    double min_fill = 0.8;   ///< share of a window's pixels that must be readings
    double max_rms = 0.05;   ///< m, a window farther from flat is not one surface (an edge, clutter)
};

/// Windows of one depth band.
struct DepthBandNoise {
    double z_lo = 0.0, z_hi = 0.0;  ///< m, median depth of the windows in [z_lo, z_hi)
    std::vector<double> rms;        ///< m, each window's plane RMS
    double median() const;          ///< m, 0 when there are no windows
};

/// Adds the windows of an organized cloud (non-overlapping, a window apart) to the bands whose
/// edges `bands` already holds; clouds that are not organized add nothing.
void addWindowNoise(const Cloud &cloud, std::vector<DepthBandNoise> &bands, const WindowNoiseOptions &options = {});

/// Bands [edges[i], edges[i+1]) with no windows yet.
std::vector<DepthBandNoise> depthBands(const std::vector<double> &edges);

}  // namespace projsurf::sim
