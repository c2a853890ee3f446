#include "projsurf/sim/noise/window_noise.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace projsurf::sim {

double DepthBandNoise::median() const {
    if (rms.empty()) return 0.0;
    std::vector<double> v = rms;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

std::vector<DepthBandNoise> depthBands(const std::vector<double> &edges) {
    std::vector<DepthBandNoise> bands;
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) bands.push_back({edges[i], edges[i + 1], {}});
    return bands;
}

namespace {

/// Plane RMS and median depth of the readings in one window; false when too few.
bool windowFit(const Cloud &cloud, int u0, int v0, const WindowNoiseOptions &o, double &rms, double &z_median) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();
    std::vector<float> z;
    z.reserve(static_cast<std::size_t>(o.window) * o.window);
    for (int v = v0; v < v0 + o.window; ++v)
        for (int u = u0; u < u0 + o.window; ++u) {
            const Point &p = cloud.points[static_cast<std::size_t>(v) * cloud.width + u];
            if (!isFinite(p)) continue;
            const Eigen::Vector3d q = p.cast<double>();
            s += q;
            ss += q * q.transpose();
            z.push_back(p.z());
        }
    if (z.size() < o.min_fill * o.window * o.window) return false;
    const double n = static_cast<double>(z.size());
    const Eigen::Vector3d mean = s / n;
    const Eigen::Matrix3d cov = ss / n - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(cov, Eigen::EigenvaluesOnly);
    rms = std::sqrt(std::max(0.0, solver.eigenvalues()(0)));
    std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
    z_median = z[z.size() / 2];
    return rms <= o.max_rms;
}

}  // namespace

void addWindowNoise(const Cloud &cloud, std::vector<DepthBandNoise> &bands, const WindowNoiseOptions &options) {
    if (!cloud.organized() || options.window < 3) return;
    for (int v0 = 0; v0 + options.window <= cloud.height; v0 += options.window)
        for (int u0 = 0; u0 + options.window <= cloud.width; u0 += options.window) {
            double rms = 0, z = 0;
            if (!windowFit(cloud, u0, v0, options, rms, z)) continue;
            for (DepthBandNoise &b : bands)
                if (z >= b.z_lo && z < b.z_hi) b.rms.push_back(rms);
        }
}

}  // namespace projsurf::sim
