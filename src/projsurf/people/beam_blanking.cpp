#include "projsurf/people/beam_blanking.hpp"

#include "projsurf/types/clamp_to_int.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace projsurf {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDiagonal = 1.41421356f;
/// The grid's distance is the octagonal (3x3 chamfer) one, at least the Euclidean one and at
/// most 1/cos(22.5 deg) of it: radii are divided by cos(22.5 deg) so the octagon holds the disc.
constexpr double kOctagon = 0.92387953;

/// Grid cells of margin needed around a point `depth` m along the axis, `off_axis` = 1 /
/// cos(angle from the axis): the rays within `margin` of it span margin f off_axis / depth px
/// (the point is depth off_axis away, and a pixel there subtends cos^2 of the axis's angle),
/// plus 1.5 cells for the point's position inside its cell and for the opening's ragged
/// edge; then widened for the octagonal distance.
double marginCells(double margin, double focal_px, int cell, double depth, double off_axis) {
    return (margin * focal_px * off_axis / (cell * depth) + 1.5) / kOctagon;
}

/// In place, the two raster scans of a 3x3 chamfer distance with offsets: afterwards
/// d(q) = min over p of (d0(p) + octagonal distance from p to q), d0 the values before.
void chamfer(cv::Mat &d) {
    const int w = d.cols, h = d.rows;
    // Each scan: first from the row before (no dependency along the row: vectorises), then
    // along the row (a dependency chain, one min per cell).
    for (int y = 1; y < h; ++y) {
        float *r = d.ptr<float>(y);
        const float *up = d.ptr<float>(y - 1);
        r[0] = std::min(r[0], std::min(up[0] + 1.0f, up[1] + kDiagonal));
        for (int x = 1; x + 1 < w; ++x)
            r[x] = std::min(r[x], std::min(up[x] + 1.0f, std::min(up[x - 1], up[x + 1]) + kDiagonal));
        r[w - 1] = std::min(r[w - 1], std::min(up[w - 1] + 1.0f, up[w - 2] + kDiagonal));
        for (int x = 1; x < w; ++x) r[x] = std::min(r[x], r[x - 1] + 1.0f);
    }
    {
        float *r = d.ptr<float>(0);  // the first row had no row before it
        for (int x = 1; x < w; ++x) r[x] = std::min(r[x], r[x - 1] + 1.0f);
    }
    for (int y = h - 1; y >= 0; --y) {
        float *r = d.ptr<float>(y);
        if (y + 1 < h) {
            const float *down = d.ptr<float>(y + 1);
            r[0] = std::min(r[0], std::min(down[0] + 1.0f, down[1] + kDiagonal));
            for (int x = 1; x + 1 < w; ++x)
                r[x] = std::min(r[x], std::min(down[x] + 1.0f, std::min(down[x - 1], down[x + 1]) + kDiagonal));
            r[w - 1] = std::min(r[w - 1], std::min(down[w - 1] + 1.0f, down[w - 2] + kDiagonal));
        }
        for (int x = w - 2; x >= 0; --x) r[x] = std::min(r[x], r[x + 1] + 1.0f);
    }
}

/// Angle between neighbouring pixels of an organized cloud (rad), from two points half the
/// image apart on one of a few rows; 0 when it cannot tell.
double pixelAngle(const Cloud &cloud) {
    if (!cloud.organized() || cloud.width < 8) return 0.0;
    const int c1 = cloud.width / 4, c2 = 3 * cloud.width / 4;
    for (const int row : {cloud.height / 2, cloud.height / 4, 3 * cloud.height / 4, cloud.height / 8}) {
        const Point &a = cloud.points[static_cast<std::size_t>(row) * cloud.width + c1];
        const Point &b = cloud.points[static_cast<std::size_t>(row) * cloud.width + c2];
        if (!isFinite(a) || !isFinite(b) || a.norm() < 1e-3f || b.norm() < 1e-3f) continue;
        const double cos_ab = std::clamp(static_cast<double>(a.normalized().dot(b.normalized())), -1.0, 1.0);
        return std::acos(cos_ab) / (c2 - c1);
    }
    return 0.0;
}

}  // namespace

BeamBlanker::BeamBlanker(const Projector &projector, const BlankingOptions &options)
    : projector_(projector), options_(options) {
    configure(clampToInt(std::round(options_.cell_angle * std::max(projector_.fx(), projector_.fy())), 1,
                         std::max(1, std::max(projector_.width, projector_.height))));
    mask_ = cv::Mat::zeros(projector_.height, projector_.width, CV_8U);
}

void BeamBlanker::configure(int cell_px) {
    const double focal = std::max(projector_.fx(), projector_.fy());
    cell_ = cell_px;
    // The widest angle from the axis: at the corners of the framebuffer, one margin further out.
    const double corner_x = 0.5 * projector_.width / projector_.fx(),
                 corner_y = 0.5 * projector_.height / projector_.fy();
    off_axis_ = std::sqrt(1.0 + corner_x * corner_x + corner_y * corner_y);
    // Clamped: a degenerate focal length (a lens model no reader lets through, but the class is
    // public) must not overflow the conversion; a pad wider than the framebuffer adds nothing.
    pad_ = clampToInt(std::ceil(marginCells(options_.ray_margin, focal, cell_, options_.min_depth, off_axis_)), 0,
                      std::max(1, std::max(projector_.width, projector_.height)));
    off_axis_ = std::hypot(corner_x + pad_ * cell_ / projector_.fx(), corner_y + pad_ * cell_ / projector_.fy());
    off_axis_ = std::sqrt(1.0 + off_axis_ * off_axis_);
    grid_w_ = (projector_.width + cell_ - 1) / cell_ + 2 * pad_;
    grid_h_ = (projector_.height + cell_ - 1) / cell_ + 2 * pad_;
}

const cv::Mat &BeamBlanker::compute(const Cloud &cloud, const Plane &plane) {
    blanked_ = 0;
    candidates_ = 0;
    noise_k_ = 0.0;
    fitCellToCloud(cloud);
    const float lens_side = lensSide(plane);
    if (!(lens_side > 0.0f) || !plane.normal.cast<float>().allFinite()) return blankNothing();
    measureWallNoise(cloud, plane);
    binObstructions(cloud, plane, lens_side);
    if (candidates_ == 0) return blankNothing();
    keepConnectedCells();
    if (!growByMargins()) return blankNothing();
    writeMask();
    return mask_;
}

const cv::Mat &BeamBlanker::blankNothing() {
    mask_.setTo(0);
    return mask_;
}

float BeamBlanker::lensSide(const Plane &plane) const {
    return plane.normal.cast<float>().dot(projector_.origin.cast<float>()) + static_cast<float>(plane.d);
}

void BeamBlanker::fitCellToCloud(const Cloud &cloud) {
    const double focal = std::max(projector_.fx(), projector_.fy());
    const double angle = std::max(options_.cell_angle, options_.cell_per_pixel * pixelAngle(cloud));
    const int cell =
        clampToInt(std::round(angle * focal), 1, std::max(1, std::max(projector_.width, projector_.height)));
    if (cell != cell_) configure(cell);
}

void BeamBlanker::measureWallNoise(const Cloud &cloud, const Plane &plane) {
    // The wall's noise: |distance| / z^2 of the points near the plane, on every 4th point.
    const Eigen::Vector3f n = plane.normal.cast<float>();
    const float d = static_cast<float>(plane.d);
    constexpr int kBins = 2000;
    constexpr float kBin = 1e-5f;  // 1/m per bin: sigma_k up to 0.013 (Kinect v1 ~0.0025)
    histogram_.assign(kBins, 0);
    const float window = static_cast<float>(options_.noise_window);
    int near_points = 0;
    for (std::size_t i = 0; i < cloud.points.size(); i += 4) {
        const Point &p = cloud.points[i];
        const float a = std::abs(n.dot(p) + d);
        if (a < window && p.z() > 0.1f) {
            histogram_[std::min(kBins - 1, static_cast<int>(a / (p.z() * p.z() * kBin)))]++;
            ++near_points;
        }
    }
    if (near_points >= 125) {
        int seen = 0, b = 0;
        while (b < kBins && 2 * (seen + histogram_[b]) < near_points) seen += histogram_[b++];
        noise_k_ = 1.4826 * (b + 0.5) * kBin;  // median absolute distance from the plane -> sigma
    }
}

float BeamBlanker::smallestCosine(const Plane &plane) const {
    float min_cos = 1.0f;
    const double l = -(pad_ * cell_) - 0.5, r = projector_.width + pad_ * cell_, b = projector_.height + pad_ * cell_;
    for (const auto &c : {Eigen::Vector2d(l, l), Eigen::Vector2d(r, l), Eigen::Vector2d(r, b), Eigen::Vector2d(l, b)})
        min_cos = std::min(min_cos, static_cast<float>(std::abs(plane.normal.dot(projector_.ray(c)))));
    return min_cos;
}

void BeamBlanker::binObstructions(const Cloud &cloud, const Plane &plane, float lens_side) {
    // The obstructing points, binned into the grid (nearest depth along the axis per cell).
    const Eigen::Vector3f o = projector_.origin.cast<float>();
    const Eigen::Vector3f n = plane.normal.cast<float>();
    const float d = static_cast<float>(plane.d);
    const float noise_gap = static_cast<float>(options_.noise_sigmas * noise_k_);
    hit_.create(grid_h_, grid_w_, CV_8U);
    hit_.setTo(0);
    nearest_.create(grid_h_, grid_w_, CV_32F);
    nearest_.setTo(kInf);
    const Eigen::Vector3f axis = projector_.direction.normalized().cast<float>();
    const Eigen::Vector3f right = projector_.right().cast<float>(), down = projector_.down().cast<float>();
    const float fx = static_cast<float>(projector_.fx()), fy = static_cast<float>(projector_.fy());
    const float cx = static_cast<float>(projector_.cx()), cy = static_cast<float>(projector_.cy());
    const float inv_cell = 1.0f / cell_, min_gap = static_cast<float>(options_.min_gap);
    const float min_depth = static_cast<float>(options_.min_depth), pad = static_cast<float>(pad_);
    // Along the ray the gap is the distance from the plane over the cosine between ray and
    // normal: a point nearer the plane than min_gap times the smallest cosine over the padded
    // framebuffer cannot count.
    const float pre_gap = min_gap * std::max(smallestCosine(plane), 0.05f);
    uchar *hit = hit_.ptr<uchar>();
    float *nearest = nearest_.ptr<float>();
    // Grid coordinates: g = (f (rel . right) / z + c + 0.5) / cell + pad.
    const float fxc = fx * inv_cell, fyc = fy * inv_cell;
    const float cxc = (cx + 0.5f) * inv_cell + pad, cyc = (cy + 0.5f) * inv_cell + pad;
    const float grid_w = static_cast<float>(grid_w_), grid_h = static_cast<float>(grid_h_);
    for (const Point &p : cloud.points) {
        const float s = n.dot(p) + d;  // > 0: camera side of the plane (NaN fails every test)
        if (!(s > pre_gap)) continue;
        const float towards = lens_side - s;  // > 0: the ray lens -> p goes on to meet the plane
        if (!(towards > 0.0f)) continue;
        const Eigen::Vector3f rel = p - o;
        // Along the ray the plane lies at lens_side / towards times rel: the gap between p
        // and the plane is |rel| s / towards; it must beat min_gap and the noise (squared).
        const float need = std::max(min_gap, noise_gap * p.z() * p.z()) * towards;
        if (!(rel.squaredNorm() * s * s > need * need)) continue;
        const float z = rel.dot(axis);
        if (!(z > min_depth)) continue;
        const float inv_z = 1.0f / z;
        const float gx = fxc * rel.dot(right) * inv_z + cxc, gy = fyc * rel.dot(down) * inv_z + cyc;
        if (!(gx >= 0.0f && gy >= 0.0f && gx < grid_w && gy < grid_h)) continue;
        const int i = static_cast<int>(gy) * grid_w_ + static_cast<int>(gx);  // truncation = floor here
        hit[i] = 255;
        nearest[i] = std::min(nearest[i], z);
        ++candidates_;
    }
}

void BeamBlanker::keepConnectedCells() {
    if (options_.filter_noise) {
        cv::morphologyEx(hit_, scratch_, cv::MORPH_CLOSE, cv::Mat());
        cv::morphologyEx(scratch_, kept_, cv::MORPH_OPEN, cv::Mat());
    } else {
        hit_.copyTo(kept_);
    }
}

bool BeamBlanker::growByMargins() {
    // Each kept cell grows by its margin: distance_ starts at -radius on kept cells (a cell
    // the closing filled takes the nearest depth of its 3x3) and the chamfer scans leave
    // d(q) = min over kept p of (octagonal distance p -> q - radius(p)), <= 0 = blanked.
    cv::erode(nearest_, near3_, cv::Mat());  // min over 3x3
    distance_.create(grid_h_, grid_w_, CV_32F);
    const float focal = static_cast<float>(std::max(projector_.fx(), projector_.fy()));
    const float margin = static_cast<float>(options_.ray_margin);
    const float min_depth = static_cast<float>(options_.min_depth);
    int x0 = grid_w_, y0 = grid_h_, x1 = -1, y1 = -1;
    float max_radius = 0.0f;
    for (int y = 0; y < grid_h_; ++y) {
        const uchar *k = kept_.ptr<uchar>(y);
        const float *z3 = near3_.ptr<float>(y);
        float *dist = distance_.ptr<float>(y);
        for (int x = 0; x < grid_w_; ++x) {
            if (!k[x]) {
                dist[x] = kInf;
                continue;
            }
            const float z = std::max(std::isfinite(z3[x]) ? z3[x] : min_depth, min_depth);
            const float r = static_cast<float>(marginCells(margin, focal, cell_, z, off_axis_));
            dist[x] = -r;
            max_radius = std::max(max_radius, r);
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    }
    if (x1 < 0) return false;
    const int reach = static_cast<int>(std::ceil(max_radius)) + 1;
    const cv::Rect roi = cv::Rect(x0 - reach, y0 - reach, x1 - x0 + 1 + 2 * reach, y1 - y0 + 1 + 2 * reach) &
                         cv::Rect(0, 0, grid_w_, grid_h_);
    cv::Mat dist_roi = distance_(roi);
    chamfer(dist_roi);
    grown_.create(grid_h_, grid_w_, CV_8U);
    grown_.setTo(0);
    cv::Mat grown_roi = grown_(roi);
    cv::compare(dist_roi, cv::Scalar(0.0), grown_roi, cv::CMP_LE);
    return true;
}

void BeamBlanker::writeMask() {
    // Back to framebuffer pixels: each cell covers cell_ x cell_ pixels.
    const int w = projector_.width, h = projector_.height;
    row_.resize(static_cast<std::size_t>(w));
    for (int gy = 0; gy * cell_ < h; ++gy) {
        const uchar *g = grown_.ptr<uchar>(gy + pad_) + pad_;
        for (int gx = 0; gx * cell_ < w; ++gx)
            std::memset(row_.data() + gx * cell_, g[gx], static_cast<std::size_t>(std::min(cell_, w - gx * cell_)));
        for (int y = gy * cell_; y < std::min(h, (gy + 1) * cell_); ++y)
            std::memcpy(mask_.ptr<uchar>(y), row_.data(), w);
    }
    // Blanked pixels, counted on the grid: each cell covers cell_ x cell_ pixels (clipped at
    // the framebuffer's right and bottom edges).
    long blanked = 0;
    for (int gy = 0; gy * cell_ < h; ++gy) {
        const uchar *g = grown_.ptr<uchar>(gy + pad_) + pad_;
        const int rows = std::min(cell_, h - gy * cell_);
        long cols = 0;
        for (int gx = 0; gx * cell_ < w; ++gx)
            if (g[gx]) cols += std::min(cell_, w - gx * cell_);
        blanked += cols * rows;
    }
    blanked_ = static_cast<int>(blanked);
}

void applyBlanking(cv::Mat &framebuffer, const cv::Mat &mask) {
    if (framebuffer.empty() || mask.empty()) return;
    CV_Assert(framebuffer.size() == mask.size() && mask.type() == CV_8U);
    framebuffer.setTo(cv::Scalar::all(0), mask);
}

}  // namespace projsurf
