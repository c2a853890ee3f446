#include "projsurf/planning/plan_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <unordered_set>

#include "projsurf/planning/plan_raster.hpp"

namespace projsurf {
namespace {

/// Cells whose centre the camera does not see (outside its image, or behind it).
cv::Mat outOfView(const PlanSurface &s, const CameraIntrinsics &camera) {
    cv::Mat out(s.raster.rows, s.raster.cols, CV_8UC1);
    for (int r = 0; r < out.rows; ++r) {
        uchar *row = out.ptr<uchar>(r);
        for (int c = 0; c < out.cols; ++c) {
            const Eigen::Vector3d p = s.frame.toCamera(s.raster.toPlane({c + 0.5, r + 0.5}));
            bool in = p.z() > 0.05;
            if (in) {
                const Eigen::Vector2d px = camera.project(p);
                in = px.x() >= 0 && px.y() >= 0 && px.x() <= camera.width - 1 && px.y() <= camera.height - 1;
            }
            row[c] = in ? 0 : 255;
        }
    }
    return out;
}

/// The wall assumed beyond the view (CV_8U, 255): the out-of-view cells (`out`) reached within
/// `pad` cells from free cells seen up to the view's edge (within `edge` cells of `out`),
/// growing only through `out` and that edge band. A wall that ends in view (a corner, a door's
/// frame, a cupboard's side) is not continued past its end.
cv::Mat assumedBeyondView(const cv::Mat &free, const cv::Mat &out, int pad, int edge) {
    cv::Mat band, grown;
    cv::dilate(out, band, cv::getStructuringElement(cv::MORPH_RECT, {2 * edge + 1, 2 * edge + 1}));
    grown = free & band;
    // Cross and square steps in turn: an octagon about each seed, near enough a disc.
    const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, {3, 3});
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    for (int i = 0; i < pad; ++i) {
        cv::dilate(grown, grown, i % 2 ? square : cross);
        grown &= band;
    }
    return grown & out;
}

/// The seen surface on a raster `beyond` m larger each way, the wall assumed free out of view
/// within `beyond` of where it was seen up to the view's edge (`edge` m), and not below the floor.
PlanSurface extend(const SeenSurface &seen, const std::optional<CameraIntrinsics> &camera, const FloorOccupancy &floor,
                   double beyond, double edge) {
    PlanSurface s;
    s.plane = seen.plane;
    s.frame = seen.frame;
    const double cell = seen.raster.cell;
    const int pad = camera ? static_cast<int>(std::ceil(beyond / cell)) : 0;
    const Eigen::Vector2d lo(seen.raster.top_left.x() - pad * cell,
                             seen.raster.top_left.y() - (seen.raster.rows + pad) * cell);
    const Eigen::Vector2d hi(seen.raster.top_left.x() + (seen.raster.cols + pad) * cell,
                             seen.raster.top_left.y() + pad * cell);
    s.raster = planRaster(lo, hi, cell);
    s.free = cv::Mat::zeros(s.raster.rows, s.raster.cols, CV_8UC1);
    s.assumed = cv::Mat::zeros(s.raster.rows, s.raster.cols, CV_8UC1);
    const cv::Rect inner(pad, pad, std::min(seen.free.cols, s.raster.cols - pad),
                         std::min(seen.free.rows, s.raster.rows - pad));
    seen.free(cv::Rect(0, 0, inner.width, inner.height)).copyTo(s.free(inner));
    if (camera && pad > 0) {
        s.assumed = assumedBeyondView(s.free, outOfView(s, *camera), pad, static_cast<int>(std::ceil(edge / cell)));
        // Not below the floor (the wall's foot).
        if (floor.floorSeen())
            for (int r = 0; r < s.assumed.rows; ++r)
                for (int c = 0; c < s.assumed.cols; ++c)
                    if (floor.aboveFloor(s.frame.toCamera(s.raster.toPlane({c + 0.5, r + 0.5}))) < 0.0)
                        s.assumed.at<uchar>(r, c) = 0;
        s.free |= s.assumed;
    }
    cv::integral(s.free / 255, s.integral, CV_32S);
    cv::integral(s.assumed / 255, s.assumed_integral, CV_32S);
    return s;
}

/// Points in front of the surface (farther from it than its obstacle margin, towards the
/// camera) and above the floor, one per voxel.
void collectInFront(const Cloud &cloud, const SeenSurface &seen, const FloorOccupancy &floor,
                    const PlanSurfaceOptions &o, PlanSurface &s) {
    std::unordered_set<long long> voxels;
    const int step = cloud.organized() ? 2 : 1;
    auto key = [&](const Eigen::Vector3d &p) {
        auto q = [&](double v) { return static_cast<long long>(std::floor(std::clamp(v, -50.0, 50.0) / o.voxel)); };
        return (q(p.x()) + 2000) * 4000 * 4000 + (q(p.y()) + 2000) * 4000 + (q(p.z()) + 2000);
    };
    const int rows = cloud.organized() ? cloud.height : 1, cols = cloud.organized() ? cloud.width : static_cast<int>(cloud.points.size());
    for (int r = 0; r < rows; r += step)
        for (int c = 0; c < cols; c += step) {
            const Point &pf = cloud.points[static_cast<std::size_t>(r) * cols + c];
            if (!isFinite(pf)) continue;
            const Eigen::Vector3d p = pf.cast<double>();
            const double h = seen.plane.signedDistance(p) - seen.shape.height(seen.frame.toPlane(p));
            if (h <= seen.tolerance.margin(pf.z()) || floor.aboveFloor(p) < o.obstacle_height) continue;
            if (!voxels.insert(key(p)).second) continue;
            const Eigen::Vector3d centre = (Eigen::Vector3d(std::floor(p.x() / o.voxel), std::floor(p.y() / o.voxel),
                                                            std::floor(p.z() / o.voxel)) +
                                            Eigen::Vector3d::Constant(0.5)) *
                                           o.voxel;
            s.in_front.push_back({s.frame.toPlane(centre), s.plane.signedDistance(centre)});
        }
}

/// A surface with a parallel one seen behind it (furniture against a wall: a closet's front)
/// ends where it was seen; only the others are assumed to go on beyond the view.
bool standsBeforeAnother(const SeenSurface &s, const SeenSurfaces &all) {
    for (const SeenSurface &t : all.surfaces)
        if (&t != &s && std::abs(s.plane.normal.dot(t.plane.normal)) > std::cos(10.0 * 3.14159265358979 / 180.0) &&
            std::abs(t.plane.d) > std::abs(s.plane.d) + 0.1)
            return true;
    return false;
}

}  // namespace

std::vector<PlanSurface> planSurfaces(const Cloud &cloud, const SeenSurfaces &seen, const FloorOccupancy &floor,
                                      const PlanSurfaceOptions &options) {
    std::vector<PlanSurface> out;
    for (const SeenSurface &s : seen.surfaces) {
        // No picture where detection would refuse one: a face that stands free, a view through
        // an opening (seeVerticalSurfaces judges them as detect does).
        if (!s.usable() || s.free.empty() || cv::countNonZero(s.free) == 0) continue;
        PlanSurface p =
            extend(s, seen.camera, floor, standsBeforeAnother(s, seen) ? 0.0 : options.beyond_view, options.view_edge);
        p.voxel = options.voxel;
        collectInFront(cloud, s, floor, options, p);
        out.push_back(std::move(p));
    }
    return out;
}

namespace {

/// Cells counted by the integral image `I` of `s`'s raster in [c0, c1) x [r0, r1) (clipped).
int cellsIn(const PlanSurface &s, const cv::Mat &I, int c0, int r0, int c1, int r1) {
    c0 = std::clamp(c0, 0, s.raster.cols);
    c1 = std::clamp(c1, 0, s.raster.cols);
    r0 = std::clamp(r0, 0, s.raster.rows);
    r1 = std::clamp(r1, 0, s.raster.rows);
    if (c1 <= c0 || r1 <= r0 || I.empty()) return 0;
    return I.at<int>(r1, c1) - I.at<int>(r0, c1) - I.at<int>(r1, c0) + I.at<int>(r0, c0);
}

}  // namespace

int freeCells(const PlanSurface &s, int c0, int r0, int c1, int r1) { return cellsIn(s, s.integral, c0, r0, c1, r1); }

double assumedShare(const PlanSurface &s, const Rectangle &picture) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e18), hi = -lo;
    for (const auto &corner : picture.corners) {
        const Eigen::Vector2d cr = s.raster.toCell(s.frame.toPlane(corner));
        lo = lo.cwiseMin(cr);
        hi = hi.cwiseMax(cr);
    }
    // The cells whose centre (c + 0.5, r + 0.5) lies in the box.
    const int c0 = static_cast<int>(std::ceil(lo.x() - 0.5)), c1 = static_cast<int>(std::floor(hi.x() - 0.5)) + 1;
    const int r0 = static_cast<int>(std::ceil(lo.y() - 0.5)), r1 = static_cast<int>(std::floor(hi.y() - 0.5)) + 1;
    const int all = std::max(0, c1 - c0) * std::max(0, r1 - r0);
    if (all == 0) return 0.0;
    return static_cast<double>(cellsIn(s, s.assumed_integral, c0, r0, c1, r1)) / all;
}

}  // namespace projsurf
