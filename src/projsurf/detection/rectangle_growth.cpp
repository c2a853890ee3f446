#include "projsurf/detection/rectangle_growth.hpp"

#include <algorithm>
#include <cmath>

#include "projsurf/detection/projector_footprint.hpp"

namespace projsurf {

Rectangle growRectangle(const Rectangle &start, const PlaneFrame &frame, const RasterFrame &raster,
                        const cv::Mat &surface, const std::array<Eigen::Vector2d, 4> &footprint_uv, double aspect,
                        const GrowthOptions &options) {
    const Eigen::Vector2d lo = frame.toPlane(start.corners[3]), hi = frame.toPlane(start.corners[1]);
    const double cell = raster.cell;
    auto fits = [&](const Eigen::Vector2d &mid, double h) {
        const Eigen::Vector2d half(0.5 * aspect * h, 0.5 * h);
        const Eigen::Vector2d a = mid - half, b = mid + half;
        for (const Eigen::Vector2d &p : {a, b, Eigen::Vector2d(a.x(), b.y()), Eigen::Vector2d(b.x(), a.y())})
            if (!insideConvex(footprint_uv, p)) return false;
        const Eigen::Vector2d ca = raster.toCell({a.x(), b.y()}), cb = raster.toCell({b.x(), a.y()});
        // (Range checked in floating point first: no conversion of an out-of-range value.)
        if (!(ca.minCoeff() >= 0.0) || !(cb.x() <= surface.cols + 1.0) || !(cb.y() <= surface.rows + 1.0)) return false;
        const int c0 = static_cast<int>(std::floor(ca.x())), r0 = static_cast<int>(std::floor(ca.y()));
        const int c1 = static_cast<int>(std::floor(cb.x() - 1e-9)), r1 = static_cast<int>(std::floor(cb.y() - 1e-9));
        if (c1 >= surface.cols || r1 >= surface.rows) return false;
        for (int r = r0; r <= r1; ++r) {
            const uchar *row = surface.ptr<uchar>(r);
            for (int k = c0; k <= c1; ++k)
                if (!row[k]) return false;
        }
        return true;
    };
    // Largest height that fits about `mid`, searched in [h0, h0 + search_cells].
    auto grow = [&](const Eigen::Vector2d &mid, double h0) {
        double good = h0, bad = h0 + options.search_cells * cell;
        if (fits(mid, bad)) return bad;
        for (int it = 0; it < options.bisections; ++it) {
            const double h = 0.5 * (good + bad);
            (fits(mid, h) ? good : bad) = h;
        }
        return good;
    };
    Eigen::Vector2d mid = 0.5 * (lo + hi);
    double h = grow(mid, hi.y() - lo.y());
    // Slide away from whatever limits it, while that lets it grow.
    for (int round = 0; round < options.max_slides; ++round) {
        bool improved = false;
        for (const Eigen::Vector2d &dir :
             {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
            const Eigen::Vector2d moved = mid + options.slide_cells * cell * dir;
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
    return makeRectangle(frame, mid - half, mid + half);
}

Rectangle shrinkRectangle(const PlaneFrame &frame, const Rectangle &rect, double margin) {
    const Eigen::Vector2d lo = frame.toPlane(rect.corners[3]), hi = frame.toPlane(rect.corners[1]);
    const Eigen::Vector2d m = Eigen::Vector2d::Constant(std::min(margin, 0.25 * std::min(rect.width, rect.height)));
    return makeRectangle(frame, lo + m, hi - m);
}

}  // namespace projsurf
