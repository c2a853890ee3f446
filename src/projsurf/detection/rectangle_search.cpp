#include "projsurf/detection/rectangle_search.hpp"
#include "projsurf/types/target_clones.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace projsurf {
namespace {

/// Integral image of blocked cells: S(r, c) = blocked cells in rows < r, cols < c.
struct BlockedSum {
    int rows = 0, cols = 0;
    std::vector<int> s;
    explicit BlockedSum(const cv::Mat &free_mask) : rows(free_mask.rows), cols(free_mask.cols) {
        s.assign(static_cast<std::size_t>(rows + 1) * (cols + 1), 0);
        for (int r = 0; r < rows; ++r) {
            const uchar *m = free_mask.ptr<uchar>(r);
            int run = 0;
            for (int c = 0; c < cols; ++c) {
                run += m[c] == 0;
                at(r + 1, c + 1) = at(r, c + 1) + run;
            }
        }
    }
    int &at(int r, int c) { return s[static_cast<std::size_t>(r) * (cols + 1) + c]; }
    int at(int r, int c) const { return s[static_cast<std::size_t>(r) * (cols + 1) + c]; }
    const int *row(int r) const { return s.data() + static_cast<std::size_t>(r) * (cols + 1); }
    int blocked(int r0, int c0, int nr, int nc) const {
        return at(r0 + nr, c0 + nc) - at(r0, c0 + nc) - at(r0 + nr, c0) + at(r0, c0);
    }
};

/// Whether some placement of an nr x nc rectangle whose top row is `r` has no blocked cell;
/// the whole row of placements is tested without an early exit, so that it vectorises.
PROJSURF_CLONES
bool rowFits(const BlockedSum &bs, int r, int nr, int nc) {
    const int *top = bs.row(r), *bottom = bs.row(r + nr);
    int found = 0;
    for (int c = 0; c + nc <= bs.cols; ++c) found |= (bottom[c + nc] - top[c + nc] - bottom[c] + top[c]) == 0;
    return found != 0;
}

bool anyFits(const BlockedSum &bs, int nr, int nc) {
    for (int r = 0; r + nr <= bs.rows; ++r)
        if (rowFits(bs, r, nr, nc)) return true;
    return false;
}

/// Bounding box of the non-zero cells (empty when there is none). (cv::boundingRect would
/// read a mask of two rows or columns as a list of points.)
cv::Rect nonZeroBox(const cv::Mat &mask) {
    int c0 = mask.cols, c1 = -1, r0 = mask.rows, r1 = -1;
    for (int r = 0; r < mask.rows; ++r) {
        const uchar *m = mask.ptr<uchar>(r);
        int first = 0, last = mask.cols - 1;
        while (first < mask.cols && !m[first]) ++first;
        if (first == mask.cols) continue;
        while (!m[last]) --last;
        c0 = std::min(c0, first);
        c1 = std::max(c1, last);
        r0 = std::min(r0, r);
        r1 = r;
    }
    return r1 < 0 ? cv::Rect() : cv::Rect(c0, r0, c1 - c0 + 1, r1 - r0 + 1);
}

}  // namespace

int widthForRows(int rows, double aspect) { return static_cast<int>(std::ceil(aspect * rows - 1e-9)); }

std::optional<GridRect> largestAspectRect(const cv::Mat &free_mask, double aspect, const Eigen::Vector2d &prefer) {
    CV_Assert(free_mask.type() == CV_8UC1);
    if (free_mask.empty() || !(aspect > 0.0)) return std::nullopt;
    // Only the bounding box of the free cells can hold the rectangle (often a small part of
    // the raster); searching it gives the same answer, placements in the same order.
    const cv::Rect box = nonZeroBox(free_mask);
    if (box.area() == 0) return std::nullopt;
    if (box.size() != free_mask.size()) {
        auto inner = largestAspectRect(free_mask(box), aspect, prefer - Eigen::Vector2d(box.x, box.y));
        if (inner) {
            inner->col += box.x;
            inner->row += box.y;
        }
        return inner;
    }
    const BlockedSum bs(free_mask);
    auto fits = [&](int nr) {
        const int nc = widthForRows(nr, aspect);
        return nr <= bs.rows && nc <= bs.cols && nc >= 1 && anyFits(bs, nr, nc);
    };
    if (!fits(1)) return std::nullopt;
    int lo = 1, hi = std::min(bs.rows, static_cast<int>(bs.cols / aspect) + 1) + 1;  // fits(lo), !fits(hi)
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (fits(mid) ? lo : hi) = mid;
    }
    const int nr = lo, nc = widthForRows(lo, aspect);
    GridRect best;
    double best_d = std::numeric_limits<double>::infinity();
    for (int r = 0; r + nr <= bs.rows; ++r) {
        if (!rowFits(bs, r, nr, nc)) continue;
        for (int c = 0; c + nc <= bs.cols; ++c) {
            if (bs.blocked(r, c, nr, nc) != 0) continue;
            const double d = (Eigen::Vector2d(c + 0.5 * nc, r + 0.5 * nr) - prefer).squaredNorm();
            if (d < best_d) {
                best_d = d;
                best = {c, r, nc, nr};
            }
        }
    }
    return best;
}

std::optional<Rectangle> largestFreeRectangle(const cv::Mat &free_mask, const RasterFrame &raster,
                                              const PlaneFrame &frame, double aspect, const Eigen::Vector2d &prefer) {
    const auto rect = largestAspectRect(free_mask, aspect, raster.toCell(prefer));
    if (!rect) return std::nullopt;
    const double h = rect->rows * raster.cell, w = aspect * h;
    const double u_mid = raster.top_left.x() + (rect->col + 0.5 * rect->cols) * raster.cell;
    const double v_top = raster.top_left.y() - rect->row * raster.cell;
    return makeRectangle(frame, {u_mid - 0.5 * w, v_top - h}, {u_mid + 0.5 * w, v_top});
}

}  // namespace projsurf
