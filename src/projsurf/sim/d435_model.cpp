#include "projsurf/sim/d435_model.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <opencv2/imgproc.hpp>

#include "projsurf/sim/noise/gaussian_table.hpp"
#include "projsurf/sim/noise/noise_field.hpp"

namespace projsurf::sim {

D435Unit makeD435Unit(const D435Model &m, int unit) {
    D435Unit d;
    d.unit = unit;
    d.field = smoothField(m.camera.width, m.camera.height, m.unit_cell_px, unitSeed("d435", unit, "field"));
    return d;
}

cv::Mat measureD435(const Scene &scene, const ExactDepth &e, const D435Model &m, const D435Unit &unit, unsigned seed) {
    const CameraIntrinsics &c = e.camera;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    // What the left imager sees through glass, then the right imager's occlusion (+x).
    cv::Mat z(c.height, c.width, CV_64F, cv::Scalar(0));
    cv::Mat quad(c.height, c.width, CV_32S, cv::Scalar(-1));
    for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
            double zz;
            int q;
            opaqueAt(e, u, v, zz, q);
            if (q < 0) continue;
            if (scene.quads[e.quad.at<int>(v, u)].material == Material::Glass && uniform(rng) >= m.glass_through)
                continue;
            z.at<double>(v, u) = zz;
            quad.at<int>(v, u) = q;
        }
    const cv::Mat hidden = occlusionFrom(scene, e, Eigen::Vector3d(m.baseline, 0.0, 0.0), 0);
    // Edge fattening: a background pixel within the window of a nearer surface takes its depth.
    cv::Mat near_z = z.clone();
    near_z.setTo(1e9, z <= 0.0);
    cv::erode(near_z, near_z, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * m.fatten_px + 1, 3)));
    // Noise fields: per-frame correlated, per-unit smooth, independent; speckle holes.
    const double s_corr = std::sqrt(m.share_correlated), s_unit = std::sqrt(m.share_unit);
    const double s_iid = std::sqrt(std::max(0.0, 1.0 - m.share_correlated - m.share_unit));
    const cv::Mat corr = correlatedNoise(c.width, c.height, m.correlated_sigma_px, rng);
    const cv::Mat speckle = correlatedNoise(c.width, c.height, m.speckle_sigma_px, rng);
    // Threshold of a unit-RMS Gaussian field exceeded by `share` of pixels.
    auto threshold = [](double share) {
        double lo = -6, hi = 6;
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            (0.5 * std::erfc(mid / std::sqrt(2.0)) > share ? lo : hi) = mid;
        }
        return lo;
    };
    const double t_speckle = threshold(m.speckle_share), t_black = threshold(m.black_speckle_share),
                 t_glossy = threshold(m.glossy_speckle_share);
    NormalSource gauss(rng);
    const double cos_max = std::cos(m.grazing_max_deg * M_PI / 180.0);
    const double fb = c.fx * m.baseline;
    cv::Mat out(c.height, c.width, CV_64F, cv::Scalar(0));
    for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
            double zz = z.at<double>(v, u);
            int q = quad.at<int>(v, u);
            const double zn = near_z.at<double>(v, u);
            if (zn < 1e8 && (zz <= 0.0 || zz - zn > m.edge_jump)) {
                zz = zn;  // fattened foreground
                q = -2;
            }
            if (zz <= 0.0) continue;
            if (q >= 0) {
                if (hidden.at<uchar>(v, u)) continue;
                if (e.cos_incidence.at<float>(v, u) < cos_max) continue;
                const Material mat = scene.quads[q].material;
                const double t = mat == Material::Black ? t_black : mat == Material::Glossy ? t_glossy : t_speckle;
                if (speckle.at<float>(v, u) > t) continue;
            }
            const double sigma = m.rms_at_2m * (zz / 2.0) * (zz / 2.0);
            const double err =
                sigma * (s_corr * corr.at<float>(v, u) + s_unit * unit.field.at<float>(v, u) + s_iid * gauss.next());
            // Quantise the disparity of the erroneous depth.
            const double disparity = fb / (zz + err);
            const double dq = std::round(disparity / m.subpixel) * m.subpixel;
            if (!(dq > 0.0)) continue;
            const double zm = fb / dq;
            if (zm >= m.min_depth && zm <= m.max_depth) out.at<double>(v, u) = zm;
        }
    return out;
}

}  // namespace projsurf::sim
