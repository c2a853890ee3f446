#include "projsurf/core/beam_blanking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace projsurf {
namespace {

constexpr double kBucketRatio = 1.25;  ///< successive dilation radii differ by this factor
constexpr int kMaxBuckets = 40;

/// Grid cells of margin needed around a point `depth` m along the axis: the rays within
/// `margin` of it span margin * f / depth px (paraxial; off-axis pixels are smaller, so this
/// errs on the blanked side), plus 1.5 cells for the point's position inside its cell and
/// for the opening's ragged edge.
double marginCells(double margin, double focal_px, int cell, double depth) {
    return margin * focal_px / (cell * depth) + 1.5;
}

int bucketOf(double radius_cells) {
    const int b = static_cast<int>(std::ceil(std::log(radius_cells) / std::log(kBucketRatio)));
    return std::clamp(b, 0, kMaxBuckets - 1);
}

}  // namespace

BeamBlanker::BeamBlanker(const Projector &projector, const BlankingOptions &options)
    : projector_(projector), options_(options) {
    const double focal = std::max(projector_.fx(), projector_.fy());
    cell_ = std::max(1, static_cast<int>(std::lround(options_.cell_angle * focal)));
    pad_ = static_cast<int>(std::ceil(marginCells(options_.ray_margin, focal, cell_, options_.min_depth)));
    grid_w_ = (projector_.width + cell_ - 1) / cell_ + 2 * pad_;
    grid_h_ = (projector_.height + cell_ - 1) / cell_ + 2 * pad_;
    kernels_.resize(kMaxBuckets);
    for (int b = 0; b < kMaxBuckets; ++b) {
        const int r = static_cast<int>(std::ceil(std::pow(kBucketRatio, b)));
        kernels_[b] = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1));
    }
    mask_ = cv::Mat::zeros(projector_.height, projector_.width, CV_8U);
}

const cv::Mat &BeamBlanker::compute(const Cloud &cloud, const Plane &plane) {
    hit_.create(grid_h_, grid_w_, CV_8U);
    hit_.setTo(0);
    nearest_.create(grid_h_, grid_w_, CV_32F);
    nearest_.setTo(std::numeric_limits<float>::infinity());
    mask_.setTo(0);
    blanked_ = 0;
    candidates_ = 0;

    const Eigen::Vector3f o = projector_.origin.cast<float>();
    const Eigen::Vector3f axis = projector_.direction.normalized().cast<float>();
    const Eigen::Vector3f right = projector_.right().cast<float>(), down = projector_.down().cast<float>();
    const Eigen::Vector3f n = plane.normal.cast<float>();
    const float d = static_cast<float>(plane.d);
    const float lens_side = n.dot(o) + d;  // signed distance of the lens from the plane
    if (!(lens_side > 0.0f)) return mask_;
    const float fx = static_cast<float>(projector_.fx()), fy = static_cast<float>(projector_.fy());
    const float cx = static_cast<float>(projector_.cx()), cy = static_cast<float>(projector_.cy());
    const float inv_cell = 1.0f / cell_, min_gap = static_cast<float>(options_.min_gap);
    const float min_depth = static_cast<float>(options_.min_depth);
    const float pad = static_cast<float>(pad_);

    // One pass: the noise histogram (|distance| / z^2 of the points near the plane) and the
    // points the contract's rule alone would count.
    constexpr int kBins = 2000;
    constexpr float kBin = 1e-5f;  // 1/m per bin: sigma_k up to 0.013 (Kinect v1 ~0.0025)
    histogram_.assign(kBins, 0);
    found_.clear();
    const float window = static_cast<float>(options_.noise_window);
    int *hist = histogram_.data();
    int near_points = 0;
    for (const Point &p : cloud.points) {
        const float s = n.dot(p) + d;  // > 0: camera side of the plane (NaN fails every test)
        const float a = std::abs(s);
        if (a < window && p.z() > 0.1f) {
            hist[std::min(kBins - 1, static_cast<int>(a / (p.z() * p.z() * kBin)))]++;
            ++near_points;
        }
        if (!(s > 0.0f)) continue;
        const float towards = lens_side - s;  // > 0: the ray lens -> p goes on to meet the plane
        if (!(towards > 0.0f)) continue;
        const Eigen::Vector3f rel = p - o;
        // Along the ray, the plane lies at lens_side / towards times rel: the gap between p
        // and the plane is |rel| * s / towards.
        const float gap = rel.norm() * s / towards;
        if (!(gap > min_gap)) continue;
        const float z = rel.dot(axis);
        if (!(z > min_depth)) continue;
        const float u = cx + fx * rel.dot(right) / z, v = cy + fy * rel.dot(down) / z;
        const float gx = std::floor((u + 0.5f) * inv_cell) + pad, gy = std::floor((v + 0.5f) * inv_cell) + pad;
        if (!(gx >= 0.0f && gy >= 0.0f && gx < grid_w_ && gy < grid_h_)) continue;
        found_.push_back({static_cast<int>(gy) * grid_w_ + static_cast<int>(gx), z, gap, p.z()});
    }
    noise_k_ = 0.0;
    if (near_points >= 500) {
        int seen = 0, b = 0;
        while (b < kBins && 2 * (seen + hist[b]) < near_points) seen += hist[b++];
        noise_k_ = 1.4826 * (b + 0.5) * kBin;  // median absolute deviation about the plane -> sigma
    }
    const float noise_gap = static_cast<float>(options_.noise_sigmas * noise_k_);
    uchar *hit = hit_.ptr<uchar>();
    float *nearest = nearest_.ptr<float>();
    for (const Candidate &c : found_) {
        if (!(c.gap > noise_gap * c.camera_z * c.camera_z)) continue;
        hit[c.cell] = 255;
        nearest[c.cell] = std::min(nearest[c.cell], c.depth);
        ++candidates_;
    }
    if (candidates_ == 0) return mask_;

    if (options_.filter_noise) {
        cv::morphologyEx(hit_, scratch_, cv::MORPH_CLOSE, cv::Mat());
        cv::morphologyEx(scratch_, kept_, cv::MORPH_OPEN, cv::Mat());
    } else {
        hit_.copyTo(kept_);
    }

    // A closed cell that had no point of its own takes the nearest depth of its 3x3.
    cv::Mat near3;
    cv::erode(nearest_, near3, cv::Mat());  // min over 3x3
    bucket_.create(grid_h_, grid_w_, CV_8U);
    bucket_.setTo(0);
    std::array<cv::Rect, kMaxBuckets> boxes{};
    std::array<bool, kMaxBuckets> used{};
    const double focal = std::max(projector_.fx(), projector_.fy());
    for (int y = 0; y < grid_h_; ++y) {
        const uchar *k = kept_.ptr<uchar>(y);
        const float *z3 = near3.ptr<float>(y);
        uchar *b = bucket_.ptr<uchar>(y);
        for (int x = 0; x < grid_w_; ++x) {
            if (!k[x]) continue;
            const float z = std::isfinite(z3[x]) ? z3[x] : min_depth;
            const int bi = bucketOf(marginCells(options_.ray_margin, focal, cell_, std::max(z, min_depth)));
            b[x] = static_cast<uchar>(bi + 1);
            const cv::Rect one(x, y, 1, 1);
            boxes[bi] = used[bi] ? (boxes[bi] | one) : one;
            used[bi] = true;
        }
    }
    grown_.create(grid_h_, grid_w_, CV_8U);
    grown_.setTo(0);
    const cv::Rect grid(0, 0, grid_w_, grid_h_);
    for (int bi = 0; bi < kMaxBuckets; ++bi) {
        if (!used[bi]) continue;
        const int r = kernels_[bi].cols / 2;
        const cv::Rect roi = cv::Rect(boxes[bi].x - r, boxes[bi].y - r, boxes[bi].width + 2 * r, boxes[bi].height + 2 * r) & grid;
        cv::compare(bucket_(roi), cv::Scalar(bi + 1), tmp_, cv::CMP_EQ);
        cv::dilate(tmp_, tmp_, kernels_[bi], cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
        cv::Mat dst = grown_(roi);
        cv::bitwise_or(dst, tmp_, dst);
    }

    // Back to framebuffer pixels: each cell covers cell_ x cell_ pixels.
    const cv::Rect inner(pad_, pad_, grid_w_ - 2 * pad_, grid_h_ - 2 * pad_);
    cv::resize(grown_(inner), full_, cv::Size(inner.width * cell_, inner.height * cell_), 0, 0, cv::INTER_NEAREST);
    full_(cv::Rect(0, 0, projector_.width, projector_.height)).copyTo(mask_);
    blanked_ = cv::countNonZero(mask_);
    return mask_;
}

void applyBlanking(cv::Mat &framebuffer, const cv::Mat &mask) {
    if (framebuffer.empty() || mask.empty()) return;
    CV_Assert(framebuffer.size() == mask.size() && mask.type() == CV_8U);
    framebuffer.setTo(cv::Scalar::all(0), mask);
}

}  // namespace projsurf
