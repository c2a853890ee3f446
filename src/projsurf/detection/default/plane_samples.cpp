#include "projsurf/detection/default/plane_samples.hpp"

#include <cmath>

#include "projsurf/types/target_clones.hpp"

namespace projsurf {

PROJSURF_CLONES void planeSamples(const std::vector<Point> &points, const std::vector<float> &band, const Plane &plane,
                                  const PlaneFrame &frame, PlaneSample *out) {
    const double nx = plane.normal.x(), ny = plane.normal.y(), nz = plane.normal.z(), d = plane.d;
    const double ox = frame.origin.x(), oy = frame.origin.y(), oz = frame.origin.z();
    const double rx = frame.right.x(), ry = frame.right.y(), rz = frame.right.z();
    const double ux = frame.up.x(), uy = frame.up.y(), uz = frame.up.z();
    const Point *P = points.data();
    const float *B = band.data();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double px = P[i].x(), py = P[i].y(), pz = P[i].z();
        const double qx = px - ox, qy = py - oy, qz = pz - oz;
        out[i].uv[0] = qx * rx + qy * ry + qz * rz;
        out[i].uv[1] = qx * ux + qy * uy + qz * uz;
        out[i].h = nx * px + ny * py + nz * pz + d;
        out[i].band = B[i];
        out[i].z = pz;
    }
}

PROJSURF_CLONES void offQuadratic(const std::vector<Point> &points, const Plane &plane, const PlaneFrame &frame,
                                  const WallShape &shape, const DepthTolerance &tolerance, double *off, float *band) {
    const double nx = plane.normal.x(), ny = plane.normal.y(), nz = plane.normal.z(), d = plane.d;
    const double ox = frame.origin.x(), oy = frame.origin.y(), oz = frame.origin.z();
    const double rx = frame.right.x(), ry = frame.right.y(), rz = frame.right.z();
    const double ux = frame.up.x(), uy = frame.up.y(), uz = frame.up.z();
    const double cx = shape.centre.x(), cy = shape.centre.y();
    const double c0 = shape.c[0], c1 = shape.c[1], c2 = shape.c[2], c3 = shape.c[3], c4 = shape.c[4], c5 = shape.c[5];
    const double k = tolerance.sigmas * tolerance.noise_k, lo = tolerance.min_band, hi = tolerance.max_band;
    const Point *P = points.data();
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i) {
        const float fz = P[i].z();
        const double px = P[i].x(), py = P[i].y(), pz = fz;
        const double sd = nx * px + ny * py + nz * pz + d;
        const double qx = px - ox, qy = py - oy, qz = pz - oz;
        const double x = (qx * rx + qy * ry + qz * rz) - cx, y = (qx * ux + qy * uy + qz * uz) - cy;
        off[i] = std::abs(sd - (c0 + c1 * x + c2 * y + c3 * x * x + c4 * x * y + c5 * y * y));
        const double b = k * pz * fz;
        band[i] = static_cast<float>(b < lo ? lo : (b > hi ? hi : b));
    }
}

}  // namespace projsurf
