#include "projsurf/detection/planes/pixel_lattice.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {
namespace {

/// One run of sorted values with no gap over the tolerance: a column, or a stray value.
struct Run {
    double centre = 0.0;  ///< mean of its values
    int values = 0;
};

/// The sorted values grouped into runs (a cloud on no grid has no gaps that wide and comes
/// back as a few long runs).
std::vector<Run> runsOf(const std::vector<float> &sorted, double tolerance) {
    std::vector<Run> runs;
    if (sorted.empty()) return runs;
    std::size_t first = 0;
    double sum = sorted[0];
    for (std::size_t i = 1; i <= sorted.size(); ++i) {
        if (i == sorted.size() || sorted[i] - sorted[i - 1] > tolerance) {
            runs.push_back({sum / static_cast<double>(i - first), static_cast<int>(i - first)});
            if (i == sorted.size()) break;
            first = i;
            sum = 0.0;
        }
        sum += sorted[i];
    }
    return runs;
}

/// Least squares of centre = origin + step * k over the runs' lattice indices at about `step`,
/// each index counted from the last run on the lattice (an error in `step` does not add up over
/// hundreds of columns, a stray value does not shift the ones after it). Nullopt when the runs
/// off the lattice hold more than max_off of the values.
std::optional<PixelLattice> fitLattice(const std::vector<Run> &runs, double step, const PixelLatticeOptions &opt) {
    double sk = 0, sc = 0, skk = 0, skc = 0, n = 0, last_k = 0, last_c = runs[0].centre;
    long off = 0, total = 0;
    for (const Run &r : runs) {
        total += r.values;
        const double t = (r.centre - last_c) / step;
        if (std::abs(t - std::round(t)) > opt.max_residual) {
            off += r.values;
            continue;
        }
        const double k = last_k + std::round(t);
        if (k > opt.max_columns) return std::nullopt;
        last_k = k;
        last_c = r.centre;
        sk += k;
        sc += r.centre;
        skk += k * k;
        skc += k * r.centre;
        n += 1;
    }
    const double det = n * skk - sk * sk;
    if (!(det > 0.0) || static_cast<double>(off) > opt.max_off * static_cast<double>(total)) return std::nullopt;
    PixelLattice l;
    l.step = (n * skc - sk * sc) / det;
    l.origin = (sc - l.step * sk) / n;
    return l;
}

/// The lattice's first and last columns holding a value on it.
bool spanValues(const std::vector<float> &values, const PixelLatticeOptions &opt, PixelLattice &l) {
    double lo = 1e300, hi = -1e300;
    for (float v : values) {
        const double k = l.index(v);
        if (std::abs(k - std::round(k)) > opt.max_residual) continue;
        lo = std::min(lo, std::round(k));
        hi = std::max(hi, std::round(k));
    }
    if (!(hi >= lo) || hi - lo >= opt.max_columns) return false;
    l.origin += lo * l.step;
    l.count = static_cast<int>(hi - lo) + 1;
    return true;
}

}  // namespace

std::optional<PixelLattice> pixelLattice(const std::vector<float> &values, const PixelLatticeOptions &opt) {
    const std::size_t stride = std::max<std::size_t>(1, values.size() / std::max(opt.max_samples, 1));
    std::vector<float> sample;
    sample.reserve(values.size() / stride + 1);
    for (std::size_t i = 0; i < values.size(); i += stride) sample.push_back(values[i]);
    std::sort(sample.begin(), sample.end());
    const std::vector<Run> runs = runsOf(sample, opt.tolerance);
    if (static_cast<int>(runs.size()) < opt.min_columns || static_cast<int>(runs.size()) > opt.max_columns)
        return std::nullopt;
    // The step: the gap between neighbouring columns (a low quantile, since missing columns
    // leave gaps of two or more steps); columns closer than a few tolerances are no lattice.
    std::vector<double> gaps(runs.size() - 1);
    for (std::size_t i = 1; i < runs.size(); ++i) gaps[i - 1] = runs[i].centre - runs[i - 1].centre;
    const auto q = gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 10);
    std::nth_element(gaps.begin(), q, gaps.end());
    if (!(*q > 8.0 * opt.tolerance)) return std::nullopt;
    std::optional<PixelLattice> lattice = fitLattice(runs, *q, opt);
    if (!lattice || !spanValues(values, opt, *lattice)) return std::nullopt;
    return lattice;
}

}  // namespace projsurf
