#pragma once
// The pixel columns (or rows) a cloud's normalised image coordinates lie on when it was made
// from a pinhole depth image: x/z = (column - cx) / fx takes one value per column, so the values
// fall on a lattice of step 1 / fx. Filtering, cropping or shuffling keeps the lattice; a cloud
// from another viewpoint, a voxel grid or a merged scan does not have one.
#include <optional>
#include <vector>

#include "projsurf/detection/detector_config.hpp"

namespace projsurf {

struct PixelLattice {
    double origin = 0.0;  ///< the value of the first column (row) holding a point
    double step = 0.0;    ///< 1 / focal length, in units of the values
    int count = 0;        ///< columns (rows) from the first to the last holding a point

    /// The column of a value (may lie outside [0, count) for a value not in the lattice's sample).
    double index(double value) const { return (value - origin) / step; }
};

/// The lattice the values lie on (all but max_off of them), from the first to the last column
/// holding a value on it; nullopt when they lie on none.
std::optional<PixelLattice> pixelLattice(const std::vector<float> &values, const PixelLatticeOptions &options = {});

}  // namespace projsurf
