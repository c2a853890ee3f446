#include "projsurf/types/lens_model_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace projsurf {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

/// Empty when a focal length of `f` px over `side` px gives an angle of view in the range.
std::string focalProblem(const std::string &key, double f, int side, bool narrow_ok = false) {
    if (!std::isfinite(f) || !(f > 0)) return key + " must be a positive finite number";
    if (narrow_ok && f > kMaxCameraFocalPx)
        return key + " = " + num(f) + " px is beyond " + num(kMaxCameraFocalPx) + " px: no camera lens is that long";
    const double fov = 2.0 * std::atan(0.5 * side / f) / kDeg;
    if ((!narrow_ok && fov < kMinLensFovDeg) || fov > kMaxLensFovDeg)
        return key + " = " + num(f) + " px gives a " + num(fov) + " deg angle of view over " + std::to_string(side) +
               " px (a lens gives " + num(kMinLensFovDeg) + "-" + num(kMaxLensFovDeg) + ")";
    return "";
}

std::string centreProblem(const std::string &key, double c, int side, bool crop_ok = false) {
    if (!std::isfinite(c)) return key + " is not finite";
    // A crop of a frame keeps the full frame's principal point: only a far-off one is refused.
    if (std::abs(c - 0.5 * side) > (crop_ok ? 1e6 : 4.0 * side))
        return key + " = " + num(c) + " lies implausibly far outside the image";
    return "";
}

}  // namespace

std::string lensModelProblem(const Projector &p) {
    if (p.width < 2 || p.height < 2) return "projector.resolution must be at least 2 x 2";
    const double fh = p.fov_h / kDeg, fv = p.fov_v / kDeg;
    if (!(fh > 0 && fh < kMaxLensFovDeg && fv > 0 && fv < kMaxLensFovDeg))
        return "projector.fov_deg must be two angles between 0 and 170 degrees";
    if (fh < 3.2 && fv < 3.2)
        return "projector.fov_deg [" + num(fh) + ", " + num(fv) +
               "] looks like radians: give the field of view in degrees (a projector's is 15-120)";
    if (!p.origin.allFinite()) return "projector.axis.origin is not finite";
    if (!(p.origin.cwiseAbs().maxCoeff() <= kMaxProjectorOffsetM))
        return "projector.axis.origin is more than 3 m from the camera: give it in metres (millimetres?)";
    if (!p.direction.allFinite() || p.direction.norm() < 1e-9)
        return "projector.axis.direction must be a finite, non-zero vector";
    if (p.intrinsics) {
        const auto &k = *p.intrinsics;
        for (const std::string &e : {focalProblem("projector.intrinsics.fx", k.fx, p.width),
                                     focalProblem("projector.intrinsics.fy", k.fy, p.height),
                                     centreProblem("projector.intrinsics.cx", k.cx, p.width),
                                     centreProblem("projector.intrinsics.cy", k.cy, p.height)})
            if (!e.empty()) return e;
    }
    for (double k : p.distortion)
        if (!std::isfinite(k) || std::abs(k) > 10.0)
            return "projector.distortion has a coefficient beyond +-10: not a projector lens";
    if (p.fullModel() && isValidProjector(p)) {
        const auto fov = fieldOfView(p);
        const double dh = std::abs(fov[0] / kDeg - fh), dv = std::abs(fov[1] / kDeg - fv);
        if (!(dh <= kMaxFovDisagreementDeg && dv <= kMaxFovDisagreementDeg))
            return "projector.intrinsics give a " + num(fov[0] / kDeg) + " x " + num(fov[1] / kDeg) +
                   " deg angle of view, projector.fov_deg says " + num(fh) + " x " + num(fv) + " (at most " +
                   num(kMaxFovDisagreementDeg) + " deg apart)";
    }
    return "";
}

std::string cameraModelProblem(const CameraIntrinsics &c) {
    if (c.width < 1 || c.height < 1) return "camera.width and camera.height must be positive whole numbers";
    for (const std::string &e :
         {focalProblem("camera.fx", c.fx, c.width, true), focalProblem("camera.fy", c.fy, c.height, true),
          centreProblem("camera.cx", c.cx, c.width, true), centreProblem("camera.cy", c.cy, c.height, true)})
        if (!e.empty()) return e;
    // Units per metre (1000 is millimetres): wide bounds, so only a scale that makes every
    // depth infinite or zero is refused (a crop of a frame or far test scenes stay readable).
    if (!std::isfinite(c.depth_scale) || !(c.depth_scale >= 1e-12 && c.depth_scale <= 1e12))
        return "camera.depth_scale = " + num(c.depth_scale) +
               " is not a plausible number of depth units per metre (1000 = millimetres; 1e-12 to 1e12 accepted)";
    return "";
}

}  // namespace projsurf
