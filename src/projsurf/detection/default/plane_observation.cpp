#include "projsurf/detection/default/plane_observation.hpp"
#include "projsurf/detection/raster_shape.hpp"
#include "projsurf/types/clamp_to_int.hpp"
#include "projsurf/types/target_clones.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace projsurf {
namespace {

/// What the per-point pass reads besides the points, in float and as plain scalars so that its
/// loop vectorises. Raster column of a point q of the plane: q . R + col0; row: q . U + row0.
struct RowConstants {
    float nx, ny, nz, d;           ///< the plane
    float rx, ry, rz, ux, uy, uz;  ///< R and U
    float col0, row0;
    float proj_h, o_col, o_row;  ///< the projector lens: its height above the plane, its raster position (unclipped)
    float band_k, band_min, band_max, obstacle_bands, obstacle_min;  ///< the tolerance
    float cols, rows;
    std::int32_t ncols, cells;
};

// Cloned as observeRows is, so that both compute with the same instructions (FMA or not).
PROJSURF_CLONES
RowConstants rowConstants(const Plane &plane, const PlaneFrame &frame, const RasterFrame &raster,
                          const Eigen::Vector3d &projector_origin, const DepthTolerance &tolerance) {
    const Eigen::Vector3d R = frame.right / raster.cell, U = -frame.up / raster.cell;
    const double cr = -frame.origin.dot(R) - raster.top_left.x() / raster.cell;
    const double cu = -frame.origin.dot(U) + raster.top_left.y() / raster.cell;
    RowConstants k;
    k.nx = static_cast<float>(plane.normal.x()), k.ny = static_cast<float>(plane.normal.y());
    k.nz = static_cast<float>(plane.normal.z()), k.d = static_cast<float>(plane.d);
    k.rx = static_cast<float>(R.x()), k.ry = static_cast<float>(R.y()), k.rz = static_cast<float>(R.z());
    k.ux = static_cast<float>(U.x()), k.uy = static_cast<float>(U.y()), k.uz = static_cast<float>(U.z());
    k.col0 = static_cast<float>(cr), k.row0 = static_cast<float>(cu);
    k.proj_h = static_cast<float>(plane.signedDistance(projector_origin));
    k.o_col = static_cast<float>(projector_origin.dot(R)), k.o_row = static_cast<float>(projector_origin.dot(U));
    k.band_k = static_cast<float>(tolerance.sigmas * tolerance.noise_k);
    k.band_min = static_cast<float>(tolerance.min_band), k.band_max = static_cast<float>(tolerance.max_band);
    k.obstacle_bands = static_cast<float>(tolerance.obstacle_bands);
    k.obstacle_min = static_cast<float>(tolerance.min_obstacle);
    k.cols = static_cast<float>(raster.cols), k.rows = static_cast<float>(raster.rows);
    k.ncols = raster.cols, k.cells = raster.cols * raster.rows;
    return k;
}

PROJSURF_CLONES
void observeRows(const PointGrid &grid, const cv::Rect &area, const RowConstants k, const RasterShape &shape,
                 const std::uint8_t *exclude, std::int32_t *bins, std::int32_t *seen, std::int32_t *off_counts,
                 std::int32_t *near_counts, float *offsets, int &support_points) {
    const float nx = k.nx, ny = k.ny, nz = k.nz, d = k.d, rx = k.rx, ry = k.ry, rz = k.rz, ux = k.ux, uy = k.uy,
                uz = k.uz, col0 = k.col0, row0 = k.row0, proj_h = k.proj_h, o_col = k.o_col, o_row = k.o_row,
                band_k = k.band_k, band_min = k.band_min, band_max = k.band_max, obstacle_bands = k.obstacle_bands,
                obstacle_min = k.obstacle_min, cols = k.cols, rows = k.rows;
    const std::int32_t ncols = k.ncols, cells = k.cells;
    std::vector<std::int32_t> bin(area.width), ray(area.width), off(area.width), foot(area.width);
    std::vector<float> offset(area.width);
    std::int32_t on_plane = 0;
    for (int gr = area.y; gr < area.y + area.height; ++gr) {
        const std::size_t first = static_cast<std::size_t>(gr) * grid.cols + area.x;
        const float *X = grid.x.data() + first, *Y = grid.y.data() + first, *Z = grid.z.data() + first;
        const std::uint8_t *E = exclude + first;
        // Classify and place every point of the row. Integer flags combined with &, and
        // selects between values computed beforehand: the loop stays straight-line and
        // vectorises (see CMakeLists.txt on trapping math). NaN points fail every test.
        for (int i = 0; i < area.width; ++i) {
            const float px = X[i], py = Y[i], pz = Z[i];
            const float np = nx * px + ny * py + nz * pz;
            const float h = np + d;
            const float band = std::min(std::max(band_k * pz * pz, band_min), band_max);
            const float margin = std::max(obstacle_bands * band, obstacle_min);
            const float pc = rx * px + ry * py + rz * pz, pw = ux * px + uy * py + uz * pz;
            // Camera ray: t * p lies on the plane.
            const float t = -d / np;
            const float tc = t * pc + col0, tw = t * pw + row0;
            const std::int32_t ray_in =
                (std::abs(np) >= 1e-6f) & (t > 0.0f) & (tc >= 0.0f) & (tc < cols) & (tw >= 0.0f) & (tw < rows);
            // Projector ray through p: o + s * (p - o) lies on the plane.
            const float s = proj_h / (proj_h - h);
            const float sc = o_col + s * (pc - o_col) + col0, sw = o_row + s * (pw - o_row) + row0;
            const float ac = pc + col0, aw = pw + row0;  // on the plane: its foot
            const float r = h - shape.at(ac, aw);        // off the wall's shape
            const std::int32_t on = (std::abs(r) <= band) & (E[i] == 0), beyond = r < -margin,
                               between = (r > margin) & (h < proj_h);
            const float fc = beyond ? tc : sc, fw = beyond ? tw : sw;  // off it: camera or projector ray
            const float bc = on ? ac : fc, bw = on ? aw : fw;
            const std::int32_t bin_in =
                (on | beyond | between) & (bc >= 0.0f) & (bc < cols) & (bw >= 0.0f) & (bw < rows);
            // Truncation is floor here: both coordinates are known to be >= 0 when used. They
            // are clamped into the raster first (NaN -> 0), so that the conversion is defined
            // for the points the selects below discard too (far, NaN); kept values are unchanged.
            const float kbc = std::min(cols, std::max(0.0f, bc)), kbw = std::min(rows, std::max(0.0f, bw));
            const float ktc = std::min(cols, std::max(0.0f, tc)), ktw = std::min(rows, std::max(0.0f, tw));
            const std::int32_t bin_cell = static_cast<std::int32_t>(kbw) * ncols + static_cast<std::int32_t>(kbc) +
                                          (beyond ? cells : 0) + (between ? 2 * cells : 0);
            const std::int32_t ray_cell = static_cast<std::int32_t>(ktw) * ncols + static_cast<std::int32_t>(ktc);
            // Within the margin (on the wall or just proud of it): its offset, at its foot.
            const float kac = std::min(cols, std::max(0.0f, ac)), kaw = std::min(rows, std::max(0.0f, aw));
            const std::int32_t near_in =
                (std::abs(r) <= margin) & (E[i] == 0) & (ac >= 0.0f) & (ac < cols) & (aw >= 0.0f) & (aw < rows);
            const std::int32_t foot_cell = static_cast<std::int32_t>(kaw) * ncols + static_cast<std::int32_t>(kac);
            foot[i] = near_in ? foot_cell : cells;
            offset[i] = near_in ? r : 0.0f;
            bin[i] = bin_in ? bin_cell : 3 * cells;
            ray[i] = ray_in ? ray_cell : cells;
            off[i] = (std::abs(r) > margin) & ray_in;
            on_plane += on & bin_in;
        }
        // Count them (a scatter: scalar, but without branches).
        for (int i = 0; i < area.width; ++i) {
            ++bins[bin[i]];
            ++seen[ray[i]];
            off_counts[ray[i]] += off[i];
            ++near_counts[foot[i]];
            offsets[foot[i]] += offset[i];
        }
    }
    support_points = on_plane;
}

}  // namespace

void observePlane(const PointGrid &grid, const cv::Rect &box, const Plane &plane, const PlaneFrame &frame,
                  const RasterFrame &raster, const Eigen::Vector3d &projector_origin, const DepthTolerance &tolerance,
                  PlaneObservation &out, const WallShape &shape, const std::vector<std::uint8_t> *exclude) {
    const int rows = raster.rows, cols = raster.cols;
    const std::size_t row_cells = static_cast<std::size_t>(cols),
                      total = (3 * rows + 1 + 2 * rows + 2 + rows + 1) * row_cells, sums = (rows + 1) * row_cells;
    if (out.counts.size() < total) out.counts.resize(total);
    if (out.offsets.size() < sums) out.offsets.resize(sums);
    std::fill_n(out.counts.data(), total, 0);
    std::fill_n(out.offsets.data(), sums, 0.0f);
    std::int32_t *bins = out.counts.data(), *rays = bins + (3 * rows + 1) * row_cells;
    auto view = [&](std::int32_t *first) { return cv::Mat(rows, cols, CV_32SC1, first); };
    out.support = view(bins);
    out.behind = view(bins + rows * row_cells);
    out.shadow = view(bins + 2 * rows * row_cells);
    out.seen = view(rays);
    out.off = view(rays + (rows + 1) * row_cells);
    std::int32_t *near = rays + 2 * (rows + 1) * row_cells;
    out.near = view(near);
    out.offset = cv::Mat(rows, cols, CV_32FC1, out.offsets.data());
    const cv::Rect area = box & cv::Rect(0, 0, grid.cols, grid.rows);
    const bool use = exclude && exclude->size() == grid.x.size();
    thread_local std::vector<std::uint8_t> zeros;
    if (!use && zeros.size() < grid.x.size()) zeros.assign(grid.x.size(), 0);
    observeRows(grid, area, rowConstants(plane, frame, raster, projector_origin, tolerance), RasterShape(shape, raster),
                use ? exclude->data() : zeros.data(), bins, rays, rays + (rows + 1) * row_cells, near,
                out.offsets.data(), out.support_points);
}

namespace {

/// Cells [c0, c1] x [r0, r1] whose centre (top_left + (col + 0.5, -(row + 0.5)) * cell) is
/// inside [lo, hi]; empty when c0 > c1 or r0 > r1.
struct CellRange {
    int c0, c1, r0, r1;
    bool empty() const { return c0 > c1 || r0 > r1; }
    bool contains(int row, int col) const { return row >= r0 && row <= r1 && col >= c0 && col <= c1; }
};

CellRange cellsInside(const RasterFrame &raster, const Eigen::Vector2d &lo, const Eigen::Vector2d &hi) {
    const double cell = raster.cell;
    return {clampToInt(std::ceil((lo.x() - raster.top_left.x()) / cell - 0.5), 0, raster.cols),
            clampToInt(std::floor((hi.x() - raster.top_left.x()) / cell - 0.5), -1, raster.cols - 1),
            clampToInt(std::ceil((raster.top_left.y() - hi.y()) / cell - 0.5), 0, raster.rows),
            clampToInt(std::floor((raster.top_left.y() - lo.y()) / cell - 0.5), -1, raster.rows - 1)};
}

}  // namespace

SurfaceCheckResult checkObservedSurface(const PlaneObservation &observation, const RasterFrame &raster,
                                        const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double max_fraction) {
    const CellRange cells = cellsInside(raster, lo, hi);
    SurfaceCheckResult r;
    if (cells.empty() || observation.seen.empty()) return r;
    for (int row = cells.r0; row <= cells.r1; ++row) {
        const auto *seen = observation.seen.ptr<std::int32_t>(row), *off = observation.off.ptr<std::int32_t>(row);
        for (int col = cells.c0; col <= cells.c1; ++col) {
            r.points += seen[col];
            r.outliers += off[col];
        }
    }
    r.accepted = r.points > 0 && r.outliers <= max_fraction * r.points;
    return r;
}

std::vector<int> offPlanePoints(const PointGrid &grid, const cv::Rect &box, const Plane &plane, const PlaneFrame &frame,
                                const RasterFrame &raster, const DepthTolerance &tolerance, const Eigen::Vector2d &lo,
                                const Eigen::Vector2d &hi, const WallShape &wall_shape) {
    // The same float arithmetic as observeRows, one point at a time.
    const CellRange cells = cellsInside(raster, lo, hi);
    std::vector<int> out;
    if (cells.empty()) return out;
    const Eigen::Vector3d R = frame.right / raster.cell, U = -frame.up / raster.cell;
    const float col0 = static_cast<float>(-frame.origin.dot(R) - raster.top_left.x() / raster.cell);
    const float row0 = static_cast<float>(-frame.origin.dot(U) + raster.top_left.y() / raster.cell);
    const Eigen::Vector3f n = plane.normal.cast<float>(), r = R.cast<float>(), u = U.cast<float>();
    const float d = static_cast<float>(plane.d);
    const RasterShape shape(wall_shape, raster);
    const cv::Rect area = box & cv::Rect(0, 0, grid.cols, grid.rows);
    for (int gr = area.y; gr < area.y + area.height; ++gr)
        for (int gc = area.x; gc < area.x + area.width; ++gc) {
            const std::size_t k = static_cast<std::size_t>(gr) * grid.cols + gc;
            const float px = grid.x[k], py = grid.y[k], pz = grid.z[k];
            const float np = n.x() * px + n.y() * py + n.z() * pz, h = np + d;
            const float band = std::min(std::max(static_cast<float>(tolerance.sigmas * tolerance.noise_k) * pz * pz,
                                                 static_cast<float>(tolerance.min_band)),
                                        static_cast<float>(tolerance.max_band));
            const float margin = std::max(static_cast<float>(tolerance.obstacle_bands) * band,
                                          static_cast<float>(tolerance.min_obstacle));
            const float ac = r.dot(Eigen::Vector3f(px, py, pz)) + col0, aw = u.dot(Eigen::Vector3f(px, py, pz)) + row0;
            if (!(std::abs(h - shape.at(ac, aw)) > margin) || !(std::abs(np) >= 1e-6f)) continue;
            const float t = -d / np;
            const float tc = t * (r.x() * px + r.y() * py + r.z() * pz) + col0;
            const float tw = t * (u.x() * px + u.y() * py + u.z() * pz) + row0;
            if (!(t > 0.0f) || !(tc >= 0.0f) || !(tw >= 0.0f)) continue;
            if (!(tc < static_cast<float>(raster.cols)) || !(tw < static_cast<float>(raster.rows)))
                continue;  // off the raster
            if (cells.contains(static_cast<int>(tw), static_cast<int>(tc))) out.push_back(grid.cloudIndex(gr, gc));
        }
    return out;
}

}  // namespace projsurf
