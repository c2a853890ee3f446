#include "projsurf/pipeline/detector.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <opencv2/imgproc.hpp>
#include <random>

#include "projsurf/core/camera.hpp"
#include "projsurf/core/euler_rodrigues.hpp"
#include "projsurf/core/hull.hpp"
#include "projsurf/core/plane_observation.hpp"
#include "projsurf/core/point_grid.hpp"
#include "projsurf/core/raster.hpp"
#include "projsurf/core/rectangle_search.hpp"
#include "projsurf/core/vertical_ransac.hpp"
#include "projsurf/core/voxel_grid.hpp"

namespace projsurf {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

/// Working buffers kept by a SurfaceDetector from one frame to the next.
struct DetectorScratch {
    PointGrid grid;
    std::vector<PlaneObservation> observations;  ///< one per candidate plane
};

namespace {

/// A vertical plane under consideration and what was found on it.
struct Candidate {
    Plane plane;
    int inliers = 0;
    PlaneFrame frame;
    std::array<Eigen::Vector3d, 4> workspace{};
    std::array<Eigen::Vector2d, 4> workspace_uv{};
    RasterFrame raster;
    cv::Mat free;     // 255 = free (whole cells inside the footprint)
    cv::Mat surface;  // 255 = observed free surface, footprint not applied (default mode)
    Rectangle rectangle;
    std::vector<std::vector<Eigen::Vector3d>> outlines;
    std::vector<int> inlier_indices;
    cv::Rect image_box;  // organized clouds: the pixels the free-space pass looks at (empty = all)
    PlaneObservation *observed = nullptr;  // default mode: what the camera saw of the plane, per raster cell
};

/// Pixels of an organized cloud where the candidate's sampled inliers lie, grown by `margin`.
cv::Rect inlierImageBox(const Cloud &cloud, const std::vector<int> &indices, int margin) {
    if (!cloud.organized() || indices.empty()) return {};
    int u0 = cloud.width, v0 = cloud.height, u1 = -1, v1 = -1;
    for (int i : indices) {
        const int u = i % cloud.width, v = i / cloud.width;
        u0 = std::min(u0, u);
        v0 = std::min(v0, v);
        u1 = std::max(u1, u);
        v1 = std::max(v1, v);
    }
    return cv::Rect(u0 - margin, v0 - margin, u1 - u0 + 1 + 2 * margin, v1 - v0 + 1 + 2 * margin) &
           cv::Rect(0, 0, cloud.width, cloud.height);
}

/// Pixels where the camera sees all of `points`, grown by `margin` and clipped to the image;
/// empty (all pixels) when one of them is not in front of the camera.
cv::Rect pixelBox(const CameraIntrinsics &camera, const std::vector<Eigen::Vector3d> &points, int margin) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e6), hi = Eigen::Vector2d::Constant(-1e6);
    for (const Eigen::Vector3d &p : points) {
        if (p.z() < 1e-3) return {};
        const Eigen::Vector2d px = camera.project(p);
        lo = lo.cwiseMin(px);
        hi = hi.cwiseMax(px);
    }
    lo = lo.cwiseMax(-1e6);
    hi = hi.cwiseMin(1e6);
    const cv::Rect pixels(
        cv::Point(static_cast<int>(std::floor(lo.x())) - margin, static_cast<int>(std::floor(lo.y())) - margin),
        cv::Point(static_cast<int>(std::ceil(hi.x())) + margin + 1, static_cast<int>(std::ceil(hi.y())) + margin + 1));
    return pixels & cv::Rect(0, 0, camera.width, camera.height);
}

/// Pixels where everything that matters to the candidate's raster is seen: the raster itself
/// (wall points, and points seen through holes in it) and the projector's beam between the
/// lens and the raster from depth `near` on (whatever shadows it), grown by `margin`.
cv::Rect rasterImageBox(const CameraIntrinsics &camera, const Candidate &c, const Eigen::Vector3d &lens, double near,
                        int margin) {
    const RasterFrame &r = c.raster;
    std::vector<Eigen::Vector3d> volume;
    for (const Eigen::Vector2d &corner : {r.toPlane({0, 0}), r.toPlane({r.cols, 0}), r.toPlane({r.cols, r.rows}),
                                         r.toPlane({0, r.rows})}) {
        const Eigen::Vector3d x = c.frame.toCamera(corner);
        // Where the beam towards this corner is at depth `near` (or the lens, if nearer).
        const double s = x.z() - lens.z() > 1e-9 ? std::clamp((near - lens.z()) / (x.z() - lens.z()), 0.0, 1.0) : 0.0;
        volume.push_back(x);
        volume.push_back(lens + s * (x - lens));
    }
    return pixelBox(camera, volume, margin);
}

/// The projector workspace on the plane: the corner rays meet it (paper eqs. 5-6).
bool workspaceOnPlane(const Eigen::Vector3d &origin, const std::array<Eigen::Vector3d, 4> &rays, Candidate &c) {
    for (int i = 0; i < 4; ++i) {
        const auto hit = intersectRay(c.plane, origin, rays[i]);
        if (!hit) return false;
        c.workspace[i] = *hit;
        c.workspace_uv[i] = c.frame.toPlane(*hit);
    }
    return true;
}

/// The largest free rectangle of the aspect ratio in the candidate's raster, centred in the
/// cells it occupies; false when none fits.
bool placeRectangle(Candidate &c, double aspect) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto &w : c.workspace_uv) centre += 0.25 * w;
    const auto rect = largestAspectRect(c.free, aspect, c.raster.toCell(centre));
    if (!rect) return false;
    const double h = rect->rows * c.raster.cell, w = aspect * h;
    const double u_mid = c.raster.top_left.x() + (rect->col + 0.5 * rect->cols) * c.raster.cell;
    const double v_top = c.raster.top_left.y() - rect->row * c.raster.cell;
    c.rectangle = makeRectangle(c.frame, {u_mid - 0.5 * w, v_top - h}, {u_mid + 0.5 * w, v_top});
    return true;
}

Rectangle shrink(const PlaneFrame &f, const Rectangle &r, double margin) {
    const Eigen::Vector2d lo = f.toPlane(r.corners[3]), hi = f.toPlane(r.corners[1]);
    const Eigen::Vector2d m = Eigen::Vector2d::Constant(std::min(margin, 0.25 * std::min(r.width, r.height)));
    return makeRectangle(f, lo + m, hi - m);
}

std::vector<Eigen::Vector3d> toCamera(const PlaneFrame &f, const std::vector<Eigen::Vector2d> &uv) {
    std::vector<Eigen::Vector3d> out;
    for (const auto &p : uv) out.push_back(f.toCamera(p));
    return out;
}

void fillDebug(const Candidate &c, DetectionDebug &debug) {
    debug.frame = c.frame;
    debug.workspace = c.workspace;
    debug.has_workspace = true;
    debug.hull = c.outlines;
    debug.free_space = c.free;
    debug.grid_origin = c.raster.top_left;
    debug.grid_cell = c.raster.cell;
    debug.inliers = c.inlier_indices;
}

Eigen::Vector3d centroid(const std::vector<Point> &pts, const std::vector<int> &idx) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int i : idx) s += pts[i].cast<double>();
    return s / std::max<std::size_t>(1, idx.size());
}

// ---------------------------------------------------------------------------------------
// Paper mode: section 3.2, step by step.
Detection detectPaper(const Cloud &cloud, const Projector &projector, const DetectorConfig &cfg, double aspect) {
    Detection det;
    const auto t0 = Clock::now();
    auto t = Clock::now();
    const std::vector<Point> voxels = voxelDownsample(cloud.points, cfg.voxel_leaf);
    det.timing_ms["voxel_grid"] = msSince(t);
    if (voxels.size() < 3) {
        det.reason = "no points to search (empty or all-NaN cloud)";
        det.timing_ms["total"] = msSince(t0);
        return det;
    }
    t = Clock::now();
    std::vector<int> active(voxels.size());
    for (std::size_t i = 0; i < voxels.size(); ++i) active[i] = static_cast<int>(i);
    const std::vector<float> band(voxels.size(), static_cast<float>(cfg.ransac_distance));
    RansacOptions opt;
    opt.max_tilt = cfg.max_tilt;
    opt.max_iterations = cfg.ransac_iterations;
    std::mt19937 rng(cfg.seed);
    const auto found = findVerticalPlane(voxels, active, band, cfg.gravity, opt, rng);
    det.timing_ms["plane"] = msSince(t);
    if (!found || found->inliers.size() < 3) {
        det.reason = "no vertical plane in view";
        det.timing_ms["total"] = msSince(t0);
        return det;
    }
    Candidate c;
    c.plane = found->plane;  // the paper keeps RANSAC's model as it is
    c.inliers = static_cast<int>(found->inliers.size());
    c.frame = makePlaneFrame(c.plane, cfg.gravity, centroid(voxels, found->inliers));
    det.plane = c.plane;
    det.inliers = c.inliers;
    det.orientation_deg = orientationDeg(c.plane);

    t = Clock::now();
    std::vector<Eigen::Vector2d> uv;
    for (int i : found->inliers) uv.push_back(c.frame.toPlane(voxels[i].cast<double>()));
    std::vector<Segment2> hull_edges;
    if (cfg.hull == HullKind::Convex) {
        const auto hull = convexHull(uv);
        hull_edges = polygonEdges(hull);
        c.outlines.push_back(toCamera(c.frame, hull));
    } else {
        hull_edges = concaveHullEdges(uv, cfg.concave_alpha);
        for (const auto &e : hull_edges) c.outlines.push_back({c.frame.toCamera(e[0]), c.frame.toCamera(e[1])});
    }
    det.timing_ms["hull"] = msSince(t);

    t = Clock::now();
    const auto rays = paperCornerRays(projector.direction, projector.fov_h, projector.fov_v);
    if (!workspaceOnPlane(projector.origin, rays, c)) {
        det.reason = "the projector workspace does not reach the plane";
        det.timing_ms["total"] = msSince(t0);
        return det;
    }
    Eigen::Vector2d lo = c.workspace_uv[0], hi = c.workspace_uv[0];
    for (const auto &p : uv) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    for (const auto &p : c.workspace_uv) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    c.raster = makeRasterFrame(lo, hi, cfg.paper_cell);
    const cv::Mat m1 = outlineMask(c.raster, hull_edges);
    const cv::Mat m2 = outlineMask(c.raster, polygonEdges({c.workspace_uv.begin(), c.workspace_uv.end()}));
    c.free = (m1 + m2) == 0;  // M3: cells at 0 in the sum are projectable
    det.timing_ms["free_space"] = msSince(t);

    t = Clock::now();
    const bool placed = placeRectangle(c, aspect);
    det.timing_ms["rectangle"] = msSince(t);
    fillDebug(c, det.debug);
    det.debug.candidates = {c.plane};
    if (!placed) {
        det.reason = "no free area on the plane for the picture";
        det.timing_ms["total"] = msSince(t0);
        return det;
    }
    det.rectangle = c.rectangle;

    t = Clock::now();
    det.surface_check = checkSurfacePaper(cloud, c.frame, c.rectangle, cfg.outlier_distance, cfg.max_outliers);
    det.timing_ms["surface_check"] = msSince(t);
    det.debug.outliers = det.surface_check.outlier_indices;
    det.found = det.surface_check.accepted;
    if (!det.found)
        det.reason = "surface check rejected the area: " + std::to_string(det.surface_check.outliers) +
                     " outliers > " + std::to_string(cfg.max_outliers);
    det.timing_ms["total"] = msSince(t0);
    return det;
}

// ---------------------------------------------------------------------------------------
// Default mode.
/// Sampled point indices: a pixel grid on organized clouds, every k-th point otherwise.
std::vector<int> samplePoints(const Cloud &cloud, int target) {
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(target) * 5 / 4);
    const int n = static_cast<int>(cloud.points.size());
    if (cloud.organized()) {
        const int s = std::max(1, static_cast<int>(std::round(std::sqrt(static_cast<double>(n) / target))));
        for (int v = s / 2; v < cloud.height; v += s)
            for (int u = s / 2; u < cloud.width; u += s) {
                const int i = v * cloud.width + u;
                if (isFinite(cloud.points[i])) out.push_back(i);
            }
    } else {
        const int finite = static_cast<int>(countFinite(cloud));
        const int k = std::max(1, finite / std::max(1, target));
        int seen = 0;
        for (int i = 0; i < n; ++i)
            if (isFinite(cloud.points[i]) && seen++ % k == 0) out.push_back(i);
    }
    return out;
}

/// Typical distance (m) between neighbouring points of the pass with this pixel step on the
/// candidate's plane: the size of the gaps the support raster must close.
double sampleSpacing(const Cloud &cloud, const Candidate &c, int step, const DepthTolerance &tol, int support_points) {
    std::vector<float> d;
    const Eigen::Vector3f n = c.plane.normal.cast<float>();
    const float pd = static_cast<float>(c.plane.d);
    auto onPlane = [&](const Point &p) { return isFinite(p) && std::abs(n.dot(p) + pd) <= tol.band(p.z()); };
    if (cloud.organized()) {
        // Every 4th inlier is plenty for a median (and each one reads cloud memory at random).
        for (std::size_t k = 0; k < c.inlier_indices.size(); k += 4) {
            const int i = c.inlier_indices[k];
            const int u = i % cloud.width, v = i / cloud.width;
            if (u + step < cloud.width && onPlane(cloud.points[i + step]))
                d.push_back((cloud.points[i + step] - cloud.points[i]).norm());
            if (v + step < cloud.height && onPlane(cloud.points[i + step * cloud.width]))
                d.push_back((cloud.points[i + step * cloud.width] - cloud.points[i]).norm());
        }
    }
    if (d.size() < 10) {
        // Unorganized: the area the wall points spread over, shared among them.
        Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e9), hi = Eigen::Vector2d::Constant(-1e9);
        for (int i : c.inlier_indices) {
            const Eigen::Vector2d uv = c.frame.toPlane(cloud.points[i].cast<double>());
            lo = lo.cwiseMin(uv);
            hi = hi.cwiseMax(uv);
        }
        const double area = std::max(0.0, (hi - lo).prod());
        return std::sqrt(area / std::max(1, support_points));
    }
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    return d[d.size() / 2];
}

/// Free space of one candidate from where its plane was observed: a cell is free when
/// wall points were seen in it, nothing was seen through it, and no point in front of the
/// wall shadows it from the projector.
void observedFreeSpace(const Cloud &cloud, const PointGrid &grid, const Projector &projector, const DetectorConfig &cfg,
                       Candidate &c) {
    const cv::Size size(c.raster.cols, c.raster.rows);
    const DepthTolerance tol = cfg.tolerance();
    // Organized clouds: only the pixels where this plane is seen (holes in it and things in
    // front of it are seen there too); unorganized: every point.
    observePlane(grid, grid.gridBox(c.image_box), c.plane, c.frame, c.raster, projector.origin, tol, *c.observed);
    const cv::Mat &support = c.observed->support, &behind = c.observed->behind, &shadow = c.observed->shadow;
    const int step = grid.step, support_points = c.observed->support_points;
    // Support: cells with wall points, the gaps between neighbouring samples closed.
    const int gap = std::clamp(static_cast<int>(std::ceil(sampleSpacing(cloud, c, step, tol, support_points) / c.raster.cell)), 1, 8);
    cv::Mat supported = support > 0;
    cv::morphologyEx(supported, supported, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, {2 * gap + 1, 2 * gap + 1}));
    // Blocked: seen through more than seen on, or shadowed; isolated single cells are noise.
    cv::Mat blocked = (behind > support) | (shadow > 0);
    cv::Mat neighbours;
    cv::boxFilter(blocked / 255, neighbours, CV_16U, {3, 3}, {-1, -1}, false, cv::BORDER_CONSTANT);
    blocked &= neighbours >= 2;
    cv::Mat footprint = cv::Mat::zeros(size, CV_8UC1);
    // Whole cells inside the footprint: its edges moved in by half a cell diagonal.
    fillPolygon(footprint, c.raster, insetConvexPolygon({c.workspace_uv.begin(), c.workspace_uv.end()}, 0.7072 * c.raster.cell),
                255);
    // A cell with a wall point may reach up to a cell past the wall's true edge: trim one
    // cell off every edge of the observed surface so the picture never hangs over it.
    c.surface = supported & ~blocked;
    cv::erode(c.surface, c.surface, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}), {-1, -1}, 1,
              cv::BORDER_CONSTANT, 0);
    c.free = c.surface & footprint;
}

bool insideConvex(const std::array<Eigen::Vector2d, 4> &quad, const Eigen::Vector2d &p) {
    int sign = 0;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d e = quad[(i + 1) % 4] - quad[i], q = p - quad[i];
        const double cr = e.x() * q.y() - e.y() * q.x();
        const int s = cr > 1e-12 ? 1 : (cr < -1e-12 ? -1 : 0);
        if (s != 0 && sign != 0 && s != sign) return false;
        if (s != 0) sign = s;
    }
    return true;
}

/// Grows the grid rectangle about its centre, continuously, while its corners stay inside
/// the exact footprint and every cell it touches is observed free surface: recovers the
/// quantisation of the grid search (the footprint is known exactly).
void refineRectangle(Candidate &c, double aspect) {
    const Eigen::Vector2d lo = c.frame.toPlane(c.rectangle.corners[3]), hi = c.frame.toPlane(c.rectangle.corners[1]);
    const double cell = c.raster.cell;
    auto fits = [&](const Eigen::Vector2d &mid, double h) {
        const Eigen::Vector2d half(0.5 * aspect * h, 0.5 * h);
        const Eigen::Vector2d a = mid - half, b = mid + half;
        for (const Eigen::Vector2d &p : {a, b, Eigen::Vector2d(a.x(), b.y()), Eigen::Vector2d(b.x(), a.y())})
            if (!insideConvex(c.workspace_uv, p)) return false;
        const int c0 = static_cast<int>(std::floor((a.x() - c.raster.top_left.x()) / cell));
        const int c1 = static_cast<int>(std::floor((b.x() - c.raster.top_left.x()) / cell - 1e-9));
        const int r0 = static_cast<int>(std::floor((c.raster.top_left.y() - b.y()) / cell));
        const int r1 = static_cast<int>(std::floor((c.raster.top_left.y() - a.y()) / cell - 1e-9));
        if (c0 < 0 || r0 < 0 || c1 >= c.surface.cols || r1 >= c.surface.rows) return false;
        for (int r = r0; r <= r1; ++r) {
            const uchar *row = c.surface.ptr<uchar>(r);
            for (int k = c0; k <= c1; ++k)
                if (!row[k]) return false;
        }
        return true;
    };
    // Largest height that fits about `mid`, searched in [h0, h0 + 2 cells].
    auto grow = [&](const Eigen::Vector2d &mid, double h0) {
        double good = h0, bad = h0 + 2.0 * cell;
        if (fits(mid, bad)) return bad;
        for (int it = 0; it < 10; ++it) {
            const double h = 0.5 * (good + bad);
            (fits(mid, h) ? good : bad) = h;
        }
        return good;
    };
    Eigen::Vector2d mid = 0.5 * (lo + hi);
    double h = grow(mid, hi.y() - lo.y());
    // Slide away from whatever limits it, half a cell at a time, while that lets it grow.
    for (int round = 0; round < 8; ++round) {
        bool improved = false;
        for (const Eigen::Vector2d &dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
            const Eigen::Vector2d moved = mid + 0.5 * cell * dir;
            if (!fits(moved, h)) continue;
            const double grown = grow(moved, h);
            if (grown > h + 1e-4) {
                mid = moved;
                h = grown;
                improved = true;
            }
        }
        if (!improved) break;
    }
    const Eigen::Vector2d half(0.5 * aspect * h, 0.5 * h);
    c.rectangle = makeRectangle(c.frame, mid - half, mid + half);
}

Detection detectDefault(const Cloud &cloud, const Projector &projector, const DetectorConfig &cfg, double aspect,
                        DetectorScratch &scratch) {
    Detection det;
    const auto t0 = Clock::now();
    auto t = Clock::now();
    const DepthTolerance tol = cfg.tolerance();
    const std::vector<int> sample = samplePoints(cloud, cfg.target_samples);
    std::vector<Point> pts(sample.size());
    std::vector<float> band(sample.size());
    for (std::size_t i = 0; i < sample.size(); ++i) {
        pts[i] = cloud.points[sample[i]];
        band[i] = tol.band(pts[i].z());
    }
    // Organized clouds are pinhole images: their intrinsics tell where a volume is seen.
    // (Every 8th sampled point is plenty for four parameters.)
    std::vector<int> probe;
    for (std::size_t i = 0; i < sample.size(); i += 8) probe.push_back(sample[i]);
    const std::optional<CameraIntrinsics> camera = fitIntrinsics(cloud, probe);
    float near = std::numeric_limits<float>::infinity();  // m, the nearest sampled point
    for (const Point &p : pts) near = std::min(near, p.z());
    det.timing_ms["sample"] = msSince(t);
    if (pts.size() < 3) {
        det.reason = "no points to search (empty or all-NaN cloud)";
        det.timing_ms["total"] = msSince(t0);
        return det;
    }

    // Every vertical plane, biggest first (sequential RANSAC + least-squares refinement).
    t = Clock::now();
    std::vector<int> active(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) active[i] = static_cast<int>(i);
    RansacOptions opt;
    opt.max_tilt = cfg.max_tilt;
    opt.max_iterations = 300;
    opt.score_subset = 1500;
    opt.max_sample_span = 1.5;
    std::mt19937 rng(cfg.seed);
    std::vector<Candidate> candidates;
    const int min_points = std::min<int>(cfg.min_plane_points, static_cast<int>(pts.size()) / 20 + 3);
    std::vector<std::vector<int>> members;  // sampled inliers of each candidate
    auto refine = [&](Plane plane, std::vector<int> &inliers, const std::vector<int> &pool) {
        for (int round = 0; round < 2; ++round) {
            const auto refined = fitPlane(pts, inliers);
            if (!refined || tiltFromVertical(*refined, cfg.gravity) > cfg.max_tilt) break;
            plane = *refined;
            inliers = planeInliers(pts, pool, band, plane);
        }
        return plane;
    };
    for (int attempt = 0; attempt < 2 * cfg.max_planes && static_cast<int>(candidates.size()) < cfg.max_planes &&
                          static_cast<int>(active.size()) >= min_points;
         ++attempt) {
        const auto found = findVerticalPlane(pts, active, band, cfg.gravity, opt, rng);
        if (!found || static_cast<int>(found->inliers.size()) < min_points) break;
        std::vector<int> inliers = found->inliers;
        const Plane plane = refine(found->plane, inliers, active);
        std::vector<char> taken(pts.size(), 0);
        for (int i : inliers) taken[i] = 1;
        active.erase(std::remove_if(active.begin(), active.end(), [&](int i) { return taken[i]; }), active.end());
        // A second slice of a plane already found (depth quantisation ribs, lens distortion of
        // the depth camera) joins it instead of counting as a surface of its own.
        const float z = static_cast<float>(centroid(pts, inliers).z());
        int same = -1;
        for (int k = 0; k < static_cast<int>(candidates.size()); ++k)
            if (std::abs(candidates[k].plane.normal.dot(plane.normal)) > std::cos(0.05) &&
                std::abs(candidates[k].plane.d - plane.d) < tol.margin(z))
                same = k;
        Candidate c;
        c.plane = plane;
        if (same >= 0) {
            members[same].insert(members[same].end(), inliers.begin(), inliers.end());
            const auto merged = fitPlane(pts, members[same]);
            if (merged && tiltFromVertical(*merged, cfg.gravity) <= cfg.max_tilt) candidates[same].plane = *merged;
            continue;
        }
        candidates.push_back(c);
        members.push_back(std::move(inliers));
    }
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        Candidate &c = candidates[k];
        c.inliers = static_cast<int>(members[k].size());
        c.frame = makePlaneFrame(c.plane, cfg.gravity, centroid(pts, members[k]));
        for (int i : members[k]) c.inlier_indices.push_back(sample[i]);
    }
    det.timing_ms["planes"] = msSince(t);
    for (const auto &c : candidates) det.debug.candidates.push_back(c.plane);
    if (candidates.empty()) {
        det.reason = "no vertical plane in view";
        det.timing_ms["total"] = msSince(t0);
        return det;
    }

    // Free space, rectangle and surface check, candidate by candidate, the largest possible
    // rectangle first; a candidate whose raster could not hold a bigger rectangle than the
    // one already accepted is not looked at.
    t = Clock::now();
    const auto rays = projector.cornerRays();
    std::vector<int> usable;
    std::vector<double> bound(candidates.size(), 0.0);
    for (int k = 0; k < static_cast<int>(candidates.size()); ++k) {
        Candidate &c = candidates[k];
        if (!workspaceOnPlane(projector.origin, rays, c)) continue;
        Eigen::Vector2d lo = c.workspace_uv[0], hi = c.workspace_uv[0];
        for (const auto &w : c.workspace_uv) {
            lo = lo.cwiseMin(w);
            hi = hi.cwiseMax(w);
        }
        // Only where the plane was seen can the picture go: clip to its inliers' extent.
        Eigen::Vector2d ilo = Eigen::Vector2d::Constant(1e9), ihi = Eigen::Vector2d::Constant(-1e9);
        for (int i : c.inlier_indices) {
            const Eigen::Vector2d uv = c.frame.toPlane(cloud.points[i].cast<double>());
            ilo = ilo.cwiseMin(uv);
            ihi = ihi.cwiseMax(uv);
        }
        lo = lo.cwiseMax(ilo - Eigen::Vector2d::Constant(cfg.cell));
        hi = hi.cwiseMin(ihi + Eigen::Vector2d::Constant(cfg.cell));
        if (!(lo.array() < hi.array()).all()) continue;
        c.raster = makeRasterFrame(lo, hi, cfg.cell);
        // Organized clouds: look only where the raster and the beam towards it are seen (a
        // margin for points off the plane at grazing angles and mixed pixels at edges); without
        // intrinsics, around where the plane's points are.
        c.image_box = camera ? rasterImageBox(*camera, c, projector.origin, near, cloud.width / 64 + cfg.support_stride)
                             : inlierImageBox(cloud, c.inlier_indices, cloud.width / 16);
        const double h = std::min(hi.y() - lo.y(), (hi.x() - lo.x()) / aspect);
        bound[k] = aspect * h * h;
        usable.push_back(k);
    }
    std::sort(usable.begin(), usable.end(), [&](int a, int b) { return bound[a] > bound[b]; });
    PointGrid &grid = scratch.grid;
    if (!usable.empty()) fillPointGrid(cloud, cfg.support_stride, grid);
    if (scratch.observations.size() < candidates.size()) scratch.observations.resize(candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k) candidates[k].observed = &scratch.observations[k];
    double ms_free = msSince(t), ms_rect = 0.0, ms_check = 0.0;

    const Candidate *chosen = nullptr;
    SurfaceCheckResult last;
    int last_k = -1;  // the candidate `last` checked
    std::vector<int> placed;
    for (int k : usable) {
        if (chosen && bound[k] <= chosen->rectangle.area()) break;
        Candidate &c = candidates[k];
        t = Clock::now();
        observedFreeSpace(cloud, grid, projector, cfg, c);
        ms_free += msSince(t);
        t = Clock::now();
        const bool ok = placeRectangle(c, aspect);
        if (ok) refineRectangle(c, aspect);
        ms_rect += msSince(t);
        if (!ok) continue;
        placed.push_back(k);
        if (chosen && c.rectangle.area() <= chosen->rectangle.area()) continue;
        // Mixed pixels at depth edges along the border are not the surface's fault: the check
        // looks one raster cell inside the rectangle.
        t = Clock::now();
        const Rectangle inner = shrink(c.frame, c.rectangle, c.raster.cell);
        const SurfaceCheckResult check = checkObservedSurface(*c.observed, c.raster, c.frame.toPlane(inner.corners[3]),
                                                              c.frame.toPlane(inner.corners[1]), cfg.max_outlier_fraction);
        ms_check += msSince(t);
        if (check.accepted || !chosen) {
            last = check;
            last_k = k;
        }
        if (check.accepted) chosen = &c;
    }
    // The outliers of the check reported, by index (for overlays): looked for only where the
    // camera sees that rectangle.
    t = Clock::now();
    if (last_k >= 0) {
        const Candidate &c = candidates[last_k];
        const Rectangle inner = shrink(c.frame, c.rectangle, c.raster.cell);
        const cv::Rect box = camera ? pixelBox(*camera, {inner.corners.begin(), inner.corners.end()}, 2 + cfg.support_stride)
                                     : c.image_box;
        last.outlier_indices = offPlanePoints(grid, grid.gridBox(box), c.plane, c.frame, c.raster, tol,
                                              c.frame.toPlane(inner.corners[3]), c.frame.toPlane(inner.corners[1]));
    }
    ms_check += msSince(t);
    det.timing_ms["free_space"] = ms_free;
    det.timing_ms["rectangle"] = ms_rect;
    det.timing_ms["surface_check"] = ms_check;
    std::sort(placed.begin(), placed.end(),
              [&](int a, int b) { return candidates[a].rectangle.area() > candidates[b].rectangle.area(); });

    const Candidate &shown = chosen ? *chosen : candidates[placed.empty() ? (usable.empty() ? 0 : usable[0]) : placed[0]];
    det.plane = shown.plane;
    det.inliers = shown.inliers;
    det.orientation_deg = orientationDeg(shown.plane);
    if (!shown.free.empty()) {
        fillDebug(shown, det.debug);
        std::vector<std::vector<cv::Point>> contours;
        cv::findContours(shown.free.clone(), contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
        for (const auto &contour : contours) {
            std::vector<Eigen::Vector3d> outline;
            for (const auto &p : contour)
                outline.push_back(shown.frame.toCamera(shown.raster.toPlane({p.x + 0.5, p.y + 0.5})));
            det.debug.hull.push_back(outline);
        }
    }
    det.debug.inliers = shown.inlier_indices;
    if (chosen) {
        det.found = true;
        det.rectangle = chosen->rectangle;
        det.surface_check = last;
    } else if (usable.empty()) {
        det.reason = "the projector workspace does not reach any vertical plane in view";
    } else if (placed.empty()) {
        det.reason = "no free area for the picture on any vertical plane";
    } else {
        det.rectangle = candidates[placed[0]].rectangle;
        det.surface_check = last;
        det.surface_check.accepted = false;
        det.reason = "the surface check rejected every candidate area";
    }
    det.debug.outliers = det.surface_check.outlier_indices;
    det.timing_ms["total"] = msSince(t0);
    return det;
}

}  // namespace

SurfaceDetector::SurfaceDetector(const Projector &projector, const DetectorConfig &config)
    : projector_(projector), config_(config), scratch_(std::make_unique<DetectorScratch>()) {}
SurfaceDetector::~SurfaceDetector() = default;
SurfaceDetector::SurfaceDetector(SurfaceDetector &&) noexcept = default;
SurfaceDetector &SurfaceDetector::operator=(SurfaceDetector &&) noexcept = default;

Detection SurfaceDetector::detect(const Cloud &cloud) {
    const double aspect = config_.aspect > 0.0 ? config_.aspect : projector_.aspect();
    return config_.method == Method::Paper ? detectPaper(cloud, projector_, config_, aspect)
                                           : detectDefault(cloud, projector_, config_, aspect, *scratch_);
}

Detection detectSurface(const Cloud &cloud, const Projector &projector, const DetectorConfig &config) {
    return SurfaceDetector(projector, config).detect(cloud);
}

}  // namespace projsurf
