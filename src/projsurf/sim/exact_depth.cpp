#include "projsurf/sim/exact_depth.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "projsurf/sim/ray_cast.hpp"

namespace projsurf::sim {
namespace {

/// Depth of the bowed surface along pixel ray d (z = 1 scaled) given the flat hit depth z.
double bowedDepth(const Quad &q, const Eigen::Vector3d &d, double z) {
    if (q.bow.amplitude == 0.0) return z;
    const double delta = q.bow.at(z * d);
    const double nd = q.bow.towards.dot(d);
    if (std::abs(nd) < 1e-6) return z;
    return z + delta / nd;
}

}  // namespace

ExactDepth castExactDepth(const Scene &scene, const CameraIntrinsics &camera) {
    ExactDepth e;
    e.camera = camera;
    const PinholeView view = cameraView(camera);
    const DepthBuffer buf = castView(scene, view, 0.05);
    e.quad = buf.quad.clone();
    e.z = cv::Mat(camera.height, camera.width, CV_64F, cv::Scalar(0));
    e.cos_incidence = cv::Mat(camera.height, camera.width, CV_32F, cv::Scalar(0));
    for (const auto &q : scene.quads) e.any_glass = e.any_glass || q.material == Material::Glass;
    std::vector<Eigen::Vector3d> normals;
    for (const auto &q : scene.quads) normals.push_back(q.normal());

    DepthBuffer behind;
    std::vector<int> index;  // quad in `opaque` -> quad in `scene`
    if (e.any_glass) {
        Scene opaque;
        for (std::size_t i = 0; i < scene.quads.size(); ++i)
            if (scene.quads[i].material != Material::Glass) {
                opaque.quads.push_back(scene.quads[i]);
                index.push_back(static_cast<int>(i));
            }
        behind = castView(opaque, view, 0.05);
        e.behind_z = cv::Mat(camera.height, camera.width, CV_64F, cv::Scalar(0));
        e.behind_quad = cv::Mat(camera.height, camera.width, CV_32S, cv::Scalar(-1));
        e.on_glass = cv::Mat::zeros(camera.height, camera.width, CV_8U);
    }
    for (int v = 0; v < camera.height; ++v)
        for (int u = 0; u < camera.width; ++u) {
            const int qi = buf.quad.at<int>(v, u);
            if (qi < 0) continue;
            const Eigen::Vector3d d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
            e.z.at<double>(v, u) = bowedDepth(scene.quads[qi], d, buf.z.at<double>(v, u));
            int qs = qi;
            if (e.any_glass && scene.quads[qi].material == Material::Glass) {
                e.on_glass.at<uchar>(v, u) = 1;
                const int bi = behind.quad.at<int>(v, u);
                if (bi >= 0) {
                    qs = index[bi];
                    e.behind_quad.at<int>(v, u) = qs;
                    e.behind_z.at<double>(v, u) = bowedDepth(scene.quads[qs], d, behind.z.at<double>(v, u));
                }
            }
            e.cos_incidence.at<float>(v, u) = static_cast<float>(std::abs(normals[qs].dot(d)) / d.norm());
        }
    return e;
}

cv::Mat depthEdgeMask(const cv::Mat &z, double jump, int radius) {
    cv::Mat edges = cv::Mat::zeros(z.rows, z.cols, CV_8U);
    auto differs = [&](int u0, int v0, int u1, int v1) {
        const double a = z.at<double>(v0, u0), b = z.at<double>(v1, u1);
        if ((a > 0.0) != (b > 0.0)) return true;
        return a > 0.0 && std::abs(a - b) > jump;
    };
    for (int v = 0; v < z.rows; ++v)
        for (int u = 0; u < z.cols; ++u)
            if ((u + 1 < z.cols && differs(u, v, u + 1, v)) || (v + 1 < z.rows && differs(u, v, u, v + 1))) {
                edges.at<uchar>(v, u) = 1;
                if (u + 1 < z.cols && differs(u, v, u + 1, v)) edges.at<uchar>(v, u + 1) = 1;
                if (v + 1 < z.rows && differs(u, v, u, v + 1)) edges.at<uchar>(v + 1, u) = 1;
            }
    if (radius > 0)
        cv::dilate(edges, edges, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * radius + 1, 2 * radius + 1)));
    return edges;
}

cv::Mat occlusionFrom(const Scene &scene, const ExactDepth &exact, const Eigen::Vector3d &origin, int pad_px) {
    PinholeView e = cameraView(exact.camera).padded(pad_px);
    e.origin = origin;
    // Glass lets the pattern through: cast without it.
    Scene opaque;
    std::vector<int> to_opaque(scene.quads.size(), -1);
    for (std::size_t i = 0; i < scene.quads.size(); ++i)
        if (scene.quads[i].material != Material::Glass) {
            to_opaque[i] = static_cast<int>(opaque.quads.size());
            opaque.quads.push_back(scene.quads[i]);
        }
    const ShadowMap map = makeShadowMap(opaque, e);
    const CameraIntrinsics &c = exact.camera;
    cv::Mat out = cv::Mat::zeros(c.height, c.width, CV_8U);
    for (int v = 0; v < c.height; ++v)
        for (int u = 0; u < c.width; ++u) {
            double z;
            int q;
            opaqueAt(exact, u, v, z, q);
            if (q < 0 || to_opaque[q] < 0) continue;
            const Eigen::Vector3d p = c.backProject(u, v, z);
            if (!map.reaches(p, to_opaque[q])) out.at<uchar>(v, u) = 1;
        }
    return out;
}

}  // namespace projsurf::sim
