#include "projsurf/detection/paper/paper_method.hpp"

#include <random>

#include "projsurf/calibration/euler_rodrigues.hpp"
#include "projsurf/detection/candidate.hpp"
#include "projsurf/detection/paper/hull.hpp"
#include "projsurf/detection/paper/outline_raster.hpp"
#include "projsurf/detection/paper/voxel_grid.hpp"
#include "projsurf/detection/planes/vertical_planes.hpp"
#include "projsurf/detection/planes/vertical_ransac.hpp"
#include "projsurf/detection/projector_footprint.hpp"
#include "projsurf/detection/rectangle_search.hpp"
#include "projsurf/detection/stage_timer.hpp"

namespace projsurf {
namespace {

/// 3.2.1: RANSAC on the voxel grid for the plane with the most points among the vertical ones;
/// the paper keeps RANSAC's model as it is (no refinement).
std::optional<PlaneInliers> findPaperPlane(const std::vector<Point> &voxels, const DetectorConfig &cfg,
                                           const Eigen::Vector3d &gravity) {
    std::vector<int> all(voxels.size());
    for (std::size_t i = 0; i < voxels.size(); ++i) all[i] = static_cast<int>(i);
    const std::vector<float> band(voxels.size(), static_cast<float>(cfg.paper.ransac_distance));
    RansacOptions opt;
    opt.max_tilt = cfg.max_tilt;
    opt.max_iterations = cfg.paper.ransac_iterations;
    std::mt19937 rng(cfg.seed);
    return findVerticalPlane(voxels, all, band, gravity, opt, rng);
}

/// 3.2.2, first half: the hull of the inliers on the plane (edges in plane coordinates; its
/// outline in the camera frame goes to `c.outlines`).
std::vector<Segment2> hullEdges(const std::vector<Eigen::Vector2d> &uv, const PaperConfig &paper, Candidate &c) {
    if (paper.hull == HullKind::Convex) {
        const auto hull = convexHull(uv);
        std::vector<Eigen::Vector3d> outline;
        for (const auto &p : hull) outline.push_back(c.frame.toCamera(p));
        c.outlines.push_back(outline);
        return polygonEdges(hull);
    }
    std::vector<Segment2> edges = concaveHullEdges(uv, paper.concave_alpha);
    for (const auto &e : edges) c.outlines.push_back({c.frame.toCamera(e[0]), c.frame.toCamera(e[1])});
    return edges;
}

/// 3.2.2, second half: both outlines (hull and workspace) rasterised, added, and the cells
/// that are 0 in the sum are projectable (the matrices M1, M2, M3).
void rasteriseFreeSpace(const std::vector<Eigen::Vector2d> &uv, const std::vector<Segment2> &hull_edges,
                        const PaperConfig &paper, Candidate &c) {
    Eigen::Vector2d lo = c.footprint.uv[0], hi = c.footprint.uv[0];
    for (const auto &p : uv) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    for (const auto &p : c.footprint.uv) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    c.raster = makeRasterFrame(lo, hi, paper.cell);
    const cv::Mat m1 = outlineMask(c.raster, hull_edges);
    const cv::Mat m2 = outlineMask(c.raster, polygonEdges({c.footprint.uv.begin(), c.footprint.uv.end()}));
    c.free = (m1 + m2) == 0;
}

}  // namespace

Detection detectPaper(const Cloud &cloud, const Projector &projector, const DetectorConfig &cfg,
                      const Eigen::Vector3d &gravity, double aspect) {
    Detection det;
    StageTimer time(det);
    const std::vector<Point> voxels = voxelDownsample(cloud.points, cfg.paper.voxel_leaf);
    time.lap("voxel_grid");
    if (voxels.size() < 3) return time.fail("no points to search (empty or all-NaN cloud)");
    if (static_cast<long long>(voxels.size()) > cfg.paper.max_voxels)
        return time.fail("the cloud fills " + std::to_string(voxels.size()) +
                         " voxels, more than the paper method searches (" + std::to_string(cfg.paper.max_voxels) +
                         "): use the default method");

    const auto found = findPaperPlane(voxels, cfg, gravity);
    time.lap("plane");
    if (!found || found->inliers.size() < 3) return time.fail("no vertical plane in view");
    Candidate c;
    c.plane = found->plane;
    c.inliers = static_cast<int>(found->inliers.size());
    c.frame = makePlaneFrame(c.plane, gravity, centroid(voxels, found->inliers));
    det.plane = c.plane;
    det.inliers = c.inliers;
    det.orientation_deg = orientationDeg(c.plane);
    auto outcome = [&](CandidateVerdict v) {  // what became of the one plane
        c.verdict = v;
        det.candidates = {outcomeOf(c, voxels, v == CandidateVerdict::Chosen)};
        setSeenExtent(voxels, found->inliers, c.frame, det.candidates.front());
    };

    std::vector<Eigen::Vector2d> uv;
    for (int i : found->inliers) uv.push_back(c.frame.toPlane(voxels[i].cast<double>()));
    const std::vector<Segment2> hull_edges = hullEdges(uv, cfg.paper, c);
    time.lap("hull");

    // The workspace from the Euler-Rodrigues corner rays (eqs. 5-6).
    const auto rays = paperCornerRays(projector.direction, projector.fov_h, projector.fov_v);
    const auto footprint = footprintOnPlane(c.plane, c.frame, projector.origin, rays);
    if (!footprint) {
        outcome(CandidateVerdict::NotReached);
        return time.fail("the projector workspace does not reach the plane");
    }
    c.footprint = *footprint;
    rasteriseFreeSpace(uv, hull_edges, cfg.paper, c);
    time.lap("free_space");

    const auto rect = largestFreeRectangle(c.free, c.raster, c.frame, aspect, quadCentre(c.footprint.uv));
    time.lap("rectangle");
    if (rect) c.rectangle = *rect;
    describeCandidate(c, det.debug);
    det.debug.candidates = {c.plane};
    if (!rect) {
        outcome(CandidateVerdict::NoFreeArea);
        return time.fail("no free area on the plane for the picture");
    }
    det.rectangle = c.rectangle;

    // 3.2.3: the surface checker on the original cloud.
    det.surface_check =
        checkSurfaceAgainstMeanDepth(cloud, c.frame, c.rectangle, cfg.paper.outlier_distance, cfg.paper.max_outliers);
    time.lap("surface_check");
    det.debug.outliers = det.surface_check.outlier_indices;
    det.found = det.surface_check.accepted;
    c.check = det.surface_check;
    outcome(det.found ? CandidateVerdict::Chosen : CandidateVerdict::CheckRejected);
    if (!det.found)
        det.reason = "surface check rejected the area: " + std::to_string(det.surface_check.outliers) + " outliers > " +
                     std::to_string(cfg.paper.max_outliers);
    return time.finish();
}

}  // namespace projsurf
