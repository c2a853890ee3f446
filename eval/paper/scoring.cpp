#include "eval/paper/scoring.hpp"

#include <cmath>
#include <limits>

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

/// Share of sample points of the rectangle that fall on free cells of the surface's mask.
double freeShare(const Rectangle &r, const SurfaceTruth &s) {
    const int n = 24;
    int free = 0, total = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double a = (i + 0.5) / n, b = (j + 0.5) / n;
            const Eigen::Vector3d top = r.corners[0] + a * (r.corners[1] - r.corners[0]);
            const Eigen::Vector3d p = top + b * (r.corners[3] - r.corners[0]);
            const Eigen::Vector2d uv = s.frame.toPlane(p);
            const int col = static_cast<int>(std::floor((uv.x() - s.grid_origin.x()) / s.cell));
            const int row = static_cast<int>(std::floor((s.grid_origin.y() - uv.y()) / s.cell));
            ++total;
            if (row >= 0 && col >= 0 && row < s.free_mask.rows && col < s.free_mask.cols &&
                s.free_mask.at<uchar>(row, col) != 0)
                ++free;
        }
    return static_cast<double>(free) / total;
}

}  // namespace

Score scoreDetection(const Detection &det, const GroundTruth &truth, const Projector &projector,
                     const Eigen::Vector3d &gravity, double aspect, const ScoreOptions &opt) {
    Score s;
    s.best_area = truth.found ? truth.best.rectangle.area() : 0.0;
    s.found = det.found;
    if (!det.found) {
        s.area_error = s.best_area;
        s.success = !truth.found;  // correctly found nothing
        s.why = truth.found ? "not found: " + det.reason : "";
        return s;
    }
    const Rectangle &r = det.rectangle;
    s.area = r.area();
    s.area_error = s.best_area - s.area;
    // The true surface the rectangle is on: the one whose plane is nearest its corners.
    const SurfaceTruth *on = nullptr;
    s.plane_error = std::numeric_limits<double>::infinity();
    for (const auto &surface : truth.surfaces) {
        double worst = 0.0;
        for (const auto &c : r.corners) worst = std::max(worst, std::abs(surface.plane.signedDistance(c)));
        if (worst < s.plane_error) {
            s.plane_error = worst;
            on = &surface;
        }
    }
    if (!on || s.plane_error > opt.plane_tolerance) {
        s.why = "not on a projection surface";
        return s;
    }
    const Eigen::Vector3d left = (r.corners[0] - r.corners[3]).normalized();
    if (std::acos(std::min(1.0, left.dot(-gravity.normalized()))) > opt.upright_tolerance) {
        s.why = "not upright";
        return s;
    }
    if (std::abs(r.width / r.height - aspect) > 0.01 * aspect) {
        s.why = "wrong aspect ratio";
        return s;
    }
    for (const auto &c : r.corners) {
        const auto px = projector.toPixel(c);
        const double t = opt.pixel_tolerance;
        if (!px || px->x() < -0.5 - t || px->y() < -0.5 - t || px->x() > projector.width - 0.5 + t ||
            px->y() > projector.height - 0.5 + t) {
            s.why = "outside the projector framebuffer";
            return s;
        }
    }
    s.free_share = freeShare(r, *on);
    if (s.free_share < opt.min_free_share) {
        s.why = "covers space that is not free";
        return s;
    }
    s.valid = true;
    s.success = s.area >= s.best_area - opt.area_tolerance;
    if (!s.success) s.why = "valid but smaller than the best by more than the tolerance";
    return s;
}

}  // namespace projsurf::eval
