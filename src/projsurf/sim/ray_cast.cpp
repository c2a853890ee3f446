#include "projsurf/sim/ray_cast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace projsurf::sim {

PinholeView PinholeView::scaled(double s) const {
    PinholeView v = *this;
    v.width = std::max(1, static_cast<int>(std::lround(width * s)));
    v.height = std::max(1, static_cast<int>(std::lround(height * s)));
    const double sx = static_cast<double>(v.width) / width, sy = static_cast<double>(v.height) / height;
    v.fx = fx * sx;
    v.fy = fy * sy;
    // Outer image edges stay where they were: edge -0.5 maps to -0.5.
    v.cx = (cx + 0.5) * sx - 0.5;
    v.cy = (cy + 0.5) * sy - 0.5;
    return v;
}

PinholeView PinholeView::padded(int pad_px) const {
    PinholeView v = *this;
    v.width += 2 * pad_px;
    v.height += 2 * pad_px;
    v.cx += pad_px;
    v.cy += pad_px;
    return v;
}

PinholeView PinholeView::fromIntrinsics(double fx, double fy, double cx, double cy, int width, int height) {
    return PinholeView{Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), fx, fy, cx, cy, width, height};
}

PinholeView PinholeView::placed(const Eigen::Vector3d &at, const Eigen::Vector3d &right, const Eigen::Vector3d &down,
                                const Eigen::Vector3d &forward) const {
    PinholeView v = *this;
    v.origin = at;
    v.rotation.row(0) = right.transpose();
    v.rotation.row(1) = down.transpose();
    v.rotation.row(2) = forward.transpose();
    return v;
}

PinholeView cameraView(const CameraIntrinsics &c) {
    return PinholeView::fromIntrinsics(c.fx, c.fy, c.cx, c.cy, c.width, c.height);
}

PinholeView projectorView(const Projector &p) {
    PinholeView v = PinholeView::fromIntrinsics(p.fx(), p.fy(), p.cx(), p.cy(), p.width, p.height)
                        .placed(p.origin, p.right(), p.down(), p.axis());
    if (p.distorted()) {
        // The ideal (undistorted) pinhole view covering every lit direction: the bounding box
        // of the framebuffer's edges in ideal pixels. Framebuffer pixels: Projector::toPixel.
        double lo_x = HUGE_VAL, hi_x = -HUGE_VAL, lo_y = HUGE_VAL, hi_y = -HUGE_VAL;
        const int n = 64;
        for (int i = 0; i <= n; ++i) {
            const double s = static_cast<double>(i) / n;
            const Eigen::Vector2d pts[4] = {{-0.5 + s * p.width, -0.5},
                                            {-0.5 + s * p.width, p.height - 0.5},
                                            {-0.5, -0.5 + s * p.height},
                                            {p.width - 0.5, -0.5 + s * p.height}};
            for (const auto &q : pts) {
                const Eigen::Vector2d ideal = p.idealFromPixel(q);
                lo_x = std::min(lo_x, ideal.x());
                hi_x = std::max(hi_x, ideal.x());
                lo_y = std::min(lo_y, ideal.y());
                hi_y = std::max(hi_y, ideal.y());
            }
        }
        const int left = static_cast<int>(std::ceil(-0.5 - lo_x)) + 1,
                  top = static_cast<int>(std::ceil(-0.5 - lo_y)) + 1;
        v.cx += left;
        v.cy += top;
        v.width = static_cast<int>(std::ceil(hi_x + 0.5)) + left + 1;
        v.height = static_cast<int>(std::ceil(hi_y + 0.5)) + top + 1;
    }
    return v;
}

PinholeView facingView(const Plane &plane, const Eigen::Vector3d &target, double distance,
                       const Eigen::Vector3d &gravity, int width, int height, double fov_h_deg) {
    const Eigen::Vector3d forward = -plane.normal;  // the normal points towards the camera side
    Eigen::Vector3d down = gravity - gravity.dot(forward) * forward;
    if (down.norm() < 1e-9) down = Eigen::Vector3d::UnitY() - forward.y() * forward;
    down.normalize();
    const Eigen::Vector3d right = down.cross(forward);
    const double f = 0.5 * width / std::tan(0.5 * fov_h_deg * 3.14159265358979323846 / 180.0);
    return PinholeView::fromIntrinsics(f, f, 0.5 * (width - 1), 0.5 * (height - 1), width, height)
        .placed(plane.project(target) - distance * forward, right, down, forward);
}

namespace {

/// Pixel bounding box [u0, u1] x [v0, v1] of a quad (view frame corners), clipped to the
/// image and to the near plane; false when nothing of it is in front of the view.
bool pixelBounds(const std::array<Eigen::Vector3d, 4> &c, const PinholeView &view, double near, int &u0, int &u1,
                 int &v0, int &v1) {
    // Sutherland-Hodgman against z >= near, then the box of the projected polygon.
    std::vector<Eigen::Vector3d> poly;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector3d &a = c[i], &b = c[(i + 1) % 4];
        const bool ain = a.z() >= near, bin = b.z() >= near;
        if (ain) poly.push_back(a);
        if (ain != bin) poly.push_back(a + (b - a) * ((near - a.z()) / (b.z() - a.z())));
    }
    if (poly.empty()) return false;
    double umin = std::numeric_limits<double>::infinity(), vmin = umin, umax = -umin, vmax = -umin;
    for (const auto &p : poly) {
        const Eigen::Vector2d px = view.pixelOf(p);
        umin = std::min(umin, px.x());
        umax = std::max(umax, px.x());
        vmin = std::min(vmin, px.y());
        vmax = std::max(vmax, px.y());
    }
    u0 = static_cast<int>(std::max(0.0, std::floor(umin)));
    v0 = static_cast<int>(std::max(0.0, std::floor(vmin)));
    u1 = static_cast<int>(std::min(view.width - 1.0, std::ceil(umax)));
    v1 = static_cast<int>(std::min(view.height - 1.0, std::ceil(vmax)));
    return u0 <= u1 && v0 <= v1;
}

}  // namespace

DepthBuffer castView(const Scene &scene, const PinholeView &view, double near) {
    DepthBuffer buf;
    buf.z = cv::Mat(view.height, view.width, CV_64F, cv::Scalar(std::numeric_limits<double>::infinity()));
    buf.quad = cv::Mat(view.height, view.width, CV_32S, cv::Scalar(-1));
    const double eps = 1e-9;  // shared edges of neighbouring quads leave no cracks
    for (std::size_t qi = 0; qi < scene.quads.size(); ++qi) {
        const Quad &q = scene.quads[qi];
        std::array<Eigen::Vector3d, 4> c;
        const auto world = q.corners();
        for (int i = 0; i < 4; ++i) c[i] = view.toView(world[i]);
        int u0 = 0, u1 = -1, v0 = 0, v1 = -1;
        if (!pixelBounds(c, view, near, u0, u1, v0, v1)) continue;
        // In the view frame the ray through (u, v) is t * d, d = ((u-cx)/fx, (v-cy)/fy, 1),
        // so t is the depth. Hit: t = (n.C) / (n.d); quad coordinates via the dual basis.
        const Eigen::Vector3d C = c[0], A = c[1] - c[0], B = c[3] - c[0];
        const Eigen::Vector3d n = A.cross(B);
        const double nc = n.dot(C);
        if (std::abs(nc) < 1e-15) continue;  // seen edge-on
        const Eigen::Vector3d fa = B.cross(n) / B.cross(n).dot(A);
        const Eigen::Vector3d fb = n.cross(A) / n.cross(A).dot(B);
        const double cfa = C.dot(fa), cfb = C.dot(fb);
        // Along a row d = (x, dy, 1) with x = (u - cx) / fx, so n.d, d.fa and d.fb are linear in x.
        for (int v = v0; v <= v1; ++v) {
            const double dy = (v - view.cy) / view.fy;
            const double n0 = n.y() * dy + n.z(), a0 = fa.y() * dy + fa.z(), b0 = fb.y() * dy + fb.z();
            double *zrow = buf.z.ptr<double>(v);
            int *qrow = buf.quad.ptr<int>(v);
            for (int u = u0; u <= u1; ++u) {
                const double x = (u - view.cx) / view.fx;
                const double den = n.x() * x + n0;
                if (std::abs(den) < 1e-15) continue;
                const double t = nc / den;
                if (!(t >= near) || !(t < zrow[u])) continue;
                const double a = t * (fa.x() * x + a0) - cfa, b = t * (fb.x() * x + b0) - cfb;
                if (a < -eps || a > 1.0 + eps || b < -eps || b > 1.0 + eps) continue;
                zrow[u] = t;
                qrow[u] = static_cast<int>(qi);
            }
        }
    }
    return buf;
}

bool ShadowMap::reaches(const Eigen::Vector3d &p, int quad) const {
    const Eigen::Vector3d pv = view.toView(p);
    if (!(pv.z() > 0.0)) return false;
    const Eigen::Vector2d px = view.pixelOf(pv);
    if (!view.inside(px)) return false;
    const int u = std::clamp(static_cast<int>(px.x() + 0.5), 0, view.width - 1);  // px >= -0.5
    const int v = std::clamp(static_cast<int>(px.y() + 0.5), 0, view.height - 1);
    const int seen = buffer.quad.at<int>(v, u);
    if (seen == quad) return true;
    // A different surface at that texel: p is reached when that surface is not clearly in
    // front of it (texel-size steps at junctions, posters a few mm proud of the wall).
    const double bias = 0.01 + 0.01 * pv.z();  // m
    return seen < 0 || buffer.z.at<double>(v, u) >= pv.z() - bias;
}

ShadowMap makeShadowMap(const Scene &scene, const PinholeView &view, double scale) {
    ShadowMap m;
    m.view = scale == 1.0 ? view : view.scaled(scale);
    m.buffer = castView(scene, m.view, 0.01);
    return m;
}

}  // namespace projsurf::sim
