#include "eval/real/label_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>

#include "projsurf/types/plane.hpp"

namespace projsurf::eval {

bool insidePolygon(const std::vector<Eigen::Vector2d> &poly, const Eigen::Vector2d &p) {
    bool in = false;
    const std::size_t n = poly.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Eigen::Vector2d &a = poly[i], &b = poly[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

namespace {

bool inPixels(const RealLabel &l, const CameraIntrinsics &cam, int surface, const Eigen::Vector2d &px) {
    if (px.x() < -0.5 || px.y() < -0.5 || px.x() > cam.width - 0.5 || px.y() > cam.height - 0.5) return false;
    bool usable = false;
    for (const auto &r : l.surfaces[surface].regions)
        if (insidePolygon(r.pixels, px)) {
            usable = true;
            break;
        }
    if (!usable) return false;
    for (const auto &o : l.obstacles)
        if (insidePolygon(o.pixels, px)) return false;
    return true;
}

}  // namespace

bool labelledFree(const RealLabel &l, const CameraIntrinsics &cam, int surface, const Eigen::Vector3d &p) {
    if (!(p.z() > 1e-3)) return false;
    return inPixels(l, cam, surface, cam.project(p));
}

SurfaceFit fitLabelSurface(const Cloud &cloud, const CameraIntrinsics &cam, const RealLabel &l, int surface) {
    SurfaceFit fit;
    if (!cloud.organized()) return fit;
    std::vector<int> idx;
    for (int v = 0; v < cloud.height; ++v)
        for (int u = 0; u < cloud.width; ++u) {
            const int i = v * cloud.width + u;
            if (isFinite(cloud.points[i]) && inPixels(l, cam, surface, Eigen::Vector2d(u, v))) idx.push_back(i);
        }
    auto plane = fitPlane(cloud.points, idx);
    if (!plane) return fit;
    std::vector<int> kept = idx;
    for (int pass = 0; pass < 6; ++pass) {
        std::vector<double> res;
        res.reserve(idx.size());
        for (int i : idx) res.push_back(std::abs(plane->signedDistance(cloud.points[i].cast<double>())));
        std::vector<double> sorted = res;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double sigma = 1.4826 * sorted[sorted.size() / 2];
        const double band = std::max(2.5 * sigma, 0.005);
        kept.clear();
        for (std::size_t k = 0; k < idx.size(); ++k)
            if (res[k] <= band) kept.push_back(idx[k]);
        const auto next = fitPlane(cloud.points, kept);
        if (!next) break;
        plane = next;
    }
    double ss = 0;
    for (int i : kept) ss += std::pow(plane->signedDistance(cloud.points[i].cast<double>()), 2);
    fit.ok = kept.size() >= 50;
    fit.plane = *plane;
    fit.points = static_cast<int>(kept.size());
    fit.rms = kept.empty() ? 0.0 : std::sqrt(ss / kept.size());
    return fit;
}

namespace {

/// Largest k x ceil(aspect k) block of ones in `free` (CV_8U) by binary search on k (a block
/// that fits implies every smaller one fits), each k checked at every placement with an
/// integral image; among the placements of the best size, the one nearest `prefer`
/// (col, row) wins.
bool largestBlock(const cv::Mat &free, double aspect, const Eigen::Vector2d &prefer, int &col, int &row, int &rows) {
    cv::Mat sum(free.rows + 1, free.cols + 1, CV_32S, cv::Scalar(0));
    for (int r = 0; r < free.rows; ++r)
        for (int c = 0; c < free.cols; ++c)
            sum.at<int>(r + 1, c + 1) =
                (free.at<uchar>(r, c) ? 1 : 0) + sum.at<int>(r, c + 1) + sum.at<int>(r + 1, c) - sum.at<int>(r, c);
    auto widthOf = [&](int k) { return static_cast<int>(std::ceil(aspect * k - 1e-9)); };
    auto fits = [&](int k, bool pick) {
        const int w = widthOf(k);
        if (k > free.rows || w > free.cols) return false;
        bool any = false;
        double best = std::numeric_limits<double>::infinity();
        for (int r = 0; r + k <= free.rows; ++r)
            for (int c = 0; c + w <= free.cols; ++c) {
                const int s =
                    sum.at<int>(r + k, c + w) - sum.at<int>(r, c + w) - sum.at<int>(r + k, c) + sum.at<int>(r, c);
                if (s != k * w) continue;
                if (!pick) return true;
                const double d = (Eigen::Vector2d(c + 0.5 * w, r + 0.5 * k) - prefer).squaredNorm();
                if (d < best) {
                    best = d;
                    col = c;
                    row = r;
                    any = true;
                }
            }
        return any;
    };
    int lo = 0, hi = free.rows;  // lo fits (0 trivially), hi + 1 does not
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (fits(mid, false))
            lo = mid;
        else
            hi = mid - 1;
    }
    if (lo == 0) return false;
    rows = lo;
    return fits(lo, true);
}

}  // namespace

LabelBest bestRectangleOnSurface(const RealLabel &l, const CameraIntrinsics &cam, int surface, const Plane &plane,
                                 double cell) {
    LabelBest best;
    const Projector &proj = l.projector;
    // Plane frame anchored where the projector's axis meets the plane.
    const auto centre = intersectRay(plane, proj.origin, proj.direction);
    if (!centre) return best;
    const PlaneFrame frame = makePlaneFrame(plane, l.gravity, *centre);
    std::vector<Eigen::Vector2d> foot;
    for (const auto &ray : proj.cornerRays()) {
        const auto hit = intersectRay(plane, proj.origin, ray);
        if (!hit) return best;
        foot.push_back(frame.toPlane(*hit));
    }
    Eigen::Vector2d lo = foot[0], hi = foot[0];
    for (const auto &f : foot) {
        lo = lo.cwiseMin(f);
        hi = hi.cwiseMax(f);
    }
    cell = std::max(cell, (hi - lo).maxCoeff() / 2500.0);
    const int cols = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell));
    const int rows = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell));
    cv::Mat free(rows, cols, CV_8U, cv::Scalar(0));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const Eigen::Vector2d uv(lo.x() + (c + 0.5) * cell, hi.y() - (r + 0.5) * cell);
            if (!insidePolygon(foot, uv)) continue;
            if (labelledFree(l, cam, surface, frame.toCamera(uv))) free.at<uchar>(r, c) = 1;
        }
    const double aspect = proj.aspect();
    const Eigen::Vector2d prefer((frame.toPlane(*centre).x() - lo.x()) / cell,
                                 (hi.y() - frame.toPlane(*centre).y()) / cell);
    int col = 0, row = 0, k = 0;
    if (!largestBlock(free, aspect, prefer, col, row, k)) return best;
    // The rectangle of exactly the aspect, centred in the block of cells it occupies.
    const double h = k * cell, w = aspect * h;
    const double u_mid = lo.x() + (col + 0.5 * std::ceil(aspect * k - 1e-9)) * cell;
    const double v_top = hi.y() - row * cell;
    const Rectangle rect = makeRectangle(frame, {u_mid - 0.5 * w, v_top - h}, {u_mid + 0.5 * w, v_top});
    best.found = true;
    best.surface = l.surfaces[surface].name;
    best.width = rect.width;
    best.height = rect.height;
    best.corners = rect.corners;
    return best;
}

LabelBest referenceBest(const Cloud &cloud, const CameraIntrinsics &cam, RealLabel &l, double cell) {
    LabelBest best;
    for (int s = 0; s < static_cast<int>(l.surfaces.size()); ++s) {
        const SurfaceFit fit = fitLabelSurface(cloud, cam, l, s);
        l.surfaces[s].has_plane = fit.ok;
        if (!fit.ok) continue;
        l.surfaces[s].plane = fit.plane;
        const LabelBest b = bestRectangleOnSurface(l, cam, s, fit.plane, cell);
        if (b.found && b.area() > best.area()) best = b;
    }
    return best;
}

RealLabel colourAwareLabel(const RealLabel &label) {
    RealLabel l = label;
    for (const auto &u : label.colour.unsuitable) l.obstacles.push_back(u.polygon);
    l.best = label.colour.best;
    return l;
}

LabelBest colourReferenceBest(const CameraIntrinsics &cam, const RealLabel &label, double cell) {
    const RealLabel l = colourAwareLabel(label);
    LabelBest best;
    for (int s = 0; s < static_cast<int>(l.surfaces.size()); ++s) {
        if (!l.surfaces[s].has_plane) continue;
        const LabelBest b = bestRectangleOnSurface(l, cam, s, l.surfaces[s].plane, cell);
        if (b.found && b.area() > best.area()) best = b;
    }
    return best;
}

}  // namespace projsurf::eval
