#include "projsurf/sim/kinect1_model.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "projsurf/sim/noise/gaussian_table.hpp"
#include "projsurf/sim/noise/noise_field.hpp"

namespace projsurf::sim {

Kinect1Unit makeKinect1Unit(const Kinect1Model &m, int unit) {
    const CameraIntrinsics &c = m.base.camera;
    Kinect1Unit k;
    k.unit = unit;
    cv::Mat f = smoothField(c.width, c.height, m.distortion_cell_px, unitSeed("kinect1", unit, "distortion"));
    const double r2_corner =
        std::pow(std::max(c.cx, c.width - 1 - c.cx), 2) + std::pow(std::max(c.cy, c.height - 1 - c.cy), 2);
    for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
            const double r2 = ((u - c.cx) * (u - c.cx) + (v - c.cy) * (v - c.cy)) / r2_corner;
            f.at<float>(v, u) *= static_cast<float>(1.0 - m.distortion_border_growth + m.distortion_border_growth * r2);
        }
    normalizeField(f);
    k.distortion = f * m.distortion_k;
    k.bands = columnBands(c.width, m.banding_period_px, unitSeed("kinect1", unit, "bands"));
    for (float &b : k.bands) b *= static_cast<float>(m.banding_k);
    std::mt19937 rng(unitSeed("kinect1", unit, "scale"));
    k.scale = 1.0 + m.scale_error_sigma * NormalSource(rng).next();
    return k;
}

cv::Mat measureKinect1(const Scene &scene, const ExactDepth &e, const Kinect1Model &m, const Kinect1Unit &unit,
                       unsigned seed) {
    const SensorModel &s = m.base;
    const CameraIntrinsics &c = e.camera;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    NormalSource gauss(rng);
    const cv::Mat shadow = s.ir_shadow ? occlusionFrom(scene, e, s.emitter, c.width / 8) : cv::Mat();
    const cv::Mat edges = depthEdgeMask(e.z, s.edge_jump, 2);
    const cv::Mat fly_edges = depthEdgeMask(e.z, s.edge_jump, 0);
    const double cos_start = std::cos(s.grazing_start_deg * M_PI / 180.0),
                 cos_max = std::cos(s.grazing_max_deg * M_PI / 180.0);
    cv::Mat out(c.height, c.width, CV_64F, cv::Scalar(0));
    for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
            double z;
            int q;
            opaqueAt(e, u, v, z, q);
            int qu = u, qv = v;
            // Ragged edges: the reading may come from a neighbour across the edge.
            if (s.edge_jitter_px > 0.0 && edges.at<uchar>(v, u)) {
                qu = std::clamp(u + static_cast<int>(std::lround(s.edge_jitter_px * gauss.next())), 0, c.width - 1);
                qv = std::clamp(v + static_cast<int>(std::lround(s.edge_jitter_px * gauss.next())), 0, c.height - 1);
                opaqueAt(e, qu, qv, z, q);
            }
            if (q < 0) continue;
            const int seen = e.quad.at<int>(qv, qu);
            const Material mat = scene.quads[seen].material;
            if (mat == Material::Glass && uniform(rng) >= m.glass_through) continue;
            const Material surf = scene.quads[q].material;
            if (surf == Material::Black && uniform(rng) < m.black_dropout) continue;
            if (surf == Material::Glossy && uniform(rng) < m.glossy_dropout) continue;
            if (!shadow.empty() && shadow.at<uchar>(qv, qu)) continue;
            const double ca = e.cos_incidence.at<float>(qv, qu);
            if (ca < cos_max) continue;
            if (ca < cos_start) {
                const double drop = s.dropoutProbability(std::acos(ca) * 180.0 / M_PI);
                if (uniform(rng) < drop) continue;
            }
            // Flying pixels: a mix of this side and a neighbour's depth across the edge.
            if (fly_edges.at<uchar>(v, u) && uniform(rng) < m.flying_probability) {
                const int du = uniform(rng) < 0.5 ? -1 : 1;
                double zn;
                int qn;
                opaqueAt(e, std::clamp(u + du, 0, c.width - 1), v, zn, qn);
                if (qn >= 0) {
                    const double a = uniform(rng);
                    z = a * z + (1.0 - a) * zn;
                }
            }
            // Systematic errors in inverse depth (the sensor measures disparity), then the
            // independent noise and the quantisation of SensorModel::measure.
            const double w = 1.0 / (unit.scale * z) + unit.distortion.at<float>(v, u) + unit.bands[u];
            if (!(w > 0.0)) continue;
            out.at<double>(v, u) = s.measure(1.0 / w, s.noise ? gauss.next() : 0.0);
        }
    return out;
}

}  // namespace projsurf::sim
