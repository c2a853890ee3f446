#include "projsurf/sim/tof_model.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "projsurf/sim/noise/gaussian_table.hpp"
#include "projsurf/sim/noise/noise_field.hpp"

namespace projsurf::sim {

TofUnit makeTofUnit(const TofModel &m, int unit) {
    TofUnit t;
    t.unit = unit;
    std::mt19937 rng(unitSeed("tof", unit, "offset"));
    NormalSource g(rng);
    t.offset = m.offset_sigma * g.next();
    t.wiggle_phase = 2.0 * M_PI * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    return t;
}

cv::Mat multipathBias(const Scene &scene, const ExactDepth &e, const TofModel &m) {
    const CameraIntrinsics &c = e.camera;
    const int step = std::max(1, m.multipath_cell_px);
    const int gw = (c.width + step - 1) / step, gh = (c.height + step - 1) / step;
    struct Patch {
        Eigen::Vector3d p, n;
        double area, albedo, range;
    };
    std::vector<Patch> patches(static_cast<std::size_t>(gw) * gh);
    std::vector<char> ok(patches.size(), 0);
    for (int j = 0; j < gh; ++j)
        for (int i = 0; i < gw; ++i) {
            const int u = std::min(c.width - 1, i * step + step / 2), v = std::min(c.height - 1, j * step + step / 2);
            double z;
            int q;
            opaqueAt(e, u, v, z, q);
            if (q < 0 || scene.quads[q].material == Material::Black) continue;
            Patch &pt = patches[j * gw + i];
            pt.p = c.backProject(u, v, z);
            pt.n = scene.quads[q].normal();
            if (pt.n.dot(pt.p) > 0.0) pt.n = -pt.n;  // towards the camera
            pt.range = pt.p.norm();
            const double cos_view = std::max(0.05, -pt.n.dot(pt.p) / pt.range);
            pt.area = (z * step / c.fx) * (z * step / c.fy) / cos_view;  // m^2 of surface in the cell
            const cv::Vec3f &a = scene.quads[q].albedo;
            pt.albedo = (a[0] + a[1] + a[2]) / 3.0;
            ok[j * gw + i] = 1;
        }
    // Per patch: direct light ~ 1 / r^2 (both ways: the camera sees the same patch); one
    // bounce via patch k: emitter -> k (1 / r_k^2, cos_k at k) -> form factor to this patch
    // -> camera. The camera measures the phase of the sum of the direct and indirect returns
    // (phasors at the modulation wavelength): short detours bias the range by about their
    // light-weighted length, long ones partly cancel. Occlusion between patches is ignored.
    cv::Mat coarse(gh, gw, CV_64F, cv::Scalar(0));
    for (std::size_t a = 0; a < patches.size(); ++a) {
        if (!ok[a]) continue;
        const Patch &pa = patches[a];
        double re = 0.0, im = 0.0;  // indirect light as a phasor relative to the direct return
        for (std::size_t b = 0; b < patches.size(); ++b) {
            if (b == a || !ok[b]) continue;
            const Patch &pb = patches[b];
            const Eigen::Vector3d ab = pb.p - pa.p;
            const double d2 = ab.squaredNorm();
            if (d2 < 1e-6) continue;
            const double d = std::sqrt(d2);
            const double cos_a = pa.n.dot(ab) / d, cos_b = -pb.n.dot(ab) / d;
            if (cos_a <= 0.0 || cos_b <= 0.0) continue;  // not facing each other (not concave)
            // Irradiance at b relative to at a (same emitter), times b's albedo, times the form factor b -> a.
            const double lit_b = (pa.range * pa.range) / (pb.range * pb.range) * (-pb.n.dot(pb.p) / pb.range) /
                                 std::max(0.05, -pa.n.dot(pa.p) / pa.range);
            const double w = lit_b * pb.albedo * cos_a * cos_b * pb.area / (M_PI * d2);
            const double phase = 2.0 * M_PI * 0.5 * (pb.range + d - pa.range) / m.modulation_wavelength;
            re += w * std::cos(phase);
            im += w * std::sin(phase);
        }
        coarse.at<double>(static_cast<int>(a) / gw, static_cast<int>(a) % gw) =
            m.modulation_wavelength / (2.0 * M_PI) * std::atan2(m.multipath_gain * im, 1.0 + m.multipath_gain * re);
    }
    cv::Mat bias;
    cv::resize(coarse, bias, cv::Size(gw * step, gh * step), 0, 0, cv::INTER_LINEAR);
    return bias(cv::Rect(0, 0, c.width, c.height)).clone();
}

cv::Mat measureTof(const Scene &scene, const ExactDepth &e, const TofModel &m, const TofUnit &unit, unsigned seed,
                   const cv::Mat &multipath) {
    const CameraIntrinsics &c = e.camera;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    NormalSource gauss(rng);
    const cv::Mat bias = multipath.empty() ? multipathBias(scene, e, m) : multipath;
    const cv::Mat edges = depthEdgeMask(e.z, m.edge_jump, m.flying_radius_px);
    const double cos_max = std::cos(m.grazing_max_deg * M_PI / 180.0);
    const double r2_corner = c.cx * c.cx + c.cy * c.cy;
    cv::Mat out(c.height, c.width, CV_64F, cv::Scalar(0));
    for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
            double z;
            int q;
            opaqueAt(e, u, v, z, q);
            if (q < 0) continue;
            if (scene.quads[e.quad.at<int>(v, u)].material == Material::Glass && uniform(rng) >= m.glass_through)
                continue;
            if (scene.quads[q].material == Material::Black && uniform(rng) < m.black_dropout) continue;
            if (scene.quads[q].material == Material::Glossy && uniform(rng) < m.glossy_dropout) continue;
            if (e.cos_incidence.at<float>(v, u) < cos_max) continue;
            const Eigen::Vector3d d((u - c.cx) / c.fx, (v - c.cy) / c.fy, 1.0);
            const double dn = d.norm();
            // Flying pixels: the pixel's light comes from both sides of the edge.
            if (edges.at<uchar>(v, u) && uniform(rng) < m.flying_probability) {
                const int r = m.flying_radius_px + 1;
                const int nu =
                    std::clamp(u + static_cast<int>(std::lround((2.0 * uniform(rng) - 1.0) * r)), 0, c.width - 1);
                const int nv =
                    std::clamp(v + static_cast<int>(std::lround((2.0 * uniform(rng) - 1.0) * r)), 0, c.height - 1);
                double zn;
                int qn;
                opaqueAt(e, nu, nv, zn, qn);
                if (qn >= 0) {
                    const double a = uniform(rng);
                    z = a * z + (1.0 - a) * zn;
                }
            }
            double range = z * dn + bias.at<double>(v, u) + unit.offset +
                           m.wiggle_amplitude * std::sin(2.0 * M_PI * z * dn / m.wiggle_period + unit.wiggle_phase);
            const double r2 = ((u - c.cx) * (u - c.cx) + (v - c.cy) * (v - c.cy)) / r2_corner;
            const double sigma = (m.noise_base + m.noise_per_m * range) * (1.0 + m.noise_border_gain * r2);
            range += sigma * gauss.next();
            const double zm = range / dn;
            if (zm >= m.min_depth && zm <= m.max_depth) out.at<double>(v, u) = zm;
        }
    return out;
}

}  // namespace projsurf::sim
