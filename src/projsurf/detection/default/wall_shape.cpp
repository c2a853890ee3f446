#include "projsurf/detection/default/wall_shape.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <memory>

#include "projsurf/detection/default/plane_samples.hpp"
#include "projsurf/detection/default/wall_relief.hpp"
#include "projsurf/types/target_clones.hpp"

namespace projsurf {
namespace {

/// The Tukey-weighted normal equations of the quadratic about `shape` (its relief empty) over
/// `near`, summed flat: the lower triangle row by row in `a`, the right side in `b`. The same
/// sums in the same order as the matrix form (no fused multiply-add in either build).
PROJSURF_CLONES void accumulateRound(const std::vector<PlaneSample> &near, const WallShape &shape, double tukey_bands,
                                     double a[21], double b[6]) {
    const double cx = shape.centre.x(), cy = shape.centre.y();
    const double c0 = shape.c[0], c1 = shape.c[1], c2 = shape.c[2], c3 = shape.c[3], c4 = shape.c[4], c5 = shape.c[5];
    double sa[21] = {}, sb[6] = {};  // local: no store through a and b per sample
    for (const PlaneSample &s : near) {
        const double x = s.uv.x() - cx, y = s.uv.y() - cy;
        const double q = c0 + c1 * x + c2 * y + c3 * x * x + c4 * x * y + c5 * y * y;
        const double r = (s.h - q) / (tukey_bands * s.band);
        if (std::abs(r) >= 1.0) continue;
        const double w = (1.0 - r * r) * (1.0 - r * r);
        const double phi[6] = {1.0, x, y, x * x, x * y, y * y};
        double wphi[6];
        for (int i = 0; i < 6; ++i) wphi[i] = w * phi[i];
        int m = 0;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j <= i; ++j) sa[m++] += wphi[i] * phi[j];
        for (int i = 0; i < 6; ++i) sb[i] += wphi[i] * s.h;
    }
    std::copy(sa, sa + 21, a);
    std::copy(sb, sb + 6, b);
}

}  // namespace

std::optional<WallShape> fitWallShape(const std::vector<Point> &points, const std::vector<float> &band,
                                      const Plane &plane, const PlaneFrame &frame, const WallShapeOptions &options,
                                      double focal_px) {
    // Every point in plane coordinates once (the quadratic's and the relief's passes read them).
    const std::size_t n = points.size();
    const std::unique_ptr<PlaneSample[]> seen(new PlaneSample[n]);  // each written below: no zero-filling
    planeSamples(points, band, plane, frame, seen.get());
    std::vector<PlaneSample> near;
    near.reserve(n);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e30), hi = Eigen::Vector2d::Constant(-1e30);
    for (std::size_t i = 0; i < n; ++i) {
        const PlaneSample &s = seen[i];
        if (!(std::abs(s.h) <= options.capture_bands * s.band)) continue;
        near.push_back(s);
        lo = lo.cwiseMin(s.uv);
        hi = hi.cwiseMax(s.uv);
    }
    if (static_cast<int>(near.size()) < options.min_points) return std::nullopt;
    // A few thousand points pin six coefficients down; keep every k-th of the rest.
    if (static_cast<int>(near.size()) > options.max_points) {
        const std::size_t k = (near.size() + options.max_points - 1) / options.max_points;
        std::size_t j = 0;
        for (std::size_t i = 0; i < near.size(); i += k) near[j++] = near[i];
        near.resize(j);
    }
    WallShape shape;
    shape.centre = 0.5 * (lo + hi);
    for (int it = 0; it < options.iterations; ++it) {
        double a[21], sums[6];
        accumulateRound(near, shape, options.tukey_bands, a, sums);
        Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
        const Eigen::Matrix<double, 6, 1> b(sums);
        for (int i = 0, m = 0; i < 6; ++i)
            for (int j = 0; j <= i; ++j) A(i, j) = a[m++];
        const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(A.selfadjointView<Eigen::Lower>());
        if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return std::nullopt;
        shape.c = ldlt.solve(b);
        if (!shape.c.allFinite()) return std::nullopt;
    }
    // A bend larger than any sensor gives means the fit followed something else. The sensor's
    // bend is a disparity error, so what it may reach grows with depth squared.
    for (const Eigen::Vector2d &corner : {lo, hi, Eigen::Vector2d(lo.x(), hi.y()), Eigen::Vector2d(hi.x(), lo.y())}) {
        const double z = frame.toCamera(corner).z();
        if (!(std::abs(shape.height(corner)) <= std::max(options.max_bend, options.bend_per_z2 * z * z)))
            return std::nullopt;
    }
    if (options.relief.enabled) {
        // The relief on every point near the quadratic (the distortion may carry a point
        // further from the plane than the capture above).
        std::vector<ReliefSample> relief;
        relief.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            const PlaneSample &s = seen[i];
            const double r = s.h - shape.quadratic(s.uv);
            if (std::abs(r) <= options.capture_bands * s.band) relief.push_back({s.uv, r, s.band, s.z});
        }
        shape.relief = fitWallRelief(relief, focal_px, options.relief);
    }
    std::vector<double> scaled;
    scaled.reserve(near.size());
    for (const PlaneSample &s : near) scaled.push_back(std::abs(s.h - shape.height(s.uv)) / (s.z * s.z));
    std::nth_element(scaled.begin(), scaled.begin() + scaled.size() / 2, scaled.end());
    shape.noise_k = 1.4826 * scaled[scaled.size() / 2];
    return shape;
}

DepthTolerance toleranceFor(const WallShape &shape, const DepthTolerance &model, double lo, double hi) {
    DepthTolerance t = model;
    if (shape.noise_k > 0.0) t.noise_k = std::clamp(shape.noise_k, lo * model.noise_k, hi * model.noise_k);
    return t;
}

double localNoiseK(const Cloud &cloud, const std::vector<int> &sample, const std::vector<float> &band,
                   const Plane &plane, double capture_bands, int offset, int min_pairs) {
    if (!cloud.organized() || offset < 1) return 0.0;
    const Eigen::Vector3f n = plane.normal.cast<float>();
    const float d = static_cast<float>(plane.d);
    std::vector<double> diffs;  // |h_i - h_j| / z^2
    for (std::size_t k = 0; k < sample.size(); ++k) {
        const int i = sample[k];
        const Point &p = cloud.points[i];
        const float h = n.dot(p) + d, cap = static_cast<float>(capture_bands) * band[k];
        if (!(std::abs(h) <= cap)) continue;
        const int u = i % cloud.width, v = i / cloud.width;
        for (const int j :
             {u + offset < cloud.width ? i + offset : -1, v + offset < cloud.height ? i + offset * cloud.width : -1}) {
            if (j < 0) continue;
            const Point &q = cloud.points[j];
            const float hq = n.dot(q) + d;
            if (!(std::abs(hq) <= cap)) continue;
            diffs.push_back(std::abs(h - hq) / (static_cast<double>(p.z()) * p.z()));
        }
    }
    if (static_cast<int>(diffs.size()) < min_pairs) return 0.0;
    const std::size_t keep = diffs.size() * 9 / 10;
    std::nth_element(diffs.begin(), diffs.begin() + keep, diffs.end());
    double sum = 0.0;
    for (std::size_t k = 0; k < keep; ++k) sum += diffs[k];
    // a - b ~ N(0, sqrt(2) sigma) for independent readings; the mean of the smallest 90 % of
    // |N(0, s)| is 0.6573 s.
    return sum / static_cast<double>(keep) / (0.6573 * std::sqrt(2.0));
}

}  // namespace projsurf
