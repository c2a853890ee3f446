#include "projsurf/planning/stance_view.hpp"

#include <algorithm>
#include <cmath>

#include "projsurf/detection/projector_footprint.hpp"
#include "projsurf/detection/rectangle_search.hpp"

namespace projsurf {
namespace {

/// Cells of `mask` (on `sub`) in the shadow of the points in front of the surface, cast from `emitter`.
void castShadows(const PlanSurface &s, const RasterFrame &sub, const Eigen::Vector3d &emitter, double voxel,
                 cv::Mat &mask) {
    const double he = s.plane.signedDistance(emitter);
    for (const Eigen::Vector3d &q : s.in_front) {
        const double hq = s.plane.signedDistance(q);
        if (hq >= he - 0.5 * voxel || hq <= 0.0) continue;  // behind the emitter (or at it): no shadow
        const double k = he / (he - hq);
        const Eigen::Vector2d cell = sub.toCell(s.frame.toPlane(emitter + k * (q - emitter)));
        const double radius = 0.75 * k * voxel / sub.cell + 0.5;
        const int c0 = static_cast<int>(std::floor(cell.x() - radius)), c1 = static_cast<int>(std::ceil(cell.x() + radius));
        const int r0 = static_cast<int>(std::floor(cell.y() - radius)), r1 = static_cast<int>(std::ceil(cell.y() + radius));
        if (c1 < 0 || r1 < 0 || c0 >= mask.cols || r0 >= mask.rows) continue;
        for (int r = std::max(0, r0); r <= std::min(mask.rows - 1, r1); ++r) {
            uchar *row = mask.ptr<uchar>(r);
            for (int c = std::max(0, c0); c <= std::min(mask.cols - 1, c1); ++c) {
                const double dx = c + 0.5 - cell.x(), dy = r + 0.5 - cell.y();
                if (dx * dx + dy * dy <= radius * radius) row[c] = 0;
            }
        }
    }
}

double shoelace(const std::array<Eigen::Vector2d, 4> &q) {
    double a = 0.0;
    for (int i = 0; i < 4; ++i) a += q[i].x() * q[(i + 1) % 4].y() - q[(i + 1) % 4].x() * q[i].y();
    return 0.5 * std::abs(a);
}

}  // namespace

Stance makeStance(const LevelledFrame &frame, double forward, double left, double turn) {
    Stance s;
    s.forward = forward;
    s.left = left;
    s.turn = turn;
    s.rotation = turnAboutUp(frame, turn);
    s.translation = forward * frame.forward + left * frame.left;
    return s;
}

std::optional<StanceFootprint> stanceFootprint(const PlanSurface &s, const Projector &projector,
                                               const std::array<Eigen::Vector3d, 4> &rays, const Stance &stance,
                                               const StanceLimits &limits) {
    const Eigen::Vector3d origin = stance.rotation * projector.origin + stance.translation;
    if (s.plane.signedDistance(origin) < limits.robot_radius) return std::nullopt;
    std::array<Eigen::Vector3d, 4> moved;
    for (int i = 0; i < 4; ++i) moved[i] = stance.rotation * rays[i];
    const auto fp = footprintOnPlane(s.plane, s.frame, origin, moved);
    if (!fp) return std::nullopt;
    StanceFootprint out;
    out.uv = fp->uv;
    Eigen::Vector2d lo = out.uv[0], hi = out.uv[0];
    for (const auto &w : out.uv) {
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
    }
    const Eigen::Vector2d a = s.raster.toCell({lo.x(), hi.y()}), b = s.raster.toCell({hi.x(), lo.y()});
    const double big = 1e6;
    const int c0 = static_cast<int>(std::floor(std::clamp(a.x(), -big, big))),
              r0 = static_cast<int>(std::floor(std::clamp(a.y(), -big, big)));
    const int c1 = static_cast<int>(std::ceil(std::clamp(b.x(), -big, big))),
              r1 = static_cast<int>(std::ceil(std::clamp(b.y(), -big, big)));
    out.cells = cv::Rect(c0, r0, std::max(0, c1 - c0), std::max(0, r1 - r0)) & cv::Rect(0, 0, s.raster.cols, s.raster.rows);
    if (out.cells.area() <= 0) return std::nullopt;
    // Bounds: the box, the footprint's area, the free cells in the box, the range disc.
    const double cell = s.raster.cell, aspect = limits.aspect;
    const double box_w = out.cells.width * cell, box_h = out.cells.height * cell;
    const double h = std::min(box_h, box_w / aspect);
    const double free = cell * cell * freeCells(s, out.cells.x, out.cells.y, out.cells.br().x, out.cells.br().y);
    const double hc = s.plane.signedDistance(stance.translation);
    const double rho2 = std::max(0.0, limits.max_distance * limits.max_distance - hc * hc);
    const double disc = 4.0 * aspect * rho2 / (aspect * aspect + 1.0);
    out.bound_area = std::min({aspect * h * h, shoelace(out.uv), free, disc});
    out.bound_width = std::sqrt(out.bound_area * aspect);
    return out;
}

std::optional<Rectangle> pictureFromStance(const PlanSurface &s, const Projector &projector,
                                           const StanceFootprint &fp, const Stance &stance,
                                           const StanceLimits &limits, cv::Mat &mask) {
    RasterFrame sub = s.raster;
    sub.top_left = s.raster.toPlane({double(fp.cells.x), double(fp.cells.y)});
    sub.cols = fp.cells.width;
    sub.rows = fp.cells.height;
    mask.create(sub.rows, sub.cols, CV_8UC1);
    mask.setTo(0);
    fillPolygon(mask, sub, insetConvexPolygon({fp.uv.begin(), fp.uv.end()}, 0.7072 * sub.cell), 255);
    mask &= s.free(fp.cells);
    // Within range of the moved camera (the cells' centres, half a diagonal in).
    const double reach = limits.max_distance - 0.7072 * sub.cell;
    for (int r = 0; r < mask.rows; ++r) {
        uchar *row = mask.ptr<uchar>(r);
        for (int c = 0; c < mask.cols; ++c)
            if (row[c] && (s.frame.toCamera(sub.toPlane({c + 0.5, r + 0.5})) - stance.translation).squaredNorm() >
                              reach * reach)
                row[c] = 0;
    }
    castShadows(s, sub, stance.rotation * projector.origin + stance.translation, s.voxel, mask);
    castShadows(s, sub, stance.translation, s.voxel, mask);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto &w : fp.uv) centre += 0.25 * w;
    return largestFreeRectangle(mask, sub, s.frame, limits.aspect, centre);
}

}  // namespace projsurf
