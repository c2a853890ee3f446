#include "projsurf/sim/sensor_model.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf::sim {

SensorModel SensorModel::ideal() {
    SensorModel s;
    s.noise = false;
    s.quantize = false;
    s.ir_shadow = false;
    return s;
}

double SensorModel::dropoutProbability(double angle_deg) const {
    if (angle_deg >= grazing_max_deg) return 1.0;
    if (!noise || angle_deg <= grazing_start_deg) return 0.0;
    return (angle_deg - grazing_start_deg) / (grazing_max_deg - grazing_start_deg);
}

double SensorModel::inverseDepthSigma() const {
    if (!noise) return 0.0;
    // sigma_z = sigma_w z^2 for small noise, so sigma_w = k; quantisation adds step^2 / 12
    // of variance in w, which the published total already contains.
    const double q2 = quantize ? disparity_step * disparity_step / 12.0 : 0.0;
    return std::sqrt(std::max(noise_k * noise_k - q2, 0.0));
}

double SensorModel::measure(double z, double standard_normal) const {
    if (!(z >= min_depth && z <= max_depth)) return 0.0;
    double w = 1.0 / z + inverseDepthSigma() * standard_normal;  // inverse depth, 1/m
    if (quantize) {
        const double raw = std::floor((disparity_offset - w) / disparity_step + 0.5);
        w = disparity_offset - disparity_step * raw;
    }
    if (!(w > 0.0)) return 0.0;
    const double zm = 1.0 / w;
    return zm >= min_depth && zm <= max_depth ? zm : 0.0;
}

}  // namespace projsurf::sim
