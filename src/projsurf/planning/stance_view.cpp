#include "projsurf/planning/stance_view.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "projsurf/detection/projector_footprint.hpp"
#include "projsurf/detection/rectangle_search.hpp"

namespace projsurf {
namespace {

/// Cells of `mask` (on `sub`) in the shadow of the points in front of the surface, cast from
/// `emitter`: the point q at height h_q over the plane, seen from e at h_e, shadows the plane
/// at uv_e + k (uv_q - uv_e), k = h_e / (h_e - h_q), a voxel's shadow k times as large. Small
/// shadows (most: things near the wall) are marked at their centre in `small` and grown by
/// one disc of kSmall cells at the end; larger ones are drawn one by one.
void castShadows(const PlanSurface &s, const RasterFrame &sub, const Eigen::Vector3d &emitter, cv::Mat &mask,
                 cv::Mat &small) {
    constexpr int kSmall = 3;  ///< cells
    const double he = s.plane.signedDistance(emitter);
    const Eigen::Vector2d ue = s.frame.toPlane(emitter);
    const double cols = mask.cols, rows = mask.rows;
    small.create(mask.rows + 2 * kSmall, mask.cols + 2 * kSmall, CV_8UC1);
    small.setTo(0);
    for (const PlanSurface::InFront &q : s.in_front) {
        if (q.h >= he - 0.5 * s.voxel || q.h <= 0.0) continue;  // behind the emitter (or at it): no shadow
        const double k = he / (he - q.h);
        const Eigen::Vector2d cell = sub.toCell(ue + k * (q.uv - ue));
        const double radius = 0.75 * k * s.voxel / sub.cell + 0.5;
        if (cell.x() + radius < 0 || cell.y() + radius < 0 || cell.x() - radius >= cols || cell.y() - radius >= rows)
            continue;
        if (radius <= kSmall) {
            small.at<uchar>(static_cast<int>(cell.y() + kSmall), static_cast<int>(cell.x() + kSmall)) = 255;
            continue;
        }
        const int c0 = std::max(0, static_cast<int>(cell.x() - radius)),
                  c1 = std::min(mask.cols - 1, static_cast<int>(cell.x() + radius));
        const int r0 = std::max(0, static_cast<int>(cell.y() - radius)),
                  r1 = std::min(mask.rows - 1, static_cast<int>(cell.y() + radius));
        for (int r = r0; r <= r1; ++r) {
            uchar *row = mask.ptr<uchar>(r);
            const double dy = r + 0.5 - cell.y();
            for (int c = c0; c <= c1; ++c) {
                const double dx = c + 0.5 - cell.x();
                if (dx * dx + dy * dy <= radius * radius) row[c] = 0;
            }
        }
    }
    cv::dilate(small, small, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * kSmall + 1, 2 * kSmall + 1}));
    mask.setTo(0, small(cv::Rect(kSmall, kSmall, mask.cols, mask.rows)));
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
    out.cells =
        cv::Rect(c0, r0, std::max(0, c1 - c0), std::max(0, r1 - r0)) & cv::Rect(0, 0, s.raster.cols, s.raster.rows);
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

std::optional<Rectangle> pictureFromStance(const PlanSurface &s, const Projector &projector, const StanceFootprint &fp,
                                           const Stance &stance, const StanceLimits &limits, cv::Mat &mask,
                                           double min_area, double min_width) {
    RasterFrame sub = s.raster;
    sub.top_left = s.raster.toPlane({double(fp.cells.x), double(fp.cells.y)});
    sub.cols = fp.cells.width;
    sub.rows = fp.cells.height;
    mask.create(sub.rows, sub.cols, CV_8UC1);
    mask.setTo(0);
    fillPolygon(mask, sub, insetConvexPolygon({fp.uv.begin(), fp.uv.end()}, 0.7072 * sub.cell), 255);
    mask &= s.free(fp.cells);
    // Within range of the moved camera (the cells' centres, half a diagonal in): the camera's
    // foot on the plane at cell (fc, fr), its height hc over it.
    const double reach = limits.max_distance - 0.7072 * sub.cell;
    const Eigen::Vector2d foot = sub.toCell(s.frame.toPlane(stance.translation));
    const double hc = s.plane.signedDistance(stance.translation);
    const double left = (reach * reach - hc * hc) / (sub.cell * sub.cell);  // cells^2 along the plane
    for (int r = 0; r < mask.rows; ++r) {
        uchar *row = mask.ptr<uchar>(r);
        const double dy = r + 0.5 - foot.y();
        for (int c = 0; c < mask.cols; ++c) {
            const double dx = c + 0.5 - foot.x();
            if (dx * dx + dy * dy > left) row[c] = 0;
        }
    }
    const Eigen::Vector2d centre = quadCentre(fp.uv);
    const auto unshadowed = largestFreeRectangle(mask, sub, s.frame, limits.aspect, centre);
    if (!unshadowed || unshadowed->area() < min_area || unshadowed->width + 1e-9 < min_width) return std::nullopt;
    thread_local cv::Mat small;
    castShadows(s, sub, stance.rotation * projector.origin + stance.translation, mask, small);
    castShadows(s, sub, stance.translation, mask, small);
    return largestFreeRectangle(mask, sub, s.frame, limits.aspect, centre);
}

}  // namespace projsurf
