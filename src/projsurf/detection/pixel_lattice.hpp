#pragma once
// The pixel columns (or rows) a cloud's normalised image coordinates lie on when it was made
// from a pinhole depth image: x/z = (column - cx) / fx takes one value per column, so the values
// fall on a lattice of step 1 / fx. Filtering, cropping or shuffling keeps the lattice; a cloud
// from another viewpoint, a voxel grid or a merged scan does not have one.
#include <optional>
#include <vector>

namespace projsurf {

struct PixelLattice {
    double origin = 0.0;  ///< the value of the first column (row) holding a point
    double step = 0.0;    ///< 1 / focal length, in units of the values
    int count = 0;        ///< columns (rows) from the first to the last holding a point

    /// The column of a value (may lie outside [0, count) for a value not in the lattice's sample).
    double index(double value) const { return (value - origin) / step; }
};

struct PixelLatticeOptions {
    double tolerance =
        5e-5;  ///< [0, 0.01] x/z, a gap this small within a column's values (float rounding, a PCD's printed decimals)
    double max_residual = 0.15;  ///< [0, 0.5] of a step: a value further off the lattice is not on it
    double max_off = 0.01;       ///< [0, 1] share of the values that may lie off it (stray points)
    int min_columns = 16;        ///< [2, 8192] fewer distinct columns: too few to tell a lattice
    int max_columns = 8192;      ///< [16, 65536] more: no depth image this wide
    int max_samples = 1 << 16;   ///< [1, 2^24] values looked at (evenly strided)
};

/// The lattice the values lie on (all but max_off of them), from the first to the last column
/// holding a value on it; nullopt when they lie on none.
std::optional<PixelLattice> pixelLattice(const std::vector<float> &values, const PixelLatticeOptions &options = {});

}  // namespace projsurf
