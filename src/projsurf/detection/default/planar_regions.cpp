#include "projsurf/detection/default/planar_regions.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <deque>

namespace projsurf {
namespace {

/// Zeroth, first and second moments of a set of points (double: sums of squares at metre
/// scale lose nothing that matters).
struct Moments {
    double n = 0;
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();

    Moments &operator+=(const Moments &o) {
        n += o.n;
        s += o.s;
        ss += o.ss;
        return *this;
    }
    Eigen::Vector3d mean() const { return s / n; }
    /// RMS distance of the points to a plane.
    double rmsTo(const Plane &p) const {
        const double e = (p.normal.dot(ss * p.normal) + 2.0 * p.d * p.normal.dot(s)) / n + p.d * p.d;
        return std::sqrt(std::max(0.0, e));
    }
};

struct Fit {
    Plane plane;
    Eigen::Vector3d mean;
    double thickness = 0;  ///< m, RMS distance to the plane
    bool ok = false;
};

Fit fit(const Moments &m) {
    Fit f;
    if (m.n < 3) return f;
    f.mean = m.mean();
    const Eigen::Matrix3d cov = m.ss / m.n - f.mean * f.mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(cov);  // closed form: a thousand cells a frame
    const Eigen::Vector3d ev = solver.eigenvalues();
    if (!(ev(1) > 1e-9)) return f;  // a line or a point, not a patch
    f.plane = makePlane(solver.eigenvectors().col(0), -solver.eigenvectors().col(0).dot(f.mean));
    f.thickness = std::sqrt(std::max(0.0, ev(0)));
    f.ok = true;
    return f;
}

double tilt(const Plane &p, const Eigen::Vector3d &down) {
    return std::asin(std::min(1.0, std::abs(p.normal.dot(down))));
}

/// A region as it grows or merges: its points' moments and its cell count.
struct Grown {
    Moments m;
    int cells = 0;
};

/// One frame cut into cells of cs x cs grid elements, the settings the stages read, and what
/// the first two stages find per cell.
struct CellGrid {
    const PointGrid &grid;
    Eigen::Vector3d down;
    const DepthTolerance &tolerance;
    const PlanarRegionOptions &options;
    int cs, cols, rows;
    std::vector<Moments> cell;
    std::vector<Fit> cell_fit;
    std::vector<char> usable;    ///< flat and vertical enough to grow a region
    std::vector<int> region_of;  ///< grown region of each cell, -1 for none

    CellGrid(const PointGrid &grid, const Eigen::Vector3d &down, const DepthTolerance &tolerance,
             const PlanarRegionOptions &options)
        : grid(grid),
          down(down),
          tolerance(tolerance),
          options(options),
          cs(std::max(2, options.cell)),
          cols(grid.cols / cs),
          rows(grid.rows / cs) {}
    bool empty() const { return !grid.organized || cols < 1 || rows < 1; }
};

/// Moments of the finite points of cell (r, c), into `m`. Sums in double over float points (a
/// cell is small: no loss), NaN points skipped.
void cellMoments(const PointGrid &grid, int cs, int r, int c, Moments &m) {
    double n = 0, sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
    for (int gr = r * cs; gr < (r + 1) * cs; ++gr) {
        const std::size_t row = static_cast<std::size_t>(gr) * grid.cols + c * cs;
        const float *X = grid.x.data() + row, *Y = grid.y.data() + row, *Z = grid.z.data() + row;
        for (int k = 0; k < cs; ++k) {
            if (!(Z[k] == Z[k])) continue;
            const double x = X[k], y = Y[k], z = Z[k];
            n += 1;
            sx += x, sy += y, sz += z;
            sxx += x * x, sxy += x * y, sxz += x * z, syy += y * y, syz += y * z, szz += z * z;
        }
    }
    m.n = n;
    m.s = {sx, sy, sz};
    m.ss << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
}

/// A plane per cell; the flat, vertical ones are usable.
void fitCells(CellGrid &g) {
    const PlanarRegionOptions &o = g.options;
    const int cs = g.cs, cols = g.cols, rows = g.rows;
    const std::size_t cells = static_cast<std::size_t>(cols) * rows;
    g.cell = std::vector<Moments>(cells);
    g.cell_fit = std::vector<Fit>(cells);
    g.usable.assign(cells, 0);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const int i = r * cols + c;
            Moments &m = g.cell[i];
            cellMoments(g.grid, cs, r, c, m);
            if (m.n < o.min_fill * cs * cs) continue;
            const Fit f = fit(m);
            if (!f.ok) continue;
            const float band = g.tolerance.band(static_cast<float>(f.mean.z()));
            if (f.thickness <= o.thickness_bands * band && tilt(f.plane, g.down) <= o.seed_tilt) {
                g.cell_fit[i] = f;
                g.usable[i] = 1;
            }
        }
}

/// Grows region `id` breadth-first from cell `seed`: a neighbour joins when its points lie on
/// the region's plane, refitted as the region grows.
Grown growRegion(CellGrid &g, int seed, int id) {
    const int cols = g.cols, rows = g.rows;
    const std::vector<Moments> &cell = g.cell;
    const std::vector<Fit> &cell_fit = g.cell_fit;
    const std::vector<char> &usable = g.usable;
    std::vector<int> &region_of = g.region_of;
    Grown grown;
    grown.m = cell[seed];
    grown.cells = 1;
    region_of[seed] = id;
    Fit plane = cell_fit[seed];
    std::deque<int> queue{seed};
    while (!queue.empty()) {
        const int k = queue.front();
        queue.pop_front();
        const int r = k / cols, c = k % cols;
        const int next[4][2] = {{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}};
        for (const auto &rc : next) {
            if (rc[0] < 0 || rc[0] >= rows || rc[1] < 0 || rc[1] >= cols) continue;
            const int j = rc[0] * cols + rc[1];
            if (!usable[j] || region_of[j] >= 0) continue;
            // On the region's plane: the cell's points are as close to it as noise allows (a
            // cell's own normal is too noisy far away to compare).
            const float band = g.tolerance.band(static_cast<float>(cell_fit[j].mean.z()));
            if (cell[j].rmsTo(plane.plane) > g.options.join_bands * band) continue;
            region_of[j] = id;
            grown.m += cell[j];
            ++grown.cells;
            queue.push_back(j);
            // Refit as the region grows (closed-form 3x3: cheap at a thousand cells a frame).
            const Fit refit = fit(grown.m);
            if (refit.ok) plane = refit;
        }
    }
    return grown;
}

/// Regions grown from the flattest usable cells first.
std::vector<Grown> growRegions(CellGrid &g) {
    std::vector<int> order;
    for (int i = 0; i < static_cast<int>(g.cell.size()); ++i)
        if (g.usable[i]) order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return g.cell_fit[a].thickness < g.cell_fit[b].thickness; });
    g.region_of.assign(g.cell.size(), -1);
    std::vector<Grown> regions;
    for (int seed : order)
        if (g.region_of[seed] < 0) regions.push_back(growRegion(g, seed, static_cast<int>(regions.size())));
    return regions;
}

/// The regions of at least min_cells cells, those on one plane merged (biggest first);
/// `merged_of` gets each region's merged region, -1 for none.
std::vector<Grown> mergeRegions(const CellGrid &g, const std::vector<Grown> &regions, std::vector<int> &merged_of) {
    std::vector<int> big;
    for (int i = 0; i < static_cast<int>(regions.size()); ++i)
        if (regions[i].cells >= g.options.min_cells) big.push_back(i);
    std::stable_sort(big.begin(), big.end(), [&](int a, int b) { return regions[a].m.n > regions[b].m.n; });
    std::vector<Grown> merged;
    merged_of.assign(regions.size(), -1);
    for (int i : big) {
        const Fit fi = fit(regions[i].m);
        if (!fi.ok) continue;
        bool joined = false;
        for (Grown &m : merged) {
            const int gi = static_cast<int>(&m - merged.data());
            const Fit fg = fit(m.m);
            const float z = static_cast<float>(fi.mean.z());
            if (std::abs(fg.plane.normal.dot(fi.plane.normal)) > std::cos(g.options.merge_angle) &&
                regions[i].m.rmsTo(fg.plane) < g.tolerance.margin(z)) {
                m.m += regions[i].m;
                m.cells += regions[i].cells;
                merged_of[i] = gi;
                joined = true;
                break;
            }
        }
        if (!joined) {
            merged_of[i] = static_cast<int>(merged.size());
            merged.push_back(regions[i]);
        }
    }
    return merged;
}

/// The merged regions vertical enough, in merge order; `order_of` gets each merged
/// region's index in the result, -1 for none.
std::vector<PlanarRegion> verticalRegions(const CellGrid &g, const std::vector<Grown> &merged,
                                          std::vector<int> &order_of) {
    std::vector<PlanarRegion> out;
    order_of.assign(merged.size(), -1);
    for (std::size_t k = 0; k < merged.size(); ++k) {
        const Fit f = fit(merged[k].m);
        if (!f.ok || tilt(f.plane, g.down) > g.options.max_tilt) continue;
        order_of[k] = static_cast<int>(out.size());
        out.push_back({f.plane, static_cast<int>(merged[k].m.n), merged[k].cells});
    }
    return out;
}

/// The regions, most points first (ties in order); `position` gets each one's new index.
std::vector<PlanarRegion> biggestFirst(const std::vector<PlanarRegion> &out, std::vector<int> &position) {
    std::vector<int> rank(out.size());
    for (std::size_t k = 0; k < out.size(); ++k) rank[k] = static_cast<int>(k);
    std::stable_sort(rank.begin(), rank.end(), [&](int a, int b) { return out[a].points > out[b].points; });
    std::vector<PlanarRegion> sorted;
    position.assign(out.size(), 0);
    for (std::size_t k = 0; k < rank.size(); ++k) {
        position[rank[k]] = static_cast<int>(k);
        sorted.push_back(out[rank[k]]);
    }
    return sorted;
}

/// Each grid element's final region index (through grown, merged, kept and sorted), -1 for none.
void labelCells(const CellGrid &g, const std::vector<int> &merged_of, const std::vector<int> &order_of,
                const std::vector<int> &position, std::vector<std::int16_t> &labels) {
    const int cs = g.cs;
    for (int k = 0; k < static_cast<int>(g.cell.size()); ++k) {
        const int r = g.region_of[k];
        const int m = r >= 0 ? merged_of[r] : -1;
        const int o = m >= 0 ? order_of[m] : -1;
        if (o < 0) continue;
        const std::int16_t id = static_cast<std::int16_t>(std::min(position[o], 32767));
        const int cr = k / g.cols, cc = k % g.cols;
        for (int gr = cr * cs; gr < (cr + 1) * cs; ++gr)
            std::fill_n(labels.data() + static_cast<std::size_t>(gr) * g.grid.cols + cc * cs, cs, id);
    }
}

}  // namespace

std::vector<PlanarRegion> findVerticalRegions(const PointGrid &grid, const Eigen::Vector3d &gravity,
                                              const DepthTolerance &tolerance, const PlanarRegionOptions &options,
                                              std::vector<std::int16_t> *labels) {
    if (labels) labels->assign(static_cast<std::size_t>(grid.cols) * grid.rows, -1);
    CellGrid g(grid, gravity.normalized(), tolerance, options);
    if (g.empty()) return {};
    // 1. A plane per cell; keep the flat, vertical ones.
    fitCells(g);
    // 2. Regions grown from the flattest cells, a neighbour joining when it lies on the
    // region's plane (refitted as it grows).
    const std::vector<Grown> regions = growRegions(g);
    // 3. Regions big enough and vertical enough; those on one plane merge (biggest first).
    std::vector<int> merged_of, order_of, position;
    const std::vector<Grown> merged = mergeRegions(g, regions, merged_of);
    const std::vector<PlanarRegion> sorted = biggestFirst(verticalRegions(g, merged, order_of), position);
    if (labels) labelCells(g, merged_of, order_of, position, *labels);
    return sorted;
}

void nearerOtherMask(const PointGrid &grid, const cv::Rect &box, const std::vector<std::int16_t> &labels,
                     const std::vector<PlanarRegion> &regions, const std::vector<char> &other, const Plane &plane,
                     const DepthTolerance &tolerance, std::vector<std::uint8_t> &mask) {
    mask.assign(labels.size(), 0);
    const cv::Rect area = box & cv::Rect(0, 0, grid.cols, grid.rows);
    const int n = static_cast<int>(std::min(other.size(), regions.size()));
    for (int gr = area.y; gr < area.y + area.height; ++gr)
        for (int gc = area.x; gc < area.x + area.width; ++gc) {
            const std::size_t i = static_cast<std::size_t>(gr) * grid.cols + gc;
            const int j = labels[i];
            if (j < 0 || j >= n || !other[j]) continue;
            const Eigen::Vector3d p(grid.x[i], grid.y[i], grid.z[i]);
            mask[i] = std::abs(regions[j].plane.signedDistance(p)) + 0.25 * tolerance.band(grid.z[i]) <
                      std::abs(plane.signedDistance(p));
        }
}

}  // namespace projsurf
