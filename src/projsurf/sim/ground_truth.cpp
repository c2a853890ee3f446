#include "projsurf/sim/ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "projsurf/detection/rectangle_search.hpp"
#include "projsurf/sim/ray_cast.hpp"

namespace projsurf::sim {

bool segmentBlocked(const Scene &scene, const Eigen::Vector3d &from, const Eigen::Vector3d &to, double tolerance) {
    const Eigen::Vector3d dir = to - from;
    const double length = dir.norm();
    if (!(length > tolerance)) return false;
    const double t_max = 1.0 - tolerance / length;
    for (const auto &q : scene.quads) {
        if (q.material == Material::Glass) continue;  // transparent: neither a surface nor a blocker
        const auto t = intersectQuad(q, from, dir, 1e-9);
        if (t && *t < t_max) return true;
    }
    return false;
}

namespace {

/// Point-in-parallelogram test for points on the quad's plane.
struct QuadTest {
    Eigen::Vector3d corner, fa, fb;
    explicit QuadTest(const Quad &q) : corner(q.corner) {
        const Eigen::Vector3d n = q.edge_a.cross(q.edge_b);
        fa = q.edge_b.cross(n) / q.edge_b.cross(n).dot(q.edge_a);
        fb = n.cross(q.edge_a) / n.cross(q.edge_a).dot(q.edge_b);
    }
    bool contains(const Eigen::Vector3d &p) const {
        const Eigen::Vector3d r = p - corner;
        const double a = r.dot(fa), b = r.dot(fb);
        return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0;
    }
};

/// Whether a point of the surface can carry the picture: on one of its quads, lit by the
/// projector (through the lens when it distorts), in the camera's image and range, not at a
/// grazing angle, and neither the camera's (nor, when depth is required, the emitter's) nor
/// the projector's ray to it blocked.
struct FreePointTest {
    const Scene &scene;
    const SensorModel &sensor;
    const Projector &projector;
    const TruthOptions &opt;
    const Plane &plane;
    std::vector<QuadTest> tests;
    PinholeView cam, proj;
    double cos_grazing;

    FreePointTest(const Scene &scene_, const std::vector<int> &quads, const SensorModel &sensor_,
                  const Projector &projector_, const TruthOptions &opt_, const Plane &plane_)
        : scene(scene_),
          sensor(sensor_),
          projector(projector_),
          opt(opt_),
          plane(plane_),
          cam(cameraView(sensor_.camera)),
          proj(projectorView(projector_)),
          cos_grazing(std::cos(sensor_.grazing_max_deg * 3.14159265358979323846 / 180.0)) {
        for (int qi : quads) tests.emplace_back(scene.quads[qi]);
    }

    bool operator()(const Eigen::Vector3d &p) const {
        if (!std::any_of(tests.begin(), tests.end(), [&](const QuadTest &t) { return t.contains(p); })) return false;
        const Eigen::Vector3d pp = proj.toView(p);
        if (!(pp.z() > 0.0)) return false;
        if (projector.distorted()) {  // the lit area is the framebuffer through the lens
            const auto fb = projector.toPixel(p);
            if (!fb || !(fb->x() >= -0.5 && fb->x() < projector.width - 0.5 && fb->y() >= -0.5 &&
                         fb->y() < projector.height - 0.5))
                return false;
        } else if (!proj.inside(proj.pixelOf(pp))) {
            return false;
        }
        if (!(p.z() >= sensor.min_depth && p.z() <= sensor.max_depth)) return false;
        if (!cam.inside(cam.pixelOf(p))) return false;
        if (std::abs(plane.normal.dot(p)) < cos_grazing * p.norm()) return false;
        if (segmentBlocked(scene, Eigen::Vector3d::Zero(), p, opt.tolerance)) return false;
        if (opt.require_depth && sensor.ir_shadow && segmentBlocked(scene, sensor.emitter, p, opt.tolerance))
            return false;
        return !segmentBlocked(scene, projector.origin, p, opt.tolerance);
    }
};

/// The surface's extent in plane coordinates [lo, hi]: its quads, cut to the projector's
/// footprint when that is bounded (st.footprint, st.has_footprint).
void truthExtent(const Scene &scene, const std::vector<int> &quads, const Projector &projector, SurfaceTruth &st,
                 Eigen::Vector2d &lo, Eigen::Vector2d &hi) {
    lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int qi : quads)
        for (const auto &c : scene.quads[qi].corners()) {
            lo = lo.cwiseMin(st.frame.toPlane(c));
            hi = hi.cwiseMax(st.frame.toPlane(c));
        }
    const auto rays = projector.cornerRays();
    st.has_footprint = true;
    for (int i = 0; i < 4; ++i) {
        const auto hit = intersectRay(st.plane, projector.origin, rays[i]);
        if (!hit) {
            st.has_footprint = false;
            break;
        }
        st.footprint[i] = *hit;
    }
    if (st.has_footprint) {
        Eigen::Vector2d flo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), fhi = -flo;
        for (const auto &c : st.footprint) {
            flo = flo.cwiseMin(st.frame.toPlane(c));
            fhi = fhi.cwiseMax(st.frame.toPlane(c));
        }
        lo = lo.cwiseMax(flo);
        hi = hi.cwiseMin(fhi);
    }
}

/// st.free_mask (rows x cols cells from st.grid_origin) and st.free_area: a cell is free when
/// all four of its corners are. (The frustum and the surface are convex or unions of
/// rectangles, so the free cells' rectangle stays inside them.)
void markFreeCells(SurfaceTruth &st, int rows, int cols, const FreePointTest &point_free, double cell) {
    cv::Mat corner_free(rows + 1, cols + 1, CV_8U);
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= cols; ++c)
            corner_free.at<uchar>(r, c) =
                point_free(st.frame.toCamera({st.grid_origin.x() + c * cell, st.grid_origin.y() - r * cell}));
    int free_cells = 0;
    for (int r = 0; r < rows; ++r) {
        uchar *m = st.free_mask.ptr<uchar>(r);
        const uchar *a = corner_free.ptr<uchar>(r), *b = corner_free.ptr<uchar>(r + 1);
        for (int c = 0; c < cols; ++c)
            if (a[c] && a[c + 1] && b[c] && b[c + 1]) {
                m[c] = 255;
                ++free_cells;
            }
    }
    st.free_area = free_cells * cell * cell;
}

SurfaceTruth surfaceTruth(const Scene &scene, const std::vector<int> &quads, const SensorModel &sensor,
                          const Projector &projector, const Eigen::Vector3d &gravity, double aspect,
                          const TruthOptions &opt) {
    SurfaceTruth st;
    const Quad &first = scene.quads[quads.front()];
    st.surface = first.surface;
    st.label = first.label;
    st.cell = opt.cell;
    st.plane = makePlane(first.normal(), -first.normal().dot(first.corner));
    const auto on_axis = intersectRay(st.plane, projector.origin, projector.axis());
    st.frame = makePlaneFrame(st.plane, gravity, on_axis ? *on_axis : first.center());

    Eigen::Vector2d lo, hi;
    truthExtent(scene, quads, projector, st, lo, hi);
    if (!(hi.x() > lo.x() && hi.y() > lo.y())) return st;
    const int cols = static_cast<int>(std::ceil((hi.x() - lo.x()) / opt.cell));
    const int rows = static_cast<int>(std::ceil((hi.y() - lo.y()) / opt.cell));
    st.grid_origin = Eigen::Vector2d(lo.x(), hi.y());
    st.free_mask = cv::Mat(rows, cols, CV_8U, cv::Scalar(0));
    markFreeCells(st, rows, cols, FreePointTest(scene, quads, sensor, projector, opt, st.plane), opt.cell);

    const Eigen::Vector2d prefer_uv = Eigen::Vector2d::Zero();  // plane coords: the axis point
    const Eigen::Vector2d prefer((prefer_uv.x() - st.grid_origin.x()) / opt.cell,
                                 (st.grid_origin.y() - prefer_uv.y()) / opt.cell);
    const auto rect = largestAspectRect(st.free_mask, aspect, prefer);
    if (!rect) return st;
    const double height = rect->rows * opt.cell;
    const double width = aspect * height;  // <= rect->cols * cell: centred in the free cells
    const double x0 = st.grid_origin.x() + rect->col * opt.cell + 0.5 * (rect->cols * opt.cell - width);
    const double top = st.grid_origin.y() - rect->row * opt.cell;
    st.rectangle = makeRectangle(st.frame, {x0, top - height}, {x0 + width, top});
    st.found = true;
    return st;
}

}  // namespace

GroundTruth computeGroundTruth(const Scene &scene, const SensorModel &sensor, const Projector &projector,
                               const Eigen::Vector3d &gravity, const TruthOptions &options) {
    GroundTruth gt;
    gt.aspect = options.aspect > 0.0 ? options.aspect : projector.aspect();
    const Eigen::Vector3d g = gravity.normalized();
    std::map<int, std::vector<int>> surfaces;
    for (std::size_t i = 0; i < scene.quads.size(); ++i)
        if (scene.quads[i].surface >= 0) surfaces[scene.quads[i].surface].push_back(static_cast<int>(i));
    for (const auto &[id, quads] : surfaces) {
        const Eigen::Vector3d n = scene.quads[quads.front()].normal();
        if (std::abs(n.dot(g)) > std::sin(options.max_tilt)) continue;  // not vertical
        SurfaceTruth st = surfaceTruth(scene, quads, sensor, projector, g, gt.aspect, options);
        if (st.found && (!gt.found || st.rectangle.area() > gt.best.rectangle.area())) {
            gt.found = true;
            gt.best = st;
        }
        gt.surfaces.push_back(std::move(st));
    }
    return gt;
}

}  // namespace projsurf::sim
