#include "projsurf/detection/default/default_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <random>

#include "projsurf/detection/candidate.hpp"
#include "projsurf/detection/colour/surface_suitability.hpp"
#include "projsurf/detection/default/face_surround.hpp"
#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/detection/default/planar_regions.hpp"
#include "projsurf/detection/default/plane_samples.hpp"
#include "projsurf/detection/image_boxes.hpp"
#include "projsurf/detection/planes/point_sampling.hpp"
#include "projsurf/detection/planes/vertical_planes.hpp"
#include "projsurf/detection/rectangle_growth.hpp"
#include "projsurf/detection/rectangle_search.hpp"
#include "projsurf/detection/stage_timer.hpp"
#include "projsurf/types/camera.hpp"

namespace projsurf {
namespace {

/// The points the planes are searched on.
struct CloudSample {
    std::vector<int> indices;                ///< into the cloud
    std::vector<Point> points;               ///< cloud.points[indices]
    std::vector<float> band;                 ///< inlier band of each point, m
    std::optional<CameraIntrinsics> camera;  ///< organized clouds are pinhole images: where a volume is seen
    float near = std::numeric_limits<float>::infinity();  ///< m, depth of the nearest point
};

/// A candidate with what the default method needs to search it.
struct PlaneCandidate : Candidate {
    cv::Rect image_box;                    ///< organized clouds: the pixels that matter to it (empty = all)
    double bound = 0.0;                    ///< m^2, the largest rectangle its raster could hold
    double spread_area = 0.0;              ///< m^2, the bounding box of its inliers on the plane
    std::vector<char> other_surfaces;      ///< depth images: the planar regions on other planes than this one
    PlaneObservation *observed = nullptr;  ///< what the camera saw of it, per raster cell
    WallShape shape;                       ///< how the seen wall departs from the plane
    DepthTolerance tolerance;              ///< the band about the shape (the noise measured on it)
    CellSuitability *colour = nullptr;     ///< the cells' fitness by their colour (null without colour)
    bool beyond_opening = false;           ///< seen through an opening of a nearer wall (a window, a door)
};

CloudSample sampleCloud(const Cloud &cloud, const DetectorConfig &cfg) {
    CloudSample s;
    s.indices = samplePoints(cloud, cfg.planes.target_samples);
    s.points.resize(s.indices.size());
    s.band.resize(s.indices.size());
    for (std::size_t i = 0; i < s.indices.size(); ++i) {
        s.points[i] = cloud.points[s.indices[i]];
        s.band[i] = cfg.tolerance.band(s.points[i].z());
        s.near = std::min(s.near, s.points[i].z());
    }
    // Every 8th sampled point is plenty for the four parameters.
    std::vector<int> probe;
    for (std::size_t i = 0; i < s.indices.size(); i += 8) probe.push_back(s.indices[i]);
    s.camera = fitIntrinsics(cloud, probe);
    return s;
}

PlaneCandidate makeCandidate(const CloudSample &s, const Plane &plane, const std::vector<int> &inliers,
                             const Eigen::Vector3d &gravity) {
    PlaneCandidate c;
    c.plane = plane;
    c.inliers = static_cast<int>(inliers.size());
    c.frame = makePlaneFrame(c.plane, gravity, centroid(s.points, inliers));
    for (int i : inliers) c.inlier_indices.push_back(s.indices[i]);
    return c;
}

/// 3.2.1 on a depth image: its planar regions, biggest first, each with the sampled points on it.
std::vector<PlaneCandidate> findRegionCandidates(const CloudSample &s, const PointGrid &grid, const DetectorConfig &cfg,
                                                 const Eigen::Vector3d &gravity, std::vector<std::int16_t> &labels,
                                                 std::vector<PlanarRegion> &regions) {
    PlanarRegionOptions opt = cfg.planes.regions;
    opt.max_tilt = cfg.max_tilt;
    std::vector<int> all(s.points.size());
    for (std::size_t i = 0; i < s.points.size(); ++i) all[i] = static_cast<int>(i);
    std::vector<PlaneCandidate> out;
    regions = findVerticalRegions(grid, gravity, cfg.tolerance, opt, &labels);
    for (int k = 0; k < static_cast<int>(regions.size()) && static_cast<int>(out.size()) < cfg.planes.max_planes; ++k) {
        const std::vector<int> inliers = planeInliers(s.points, all, s.band, regions[k].plane);
        if (inliers.size() < 3) continue;
        PlaneCandidate c = makeCandidate(s, regions[k].plane, inliers, gravity);
        // Regions of other surfaces (not this plane seen in pieces): where they meet it (a
        // corner), their points are no support for it.
        c.other_surfaces.assign(regions.size(), 0);
        for (std::size_t j = 0; j < regions.size(); ++j) {
            const Plane &p = regions[j].plane;
            const double z = std::abs(p.d);  // about the depth the two planes are compared at
            c.other_surfaces[j] = std::abs(p.normal.dot(c.plane.normal)) < std::cos(opt.merge_angle) ||
                                  std::abs(p.d - c.plane.d) > cfg.tolerance.margin(static_cast<float>(z));
        }
        out.push_back(std::move(c));
    }
    return out;
}

/// 3.2.1: every vertical plane of the sample, with its frame (upright by gravity).
std::vector<PlaneCandidate> findCandidates(const CloudSample &s, const DetectorConfig &cfg,
                                           const Eigen::Vector3d &gravity) {
    VerticalPlaneOptions opt;
    opt.ransac.max_tilt = cfg.max_tilt;
    opt.ransac.max_iterations = cfg.planes.ransac_iterations;
    opt.ransac.score_subset = cfg.planes.score_subset;
    opt.ransac.max_sample_span = cfg.planes.max_sample_span;
    opt.max_planes = cfg.planes.max_planes;
    opt.min_points = std::min<int>(cfg.planes.min_plane_points, static_cast<int>(s.points.size()) / 20 + 3);
    opt.refine_rounds = cfg.planes.refine_rounds;
    opt.merge_angle = cfg.planes.merge_angle;
    std::mt19937 rng(cfg.seed);
    std::vector<PlaneCandidate> out;
    for (const PlaneInliers &p : findVerticalPlanes(s.points, s.band, gravity, cfg.tolerance, opt, rng))
        out.push_back(makeCandidate(s, p.plane, p.inliers, gravity));
    return out;
}

/// Share of the grid's readings that lie in the vertical regions.
double regionShare(const std::vector<PlanarRegion> &regions, const PointGrid &grid) {
    std::size_t readings = 0;
    for (float z : grid.z) readings += z == z;
    std::size_t in_regions = 0;
    for (const PlanarRegion &r : regions) in_regions += static_cast<std::size_t>(r.points);
    return readings ? static_cast<double>(in_regions) / static_cast<double>(readings) : 0.0;
}

/// A plane parallel to a candidate's (within merge_angle) and within its obstacle margin.
bool foundAlready(const Plane &plane, const std::vector<PlaneCandidate> &candidates, const DetectorConfig &cfg) {
    for (const PlaneCandidate &c : candidates) {
        const double z = std::abs(c.plane.d);
        if (std::abs(c.plane.normal.dot(plane.normal)) > std::cos(cfg.planes.merge_angle) &&
            std::abs(std::abs(c.plane.d) - std::abs(plane.d)) < cfg.tolerance.margin(static_cast<float>(z)))
            return true;
    }
    return false;
}

/// 3.2.1: the point grid of the free-space passes, and every vertical plane in view: a depth
/// image's planar regions, else (or when no region grows) sequential RANSAC.
std::vector<PlaneCandidate> findPlanes(const Cloud &cloud, const CloudSample &s, const DetectorConfig &cfg,
                                       const Eigen::Vector3d &gravity, DefaultScratch &scratch) {
    fillPointGrid(cloud, cfg.free_space.stride, scratch.grid);
    scratch.region_labels.clear();
    const bool regions = cfg.planes.image_regions && scratch.grid.organized;
    if (!regions) return findCandidates(s, cfg, gravity);
    std::vector<PlaneCandidate> out =
        findRegionCandidates(s, scratch.grid, cfg, gravity, scratch.region_labels, scratch.regions);
    // A depth image whose cells are too rough to grow regions (a poor stereo unit's correlated
    // noise, more per-pixel noise than the sensor model's) may still hold a plain wall: when
    // the regions hold little of what the camera read, the robust plane search runs as well,
    // and the planes no region found join the candidates.
    if (regionShare(scratch.regions, scratch.grid) >= cfg.planes.min_region_share) return out;
    if (out.empty()) scratch.region_labels.clear();
    for (PlaneCandidate &c : findCandidates(s, cfg, gravity))
        if (!foundAlready(c.plane, out, cfg)) out.push_back(std::move(c));
    return out;
}

/// Cloud indices of the sampled points within the band of the candidate's shape (the plane's
/// band misses where the camera bends the wall). The relief is bilinear between its nodes, so it
/// reaches no further than its largest node: a point that far beyond the band about the
/// quadratic, or that far inside it, is decided without looking the relief up.
std::vector<int> onShape(const CloudSample &s, const PlaneCandidate &c) {
    float relief_max = 0.0f;
    for (float h : c.shape.relief.h) relief_max = std::max(relief_max, std::abs(h));
    const double reach = relief_max + 1e-9;  // m; the margin covers rounding
    // Each written by offQuadratic: no zero-filling.
    const std::unique_ptr<double[]> off_quadratic(new double[s.points.size()]);
    const std::unique_ptr<float[]> band(new float[s.points.size()]);
    offQuadratic(s.points, c.plane, c.frame, c.shape, c.tolerance, off_quadratic.get(), band.get());
    std::vector<int> out;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        if (off_quadratic[i] > band[i] + reach) continue;
        if (off_quadratic[i] + reach < band[i]) {
            out.push_back(s.indices[i]);
            continue;
        }
        const Eigen::Vector3d p = s.points[i].cast<double>();
        if (std::abs(c.plane.signedDistance(p) - c.shape.height(c.frame.toPlane(p))) <= band[i])
            out.push_back(s.indices[i]);
    }
    return out;
}

/// The wall's bend and noise about the candidate's plane as the camera saw them, and its
/// sampled points on that shape; false when no shape could be fitted.
bool fitShape(const Cloud &cloud, const CloudSample &s, const DetectorConfig &cfg, PlaneCandidate &c) {
    const double focal = s.camera ? s.camera->fx : CameraIntrinsics{}.fx;
    const auto shape = fitWallShape(s.points, s.band, c.plane, c.frame, cfg.wall.shape, focal);
    if (!shape) return false;
    c.shape = *shape;
    // The residual about the shape also counts what the shape cannot follow (a window recess, a
    // box): on depth images it may exceed the noise measured between nearby readings only by
    // what a smooth sensor error leaves (local_cap times).
    const double local =
        localNoiseK(cloud, s.indices, s.band, c.plane, cfg.wall.shape.capture_bands, cfg.wall.noise_offset_px);
    if (local > 0.0)
        c.shape.noise_k = std::min(c.shape.noise_k, cfg.wall.local_cap * std::max(local, cfg.tolerance.noise_k));
    c.tolerance = toleranceFor(c.shape, cfg.tolerance, cfg.wall.noise_min, cfg.wall.noise_max);
    c.inlier_indices = onShape(s, c);
    c.inliers = static_cast<int>(c.inlier_indices.size());
    return true;
}

/// Each wall's shape, and its plane refitted (least squares) to all the points on that shape:
/// the plane a segmentation found on part of the wall tilts with the sensor's error there. A
/// refit is kept only when more points lie on its shape (a narrow face next to another would
/// otherwise lean towards it).
void shapeWall(const Cloud &cloud, const CloudSample &s, const DetectorConfig &cfg, const Eigen::Vector3d &gravity,
               PlaneCandidate &c) {
    c.tolerance = cfg.tolerance;
    if (!cfg.wall.fit_shape || !fitShape(cloud, s, cfg, c)) return;
    for (int round = 0; round < cfg.wall.plane_refits; ++round) {
        const auto refit = fitPlane(cloud.points, c.inlier_indices);
        if (!refit || tiltFromVertical(*refit, gravity) > cfg.max_tilt) return;
        const double turn = std::acos(std::min(1.0, std::abs(refit->normal.dot(c.plane.normal))));
        if (turn < cfg.wall.refit_min_turn && std::abs(refit->d - c.plane.d) < cfg.wall.refit_min_shift) return;
        PlaneCandidate moved = c;
        moved.plane = *refit;
        moved.frame = makePlaneFrame(moved.plane, gravity, centroid(cloud.points, c.inlier_indices));
        if (!fitShape(cloud, s, cfg, moved) || moved.inliers <= c.inliers) return;
        c = std::move(moved);
    }
}

/// The box of the points (their 3rd to 97th percentiles) in the frame's plane coordinates.
std::pair<Eigen::Vector2d, Eigen::Vector2d> pointBox(const Cloud &cloud, const PlaneFrame &frame,
                                                     const std::vector<int> &points) {
    std::vector<double> us, vs;
    for (int i : points) {
        const Eigen::Vector2d w = frame.toPlane(cloud.points[i].cast<double>());
        us.push_back(w.x());
        vs.push_back(w.y());
    }
    const auto at = [](std::vector<double> &v, double q) {
        const auto k = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
        std::nth_element(v.begin(), k, v.end());
        return *k;
    };
    if (us.empty()) return {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    return {{at(us, 0.03), at(vs, 0.03)}, {at(us, 0.97), at(vs, 0.97)}};
}

/// A larger wall behind the face, seen above it: a parallel candidate further from the camera
/// by more than the obstacle margin whose points' box is larger, overlaps the face's sideways
/// and reaches over its top.
bool wallBehind(const Cloud &cloud, const DetectorConfig &cfg, const PlaneCandidate &c,
                const std::vector<PlaneCandidate> &candidates) {
    const auto [lo, hi] = pointBox(cloud, c.frame, c.inlier_indices);
    const double reach = cfg.objects.surround.offsets.empty() ? 0.0 : cfg.objects.surround.offsets.front();
    for (const PlaneCandidate &o : candidates) {
        if (&o == &c || std::abs(o.plane.normal.dot(c.plane.normal)) < std::cos(cfg.planes.regions.merge_angle))
            continue;
        const double z = std::abs(c.plane.d);
        if (std::abs(o.plane.d) - z <= cfg.tolerance.margin(static_cast<float>(z))) continue;
        const auto [olo, ohi] = pointBox(cloud, c.frame, o.inlier_indices);
        if ((ohi - olo).prod() > (hi - lo).prod() && olo.x() < hi.x() && ohi.x() > lo.x() && ohi.y() >= hi.y() + reach)
            return true;
    }
    return false;
}

/// A face that is an object on the scene, not a wall (depth images only): it stands free in the
/// room, or it stands before a larger wall that is seen above it, or it is a strip too low to
/// hold a picture.
bool objectFace(const Cloud &cloud, const CloudSample &s, const DetectorConfig &cfg, const PlaneCandidate &c,
                const std::vector<PlaneCandidate> &candidates) {
    if (!cfg.objects.avoid || !s.camera) return false;
    const FaceSurround f = faceSurround(cloud, *s.camera, c.frame, c.inlier_indices, c.tolerance, cfg.objects.surround);
    if (f.height < cfg.objects.rule.min_height || standsFree(f, cfg.objects.rule)) return true;
    return openAbove(f, cfg.objects.rule) && wallBehind(cloud, cfg, c, candidates);
}

/// The bounding box of the candidate's inliers in its plane coordinates (and its area).
void inlierExtent(const Cloud &cloud, PlaneCandidate &c, Eigen::Vector2d &lo, Eigen::Vector2d &hi) {
    lo = Eigen::Vector2d::Constant(1e9);
    hi = Eigen::Vector2d::Constant(-1e9);
    for (int i : c.inlier_indices) {
        const Eigen::Vector2d uv = c.frame.toPlane(cloud.points[i].cast<double>());
        lo = lo.cwiseMin(uv);
        hi = hi.cwiseMax(uv);
    }
    c.spread_area = std::max(0.0, (hi - lo).prod());
}

/// The projector's footprint on the candidate and the raster over the part of it where the
/// plane was seen; false when the projector does not reach the plane or the two do not meet.
bool frameCandidate(const Cloud &cloud, const CloudSample &s, const Projector &projector, const DetectorConfig &cfg,
                    double aspect, PlaneCandidate &c) {
    const auto footprint = footprintOnPlane(c.plane, c.frame, projector.origin, projector.footprintRays());
    if (!footprint) return false;
    c.footprint = *footprint;
    Eigen::Vector2d lo = c.footprint.uv[0], hi = c.footprint.uv[0];
    for (const auto &w : c.footprint.uv) {
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
    }
    const Eigen::Vector2d footprint_lo = lo, footprint_hi = hi;
    // Only where the plane was seen can the picture go: clip to its inliers' extent.
    Eigen::Vector2d ilo, ihi;
    inlierExtent(cloud, c, ilo, ihi);
    const Eigen::Vector2d pad = Eigen::Vector2d::Constant(cfg.free_space.cell);
    lo = lo.cwiseMax(ilo - pad);
    hi = hi.cwiseMin(ihi + pad);
    if (!(lo.array() < hi.array()).all()) return false;
    // The raster reaches a cell past the footprint where the wall was seen there: the free
    // surface loses a cell at the raster's edge (taken for the wall's edge), and the
    // footprint's edge is not the wall's.
    c.raster = makeRasterFrame(footprint_lo.cwiseMax(ilo) - pad, footprint_hi.cwiseMin(ihi) + pad, cfg.free_space.cell);
    // Organized clouds: only where the raster and the beam towards it are seen, with a margin
    // for points off the plane at grazing angles and mixed pixels at edges; without
    // intrinsics, around where the plane's points are.
    const int width = cloud.width;
    c.image_box =
        s.camera ? beamImageBox(*s.camera, c.frame, c.raster, projector.origin, s.near,
                                static_cast<int>(width * cfg.free_space.image_margin) + cfg.free_space.stride)
                 : indexImageBox(cloud, c.inlier_indices, static_cast<int>(width * cfg.free_space.inlier_box_margin));
    const double h = std::min(hi.y() - lo.y(), (hi.x() - lo.x()) / aspect);
    c.bound = aspect * h * h;
    return true;
}

/// 3.2.2: the free surface of the candidate from one pass over the points where it is seen.
void observeFreeSpace(const Cloud &cloud, DefaultScratch &scratch, const Projector &projector,
                      const DetectorConfig &cfg, PlaneCandidate &c) {
    const PointGrid &grid = scratch.grid;
    // On depth images, points of another surface nearer its plane than this one's (where a wall
    // meets this one at a corner) are no support for it, even within its band.
    const bool exclude =
        cfg.free_space.exclude_other_surfaces && !c.other_surfaces.empty() && !scratch.region_labels.empty();
    if (exclude)
        nearerOtherMask(grid, grid.gridBox(c.image_box), scratch.region_labels, scratch.regions, c.other_surfaces,
                        c.plane, c.tolerance, scratch.exclude);
    observePlane(grid, grid.gridBox(c.image_box), c.plane, c.frame, c.raster, projector.origin, c.tolerance,
                 *c.observed, c.shape, exclude ? &scratch.exclude : nullptr);
    // The gaps between neighbouring samples on the wall are closed, up to a limit.
    const double spacing = sampleSpacing(cloud, c.inlier_indices, c.plane, grid.step, c.tolerance, c.spread_area,
                                         c.observed->support_points);
    const double gap = std::ceil(spacing / c.raster.cell);
    const int gap_cells =
        std::isfinite(gap) ? static_cast<int>(std::clamp(gap, 1.0, double(cfg.free_space.max_gap_cells))) : 1;
    SurfaceCells cells = observedFreeSurface(*c.observed, gap_cells, cfg.free_space.min_blocked_neighbours,
                                             cfg.free_space.proud, c.raster.cell, cfg.free_space.steps);
    c.surface = cells.free;
    c.cell_state = cells.state;
    c.free = c.surface & footprintCells(c.raster, c.footprint.uv);
}

/// The largest rectangle on the candidate's free cells, grown against the exact footprint.
bool placeRectangle(double aspect, PlaneCandidate &c) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto &w : c.footprint.uv) centre += 0.25 * w;
    const auto rect = largestFreeRectangle(c.free, c.raster, c.frame, aspect, centre);
    if (!rect) return false;
    c.rectangle = growRectangle(*rect, c.frame, c.raster, c.surface, c.footprint.uv, aspect);
    return true;
}

/// Each free cell's fitness by the colour of the wall seen there, in its cell state.
void judgeColour(const Cloud &cloud, DefaultScratch &scratch, const DetectorConfig &cfg, std::size_t k,
                 PlaneCandidate &c) {
    CellSuitability &s = scratch.colour.at(k);
    cellSuitability(scratch.grid, scratch.grid.gridBox(c.image_box), cloud.colours, c.plane, c.frame, c.raster,
                    c.tolerance, c.shape, cfg.suitability.cells, s);
    if (s.empty()) return;
    c.colour = &s;
    for (int r = 0; r < s.rows; ++r) {
        const uchar *unfit = s.unfit.ptr<uchar>(r);
        uchar *state = c.cell_state.ptr<uchar>(r);
        for (int col = 0; col < s.cols; ++col)
            if (unfit[col] && state[col] == static_cast<uchar>(CellState::Free))
                state[col] = static_cast<uchar>(static_cast<int>(CellState::Edge) + unfit[col]);
    }
}

/// The cells unfit by their colour taken off the free surface.
void avoidUnfit(PlaneCandidate &c) {
    const cv::Mat unfit = c.colour->unfit != 0;
    c.surface.setTo(0, unfit);
    c.free.setTo(0, unfit);
}

double unfitShare(const PlaneCandidate &c) {
    return regionSuitability(*c.colour, c.raster, c.frame.toPlane(c.rectangle.corners[3]),
                             c.frame.toPlane(c.rectangle.corners[1]))
        .unfit_share;
}

/// The rectangle by the suitability mode: off (or no colour) as placeRectangle; avoid on the
/// fit cells only; prefer the better of both by area x (1 - unfit share)^k.
bool placeSuitableRectangle(const DetectorConfig &cfg, double aspect, PlaneCandidate &c) {
    const SuitabilityMode mode = c.colour ? cfg.suitability.mode : SuitabilityMode::Off;
    if (mode == SuitabilityMode::Off) return placeRectangle(aspect, c);
    if (mode == SuitabilityMode::Avoid) {
        avoidUnfit(c);
        return placeRectangle(aspect, c);
    }
    const bool any = placeRectangle(aspect, c);
    const Rectangle plain = c.rectangle;
    const double plain_score =
        any ? plain.area() * std::pow(1.0 - unfitShare(c), cfg.suitability.prefer_exponent) : 0.0;
    const cv::Mat surface = c.surface.clone(), free = c.free.clone();
    avoidUnfit(c);
    const bool clean = placeRectangle(aspect, c);
    if (clean && c.rectangle.area() >= plain_score) return true;
    if (!any) return false;
    c.rectangle = plain;
    c.surface = surface;
    c.free = free;
    return true;
}

/// What the chosen rectangle lies on, by its colour.
SuitabilityReport reportSuitability(const DetectorConfig &cfg, const PlaneCandidate &c) {
    SuitabilityReport r;
    if (!c.colour || cfg.suitability.mode == SuitabilityMode::Off) return r;
    const RegionSuitability s = regionSuitability(*c.colour, c.raster, c.frame.toPlane(c.rectangle.corners[3]),
                                                  c.frame.toPlane(c.rectangle.corners[1]));
    r.used = true;
    r.mode = suitabilityModeName(cfg.suitability.mode);
    r.mean_albedo = s.mean_luminance;
    r.texture = s.contrast;
    r.unsuitable_share = s.unfit_share;
    r.wall_luminance = c.colour->median_luminance;
    return r;
}

/// 3.2.3, read off the free-space pass. Mixed pixels at depth edges along the border are not
/// the surface's fault: the check looks one raster cell inside the rectangle.
SurfaceCheckResult checkRectangle(const DetectorConfig &cfg, const PlaneCandidate &c) {
    const Rectangle inner = shrinkRectangle(c.frame, c.rectangle, c.raster.cell);
    return checkObservedSurface(*c.observed, c.raster, c.frame.toPlane(inner.corners[3]),
                                c.frame.toPlane(inner.corners[1]), cfg.check.max_outlier_fraction);
}

/// Cloud indices of the points the check counted as off the wall (for overlays), looked for
/// only where the camera sees the rectangle.
std::vector<int> checkOutliers(const CloudSample &s, const PointGrid &grid, const PlaneCandidate &c) {
    const Rectangle inner = shrinkRectangle(c.frame, c.rectangle, c.raster.cell);
    const cv::Rect box =
        s.camera ? pixelBox(*s.camera, {inner.corners.begin(), inner.corners.end()}, 2 + grid.step) : c.image_box;
    return offPlanePoints(grid, grid.gridBox(box), c.plane, c.frame, c.raster, c.tolerance,
                          c.frame.toPlane(inner.corners[3]), c.frame.toPlane(inner.corners[1]), c.shape);
}

/// Outlines of the free cells, camera frame (for overlays).
std::vector<std::vector<Eigen::Vector3d>> freeOutlines(const PlaneCandidate &c) {
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(c.free.clone(), contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
    std::vector<std::vector<Eigen::Vector3d>> out;
    for (const auto &contour : contours) {
        std::vector<Eigen::Vector3d> outline;
        for (const auto &p : contour) outline.push_back(c.frame.toCamera(c.raster.toPlane({p.x + 0.5, p.y + 0.5})));
        out.push_back(outline);
    }
    return out;
}

/// Stage 3: the candidates the projector reaches, the largest rectangle they could hold first.
/// A face seen through an opening of a nearer wall (the world outside a window, a room beyond a
/// door): bounded in front on every side, behind a parallel candidate by more than
/// objects.opening_depth. The projector's light would fall on the glass or through the door.
bool beyondOpening(const Cloud &cloud, const CloudSample &s, const DetectorConfig &cfg, const PlaneCandidate &c,
                   const std::vector<PlaneCandidate> &candidates) {
    if (!cfg.objects.avoid || !s.camera) return false;
    bool nearer_wall = false;
    for (const PlaneCandidate &o : candidates)
        nearer_wall |= &o != &c &&
                       std::abs(o.plane.normal.dot(c.plane.normal)) > std::cos(cfg.planes.regions.merge_angle) &&
                       std::abs(c.plane.d) - std::abs(o.plane.d) > cfg.objects.opening_depth;
    if (!nearer_wall) return false;
    const FaceSurround f =
        faceSurround(cloud, *s.camera, c.frame, c.inlier_indices, cfg.tolerance, cfg.objects.surround);
    return enclosedInFront(f, cfg.objects.rule);
}

std::vector<int> frameCandidates(const Cloud &cloud, const CloudSample &s, const Projector &projector,
                                 const DetectorConfig &cfg, double aspect, std::vector<PlaneCandidate> &candidates,
                                 DefaultScratch &scratch) {
    std::vector<int> usable;
    for (int k = 0; k < static_cast<int>(candidates.size()); ++k) {
        candidates[k].beyond_opening = beyondOpening(cloud, s, cfg, candidates[k], candidates);
        if (!candidates[k].beyond_opening && frameCandidate(cloud, s, projector, cfg, aspect, candidates[k]))
            usable.push_back(k);
        else
            candidates[k].verdict =
                candidates[k].beyond_opening ? CandidateVerdict::BeyondOpening : CandidateVerdict::NotReached;
    }
    std::sort(usable.begin(), usable.end(), [&](int a, int b) { return candidates[a].bound > candidates[b].bound; });
    if (scratch.observations.size() < candidates.size()) scratch.observations.resize(candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k) candidates[k].observed = &scratch.observations[k];
    if (cloud.hasColour() && scratch.colour.size() < candidates.size()) scratch.colour.resize(candidates.size());
    return usable;
}

/// What stage 4 settled on: the accepted candidate, the one whose check is reported (the
/// accepted one, else the first checked), and every candidate that held a rectangle.
struct Choice {
    const PlaneCandidate *chosen = nullptr;
    const PlaneCandidate *checked = nullptr;
    SurfaceCheckResult check;
    std::vector<int> placed;
    std::vector<int> objects;  ///< candidates skipped as faces that stand free
};

/// Stage 4: each wall's shape, free space (3.2.2), colour, rectangle and surface check (3.2.3),
/// candidate by candidate in `usable` order; one that could not hold a bigger rectangle than
/// the one accepted is not looked at.
Choice chooseCandidate(const Cloud &cloud, const CloudSample &s, const Projector &projector, const DetectorConfig &cfg,
                       const Eigen::Vector3d &gravity, double aspect, const std::vector<int> &usable,
                       std::vector<PlaneCandidate> &candidates, DefaultScratch &scratch, StageTimer &time) {
    Choice r;
    for (int k : usable) {
        PlaneCandidate &c = candidates[k];
        if (r.chosen && c.bound <= r.chosen->rectangle.area()) break;
        // How the wall departs from its plane (the depth camera's bend) and its noise; on that
        // shape its points may reach further, so the raster is laid again.
        shapeWall(cloud, s, cfg, gravity, c);
        const bool object = objectFace(cloud, s, cfg, c, candidates);
        time.lap("wall_shape");
        const bool framed = !object && frameCandidate(cloud, s, projector, cfg, aspect, c);
        time.lap("framing");
        if (object) r.objects.push_back(k);
        c.verdict = object ? CandidateVerdict::Object : CandidateVerdict::NotReached;
        if (!framed) continue;
        observeFreeSpace(cloud, scratch, projector, cfg, c);
        time.lap("free_space");
        if (cloud.hasColour() && cfg.suitability.mode != SuitabilityMode::Off) {
            // Colour only takes cells away: a wall whose rectangle without it is no bigger than
            // the one accepted is not judged.
            if (r.chosen && !(placeRectangle(aspect, c) && c.rectangle.area() > r.chosen->rectangle.area())) {
                c.verdict =
                    c.rectangle.area() > 0.0 ? CandidateVerdict::SmallerRectangle : CandidateVerdict::NoFreeArea;
                time.lap("rectangle");
                continue;
            }
            judgeColour(cloud, scratch, cfg, static_cast<std::size_t>(k), c);
            time.lap("suitability");
        }
        const bool ok = placeSuitableRectangle(cfg, aspect, c);
        time.lap("rectangle");
        c.verdict = ok ? CandidateVerdict::SmallerRectangle : CandidateVerdict::NoFreeArea;
        if (!ok) continue;
        r.placed.push_back(k);
        if (r.chosen && c.rectangle.area() <= r.chosen->rectangle.area()) continue;
        const SurfaceCheckResult result = checkRectangle(cfg, c);
        if (result.accepted || !r.chosen) {
            r.check = result;
            r.checked = &c;
        }
        if (result.accepted) r.chosen = &c;
        if (!result.accepted) {
            c.verdict = CandidateVerdict::CheckRejected;
            c.check = result;
        }
        time.lap("surface_check");
    }
    if (r.checked) r.check.outlier_indices = checkOutliers(s, scratch.grid, *r.checked);
    time.lap("surface_check");
    return r;
}

/// Stage 5: the answer (the rectangle, or why there is none) and the plane shown with it.
void describeAnswer(const DetectorConfig &cfg, const std::vector<PlaneCandidate> &candidates,
                    const std::vector<int> &usable, Choice choice, Detection &det) {
    std::vector<int> &placed = choice.placed;
    std::sort(placed.begin(), placed.end(),
              [&](int a, int b) { return candidates[a].rectangle.area() > candidates[b].rectangle.area(); });
    const PlaneCandidate &shown =
        choice.chosen ? *choice.chosen : candidates[!placed.empty() ? placed[0] : (usable.empty() ? 0 : usable[0])];
    det.plane = shown.plane;
    det.inliers = shown.inliers;
    det.orientation_deg = orientationDeg(shown.plane);
    if (!shown.free.empty()) {
        describeCandidate(shown, det.debug);
        det.debug.wall_shape = shown.shape;
        det.debug.tolerance = shown.tolerance;
        const auto outlines = freeOutlines(shown);
        det.debug.hull.insert(det.debug.hull.end(), outlines.begin(), outlines.end());
    }
    det.debug.inliers = shown.inlier_indices;
    if (choice.chosen) {
        det.found = true;
        det.rectangle = choice.chosen->rectangle;
        det.surface_check = choice.check;
        det.suitability = reportSuitability(cfg, *choice.chosen);
    } else if (usable.empty()) {
        det.reason = "the projector workspace does not reach any vertical plane in view";
    } else if (placed.empty() && !choice.objects.empty()) {
        det.reason = "the projector reaches only faces that stand free in the room (furniture, boxes, people), no wall";
    } else if (placed.empty()) {
        det.reason = "no free area for the picture on any vertical plane";
    } else {
        det.rectangle = candidates[placed[0]].rectangle;
        det.surface_check = choice.check;
        det.surface_check.accepted = false;
        det.reason = "the surface check rejected every candidate area";
    }
    det.debug.outliers = det.surface_check.outlier_indices;
}

}  // namespace

Detection detectDefault(const Cloud &cloud, const Projector &projector, const DetectorConfig &cfg,
                        const Eigen::Vector3d &gravity, double aspect, DefaultScratch &scratch) {
    Detection det;
    StageTimer time(det);
    // 1. A sample of the cloud to search planes on.
    const CloudSample sample = sampleCloud(cloud, cfg);
    time.lap("sample");
    if (sample.points.size() < 3) return time.fail("no points to search (empty or all-NaN cloud)");

    // 2. Every vertical plane in view, biggest first (3.2.1).
    std::vector<PlaneCandidate> candidates = findPlanes(cloud, sample, cfg, gravity, scratch);
    for (const auto &c : candidates) det.debug.candidates.push_back(c.plane);
    time.lap("planes");
    if (candidates.empty()) return time.fail("no vertical plane in view");

    // 3. Those the projector reaches, the largest rectangle they could hold first.
    const std::vector<int> usable = frameCandidates(cloud, sample, projector, cfg, aspect, candidates, scratch);
    time.lap("framing");

    // 4. Shape, free space, colour, rectangle and check of each, until none could beat the best.
    Choice choice = chooseCandidate(cloud, sample, projector, cfg, gravity, aspect, usable, candidates, scratch, time);

    // 5. The answer, the plane shown with it, and what became of every candidate.
    for (const PlaneCandidate &c : candidates)
        det.candidates.push_back(outcomeOf(c, cloud.points, &c == choice.chosen, c.bound));
    describeAnswer(cfg, candidates, usable, std::move(choice), det);
    return time.finish();
}

SeenSurfaces seeVerticalSurfaces(const Cloud &cloud, const DetectorConfig &cfg, const Eigen::Vector3d &gravity,
                                 double cell, double reach, DefaultScratch &scratch) {
    SeenSurfaces out;
    const CloudSample sample = sampleCloud(cloud, cfg);
    out.camera = sample.camera;
    if (sample.points.size() < 3) return out;
    std::vector<PlaneCandidate> candidates = findPlanes(cloud, sample, cfg, gravity, scratch);
    if (scratch.observations.size() < candidates.size()) scratch.observations.resize(candidates.size());
    DetectorConfig fine = cfg;
    fine.free_space.cell = cell;
    // Detection's judgement, in detection's order: the opening before the wall's shape (on
    // every candidate as found), the object after it.
    for (PlaneCandidate &c : candidates) c.beyond_opening = beyondOpening(cloud, sample, cfg, c, candidates);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        PlaneCandidate &c = candidates[k];
        c.observed = &scratch.observations[k];
        shapeWall(cloud, sample, cfg, gravity, c);
        const bool object = !c.beyond_opening && objectFace(cloud, sample, cfg, c, candidates);
        Eigen::Vector2d lo, hi;
        inlierExtent(cloud, c, lo, hi);
        // Within `reach` of the camera's foot on the plane (a far plane is not rastered whole).
        const Eigen::Vector2d foot = c.frame.toPlane(Eigen::Vector3d::Zero());
        lo = (lo - Eigen::Vector2d::Constant(cell)).cwiseMax(foot - Eigen::Vector2d::Constant(reach));
        hi = (hi + Eigen::Vector2d::Constant(cell)).cwiseMin(foot + Eigen::Vector2d::Constant(reach));
        if (!(lo.array() < hi.array()).all()) continue;
        c.raster = makeRasterFrame(lo, hi, cell);
        // No lens in front of the plane: nothing counts as shadowing it (what does depends on
        // where a projector stands); every pixel is looked at.
        Projector on_plane;
        on_plane.origin = c.frame.origin;
        observeFreeSpace(cloud, scratch, on_plane, fine, c);
        SeenSurface s;
        s.plane = c.plane;
        s.frame = c.frame;
        s.raster = c.raster;
        s.free = c.surface;
        s.state = c.cell_state;
        s.tolerance = c.tolerance;
        s.shape = c.shape;
        s.inliers = c.inliers;
        s.object = object;
        s.beyond_opening = c.beyond_opening;
        out.surfaces.push_back(std::move(s));
    }
    return out;
}

}  // namespace projsurf
