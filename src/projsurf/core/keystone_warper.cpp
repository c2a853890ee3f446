#include "projsurf/core/keystone_warper.hpp"

// How the result relates to cv::warpPerspective (INTER_LINEAR, BORDER_CONSTANT 0), which is
// what warpToFramebuffer used before: OpenCV maps each framebuffer pixel through the inverse
// homography in double, rounds the source position to 1/32 px (cvRound of 32 X), and blends
// the four neighbours with weights (32 - fx)(32 - fy), fx (32 - fy), ... scaled by 32 and
// rounded with + 2^14 >> 15; neighbours outside the picture count as 0. The weights are exact
// products of the 1/32 fractions, so blending with the unscaled products and + 512 >> 10 gives
// the same integer. The positions are computed the same way (double, same formula), so the
// only differences come from a position within floating-point noise of a 1/32 px boundary
// (OpenCV sums its terms per block of pixels, we per pixel): there the sample moves by 1/32 px.

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define PROJSURF_WARP_SSE2 1
#endif

namespace projsurf {

namespace {

constexpr int kBits = 5;             // source positions in 1/32 px, as OpenCV's INTER_BITS
constexpr int kSteps = 1 << kBits;   // 32
constexpr int kRound = 1 << (2 * kBits - 1);  // the weights of a pixel sum to 32 * 32

std::string sizeText(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

/// Any channel count, any position: neighbours outside the picture are black.
void blendSlow(const cv::Mat &src, int sx, int sy, int fx, int fy, uchar *out) {
    const int cn = src.channels();
    const int wgt[4] = {(kSteps - fx) * (kSteps - fy), fx * (kSteps - fy), (kSteps - fx) * fy, fx * fy};
    const int nx[4] = {sx, sx + 1, sx, sx + 1}, ny[4] = {sy, sy, sy + 1, sy + 1};
    for (int c = 0; c < cn; ++c) {
        int sum = 0;
        for (int i = 0; i < 4; ++i)
            if (nx[i] >= 0 && nx[i] < src.cols && ny[i] >= 0 && ny[i] < src.rows)
                sum += wgt[i] * src.ptr<uchar>(ny[i])[nx[i] * cn + c];
        out[c] = static_cast<uchar>((sum + kRound) >> (2 * kBits));
    }
}

/// Plain C++ for `CN` channels (the reference for the SIMD versions below). `idx` is the
/// top-left neighbour's pixel index in the continuous picture, `row` its row length in bytes.
template <int CN>
void gatherScalar(const uchar *src, std::size_t row, const std::int32_t *idx, const std::uint16_t *fxy, uchar *dst,
                  int n, int cn_runtime = CN) {
    const int cn = CN > 0 ? CN : cn_runtime;
    for (int i = 0; i < n; ++i) {
        const uchar *p = src + static_cast<std::size_t>(idx[i]) * cn;
        const int fx = fxy[i] & 0xff, fy = fxy[i] >> 8;
        for (int c = 0; c < cn; ++c) {
            const int top = p[c] * (kSteps - fx) + p[c + cn] * fx;
            const int bottom = p[row + c] * (kSteps - fx) + p[row + c + cn] * fx;
            dst[c] = static_cast<uchar>((top * (kSteps - fy) + bottom * fy + kRound) >> (2 * kBits));
        }
        dst += cn;
    }
}

#ifdef PROJSURF_WARP_SSE2
/// Broadcast weights per 1/32 px fraction: 16-bit (32 - f) and f for the vertical blend,
/// 16-bit pairs (32 - f, f) for the horizontal one (_mm_madd_epi16).
struct Sse2Weights {
    __m128i top[kSteps], bottom[kSteps], pair[kSteps];
};
const Sse2Weights &sse2Weights() {
    static const Sse2Weights w = [] {
        Sse2Weights t;
        for (int f = 0; f < kSteps; ++f) {
            t.top[f] = _mm_set1_epi16(static_cast<short>(kSteps - f));
            t.bottom[f] = _mm_set1_epi16(static_cast<short>(f));
            t.pair[f] = _mm_set1_epi32((f << 16) | (kSteps - f));
        }
        return t;
    }();
    return w;
}

/// One pixel of 3 or 4 channels: `a`, `b` hold the left and right neighbours of the top and
/// bottom rows as 16-bit lanes (left in lanes 0..CN-1, right from lane CN). Returns the
/// blended pixel in the low CN bytes.
template <int CN>
inline std::uint32_t blendSse2(__m128i a, __m128i b, const Sse2Weights &w, int fx, int fy) {
    // Vertical: at most 255 * 32, fits 16 bits.
    const __m128i v = _mm_add_epi16(_mm_mullo_epi16(a, w.top[fy]), _mm_mullo_epi16(b, w.bottom[fy]));
    // Horizontal: (left, right) 16-bit pairs per channel -> 32-bit sums.
    const __m128i pairs = _mm_unpacklo_epi16(v, _mm_srli_si128(v, 2 * CN));
    __m128i s = _mm_madd_epi16(pairs, w.pair[fx]);
    s = _mm_srli_epi32(_mm_add_epi32(s, _mm_set1_epi32(kRound)), 2 * kBits);
    s = _mm_packs_epi32(s, s);
    s = _mm_packus_epi16(s, s);
    return static_cast<std::uint32_t>(_mm_cvtsi128_si32(s));
}

void gather3Sse2(const uchar *src, std::size_t row, const std::int32_t *idx, const std::uint16_t *fxy, uchar *dst,
                 int n, const Sse2Weights &w) {
    const __m128i zero = _mm_setzero_si128();
    auto pixel = [&](int i) {
        const uchar *p = src + static_cast<std::size_t>(idx[i]) * 3;
        // 8-byte loads: the top row from p (a full row follows it, so no overrun); the bottom
        // row from 2 bytes early (its 6 wanted bytes may end the picture), shifted back.
        const __m128i a = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)), zero);
        const __m128i b = _mm_srli_si128(
            _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p + row - 2)), zero), 4);
        return blendSse2<3>(a, b, w, fxy[i] & 0xff, fxy[i] >> 8);
    };
    // 4-byte stores (the 4th byte is overwritten by the next pixel), 3 bytes for the last.
    for (int i = 0; i + 1 < n; ++i, dst += 3) {
        const std::uint32_t px = pixel(i);
        std::memcpy(dst, &px, 4);
    }
    if (n > 0) {
        const std::uint32_t px = pixel(n - 1);
        std::memcpy(dst, &px, 3);
    }
}

void gather4Sse2(const uchar *src, std::size_t row, const std::int32_t *idx, const std::uint16_t *fxy, uchar *dst,
                 int n, const Sse2Weights &w) {
    const __m128i zero = _mm_setzero_si128();
    for (int i = 0; i < n; ++i) {
        const uchar *p = src + static_cast<std::size_t>(idx[i]) * 4;
        const __m128i a = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)), zero);
        const __m128i b = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p + row)), zero);
        const std::uint32_t px = blendSse2<4>(a, b, w, fxy[i] & 0xff, fxy[i] >> 8);
        std::memcpy(dst, &px, 4);
        dst += 4;
    }
}
#endif

}  // namespace

WarpSource warpSourceFor(const Keystone &k, cv::Size picture) {
    WarpSource s;
    s.size = picture;
    s.homography = k.homography;
    // The least-shrunk edge of the picture; below half size, area-average first.
    const double sx[4] = {-0.5, picture.width - 0.5, picture.width - 0.5, -0.5};
    const double sy[4] = {-0.5, -0.5, picture.height - 0.5, picture.height - 0.5};
    double scale = 0.0;
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        const double src_len = std::hypot(sx[j] - sx[i], sy[j] - sy[i]);
        scale = std::max(scale, (k.picture_px[j] - k.picture_px[i]).norm() / src_len);
    }
    if (scale < 0.5) {
        const int w2 = std::max(1, static_cast<int>(std::lround(picture.width * scale)));
        const int h2 = std::max(1, static_cast<int>(std::lround(picture.height * scale)));
        const double fx = static_cast<double>(w2) / picture.width, fy = static_cast<double>(h2) / picture.height;
        // small-picture coordinates x' = (x + 0.5) fx - 0.5; H' = H S^-1
        const cv::Matx33d S_inv(1.0 / fx, 0, (0.5 - 0.5 * fx) / fx, 0, 1.0 / fy, (0.5 - 0.5 * fy) / fy, 0, 0, 1);
        s.reduce = true;
        s.size = cv::Size(w2, h2);
        s.homography = k.homography * S_inv;
    }
    return s;
}

KeystoneWarper::KeystoneWarper(const Keystone &keystone) : keystone_(keystone) {
    const int W = keystone_.framebuffer.width, H = keystone_.framebuffer.height;
    if (W < 1 || H < 1 || keystone_.picture.width < 1 || keystone_.picture.height < 1)
        throw std::invalid_argument("keystone warp: the keystone has an empty picture or framebuffer size");
    const WarpSource source = warpSourceFor(keystone_, keystone_.picture);
    reduce_ = source.reduce;
    source_ = source.size;
    const int w = source_.width, h = source_.height;
    const cv::Matx33d M = source.homography.inv();  // framebuffer -> source, as warpPerspective

    // Columns worth visiting per row: the framebuffer image of the source rectangle widened to
    // [-1 - 1/16, w + 1/16] x [-1 - 1/16, h + 1/16], which holds every pixel whose footprint
    // touches the picture (a rounded position in [-1, w) needs X in [-1 - 1/64, w - 1/64]).
    // When that rectangle crosses the homography's line at infinity, every column is visited.
    const double lo = -1.0 - 1.0 / 16, hx = w + 1.0 / 16, hy = h + 1.0 / 16;
    const double cx[4] = {lo, hx, hx, lo}, cy[4] = {lo, lo, hy, hy};
    double qx[4], qy[4];
    bool bounded = true;
    for (int i = 0; i < 4; ++i) {
        const cv::Vec3d q = source.homography * cv::Vec3d(cx[i], cy[i], 1.0);
        const cv::Vec3d q0 = source.homography * cv::Vec3d(cx[0], cy[0], 1.0);
        if (!(std::abs(q[2]) > 1e-12) || (q[2] > 0) != (q0[2] > 0)) bounded = false;
        qx[i] = q[0] / q[2];
        qy[i] = q[1] / q[2];
    }
    const double y_min = *std::min_element(qy, qy + 4), y_max = *std::max_element(qy, qy + 4);
    bounded = bounded && std::isfinite(y_min) && std::isfinite(y_max);

    span_begin_.assign(H, 0);
    span_end_.assign(H, 0);
    const std::size_t guess = static_cast<std::size_t>(W) * H / 2;
    fast_idx_.reserve(guess);
    fast_fxy_.reserve(guess);
    for (int y = 0; y < H; ++y) {
        int x_first = 0, x_last = W - 1;
        if (bounded) {
            if (y < y_min - 2 || y > y_max + 2) continue;
            const double yc = std::clamp(static_cast<double>(y), y_min, y_max);
            double xa = HUGE_VAL, xb = -HUGE_VAL;
            for (int i = 0; i < 4; ++i) {
                const int j = (i + 1) % 4;
                if (yc < std::min(qy[i], qy[j]) || yc > std::max(qy[i], qy[j])) continue;
                const double x = qy[i] == qy[j] ? qx[i] : qx[i] + (yc - qy[i]) * (qx[j] - qx[i]) / (qy[j] - qy[i]);
                const double x2 = qy[i] == qy[j] ? qx[j] : x;
                xa = std::min({xa, x, x2});
                xb = std::max({xb, x, x2});
            }
            if (!(xa <= xb)) continue;
            x_first = static_cast<int>(std::clamp(std::floor(xa) - 2.0, 0.0, W - 1.0));
            x_last = static_cast<int>(std::clamp(std::ceil(xb) + 2.0, 0.0, W - 1.0));
        }
        // Source positions exactly as cv::warpPerspective computes them.
        const double X0 = M(0, 1) * y + M(0, 2), Y0 = M(1, 1) * y + M(1, 2), W0 = M(2, 1) * y + M(2, 2);
        int lit_begin = -1, lit_end = -1;
        int run_start = -1;
        const std::size_t slow_row_start = slow_.size();
        auto closeRun = [&](int x_end) {
            if (run_start < 0) return;
            const int count = x_end - run_start;
            runs_.push_back({y, run_start, count, static_cast<int>(fast_idx_.size()) - count});
            run_start = -1;
        };
        for (int x = x_first; x <= x_last; ++x) {
            double iw = W0 + M(2, 0) * x;
            iw = iw != 0.0 ? kSteps / iw : 0.0;
            const double fX = std::max(static_cast<double>(INT_MIN), std::min(static_cast<double>(INT_MAX), (X0 + M(0, 0) * x) * iw));
            const double fY = std::max(static_cast<double>(INT_MIN), std::min(static_cast<double>(INT_MAX), (Y0 + M(1, 0) * x) * iw));
            const int X = cvRound(fX), Y = cvRound(fY);
            const int sx = X >> kBits, sy = Y >> kBits;  // arithmetic shift: floor
            const int fx = X & (kSteps - 1), fy = Y & (kSteps - 1);
            const bool lit = sx >= -1 && sx <= w - 1 && sy >= -1 && sy <= h - 1;
            const bool fast = sx >= 0 && sx <= w - 2 && sy >= 0 && sy <= h - 2;
            if (lit) {
                if (lit_begin < 0) lit_begin = x;
                lit_end = x + 1;
            }
            if (fast) {
                if (run_start < 0) run_start = x;
                fast_idx_.push_back(sy * w + sx);
                fast_fxy_.push_back(static_cast<std::uint16_t>(fx | fy << 8));
            } else {
                closeRun(x);
                // Kept only when inside the lit span (trimmed below); an unlit pixel between
                // lit ones (not expected: the positions are monotonic along a row) comes out black.
                slow_.push_back({y, x, sx, sy, static_cast<std::uint8_t>(fx), static_cast<std::uint8_t>(fy)});
            }
        }
        closeRun(x_last + 1);
        if (lit_begin < 0) {
            slow_.resize(slow_row_start);
            continue;
        }
        span_begin_[y] = lit_begin;
        span_end_[y] = lit_end;
        slow_.erase(std::remove_if(slow_.begin() + static_cast<std::ptrdiff_t>(slow_row_start), slow_.end(),
                                   [&](const Slow &s) { return s.x < lit_begin || s.x >= lit_end; }),
                    slow_.end());
    }
    fast_idx_.shrink_to_fit();
    fast_fxy_.shrink_to_fit();
}

void KeystoneWarper::warp(const cv::Mat &picture, cv::Mat &framebuffer) {
    const cv::Mat in = picture;  // keeps the pixels alive even if `framebuffer` is the same Mat
    if (in.depth() != CV_8U)
        throw std::invalid_argument("keystone warp: the picture must be 8-bit per channel");
    if (in.size() != keystone_.picture)
        throw std::invalid_argument("keystone warp: the picture is " + sizeText(in.size()) +
                                    " but the keystone was computed for " + sizeText(keystone_.picture));
    const cv::Mat *src = &in;
    if (reduce_) {
        cv::resize(in, reduced_, source_, 0, 0, cv::INTER_AREA);
        src = &reduced_;
    } else if (!in.isContinuous()) {
        in.copyTo(contiguous_);
        src = &contiguous_;
    }
    // Never write into the pixels being read.
    if (framebuffer.data && framebuffer.datastart < in.dataend && in.datastart < framebuffer.dataend)
        framebuffer.release();
    framebuffer.create(keystone_.framebuffer, in.type());

    const int cn = in.channels();
    const int W = keystone_.framebuffer.width;
    for (int y = 0; y < framebuffer.rows; ++y) {
        uchar *row = framebuffer.ptr<uchar>(y);
        std::memset(row, 0, static_cast<std::size_t>(span_begin_[y]) * cn);
        std::memset(row + static_cast<std::size_t>(span_end_[y]) * cn, 0, static_cast<std::size_t>(W - span_end_[y]) * cn);
    }
    const uchar *base = src->ptr<uchar>();
    const std::size_t row_bytes = static_cast<std::size_t>(src->cols) * cn;
#ifdef PROJSURF_WARP_SSE2
    const Sse2Weights &weights = sse2Weights();
#endif
    for (const Run &r : runs_) {
        uchar *dst = framebuffer.ptr<uchar>(r.y) + static_cast<std::size_t>(r.x) * cn;
        const std::int32_t *idx = fast_idx_.data() + r.data;
        const std::uint16_t *fxy = fast_fxy_.data() + r.data;
        switch (cn) {
        case 1:
            gatherScalar<1>(base, row_bytes, idx, fxy, dst, r.count);
            break;
#ifdef PROJSURF_WARP_SSE2
        case 3:
            gather3Sse2(base, row_bytes, idx, fxy, dst, r.count, weights);
            break;
        case 4:
            gather4Sse2(base, row_bytes, idx, fxy, dst, r.count, weights);
            break;
#else
        case 3:
            gatherScalar<3>(base, row_bytes, idx, fxy, dst, r.count);
            break;
        case 4:
            gatherScalar<4>(base, row_bytes, idx, fxy, dst, r.count);
            break;
#endif
        default:
            gatherScalar<0>(base, row_bytes, idx, fxy, dst, r.count, cn);
        }
    }
    for (const Slow &s : slow_)
        blendSlow(*src, s.sx, s.sy, s.fx, s.fy, framebuffer.ptr<uchar>(s.y) + static_cast<std::size_t>(s.x) * cn);
}

cv::Mat KeystoneWarper::warp(const cv::Mat &picture) {
    cv::Mat out;
    warp(picture, out);
    return out;
}

}  // namespace projsurf
