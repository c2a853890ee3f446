#include "projsurf/keystone/keystone_warper.hpp"

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

#include "projsurf/keystone/keystone_remap.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#include <tmmintrin.h>
#endif

namespace projsurf {

namespace {

constexpr int kBits = 5;                      // source positions in 1/32 px, as OpenCV's INTER_BITS
constexpr int kSteps = 1 << kBits;            // 32
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

/// Per fast pixel, the bilinear weights as bytes: 32 - fx, fx, 32 - fy, fy (fx, fy in 1/32 px).
std::uint32_t packWeights(int fx, int fy) {
    return static_cast<std::uint32_t>((kSteps - fx) | fx << 8 | (kSteps - fy) << 16 | fy << 24);
}

/// Plain C++ for `CN` channels (0: `cn` at run time); the reference for the SIMD versions.
/// `idx` is the top-left neighbour's pixel index in the continuous picture, `row` the
/// picture's row length in bytes.
template <int CN>
void gatherScalar(const uchar *src, std::size_t row, const std::int32_t *idx, const std::uint32_t *wts, uchar *dst,
                  int n, int cn_runtime = CN) {
    const int cn = CN > 0 ? CN : cn_runtime;
    for (int i = 0; i < n; ++i) {
        const uchar *p = src + static_cast<std::size_t>(idx[i]) * cn;
        const std::uint32_t w = wts[i];
        const int wx0 = w & 0xff, wx1 = (w >> 8) & 0xff, wy0 = (w >> 16) & 0xff, wy1 = w >> 24;
        for (int c = 0; c < cn; ++c) {
            const int top = p[c] * wx0 + p[c + cn] * wx1;
            const int bottom = p[row + c] * wx0 + p[row + c + cn] * wx1;
            dst[c] = static_cast<uchar>((top * wy0 + bottom * wy1 + kRound) >> (2 * kBits));
        }
        dst += cn;
    }
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
// SSSE3 (pshufb, pmaddubsw) and AVX2, chosen at run time: the library is built for generic
// x86-64 (SSE2). On the 1280x800 BGR benchmark frame (bench/, KeystoneWarp) the SSSE3 blend
// takes about a third of the plain C++ loop's time and AVX2 (two pixels per step) about 20 %
// less again; CPUs without them take the plain path.
#define PROJSURF_WARP_SSSE3 1

bool haveSsse3() {
    static const bool have = [] {
        __builtin_cpu_init();  // in case the first warp runs before static constructors
        return __builtin_cpu_supports("ssse3") != 0;
    }();
    return have;
}

/// One pixel of 3 or 4 channels. `ab`: the top row's two neighbours in bytes 0..7 and the
/// bottom row's in bytes 8..15 (where `order` expects them). Horizontal blend of byte pairs
/// (left, right) with pmaddubsw, then vertical of 16-bit pairs (top, bottom) with pmaddwd:
/// the same integer sum as the scalar path. Returns the pixel in the low 3 or 4 bytes (the
/// 4th byte is 0 for 3 channels).
__attribute__((target("ssse3"), always_inline)) inline std::uint32_t blendSsse3(__m128i ab, __m128i order,
                                                                                std::uint32_t w) {
    const __m128i wv = _mm_cvtsi32_si128(static_cast<int>(w));
    const __m128i wx = _mm_shuffle_epi8(wv, _mm_setr_epi8(0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1));
    const __m128i wy = _mm_shuffle_epi8(wv, _mm_setr_epi8(2, -1, 3, -1, 2, -1, 3, -1, 2, -1, 3, -1, 2, -1, 3, -1));
    const __m128i h = _mm_maddubs_epi16(_mm_shuffle_epi8(ab, order), wx);  // <= 255 * 32 per lane
    __m128i s = _mm_madd_epi16(h, wy);
    s = _mm_srli_epi32(_mm_add_epi32(s, _mm_set1_epi32(kRound)), 2 * kBits);
    s = _mm_packs_epi32(s, s);
    return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(s, s)));
}

/// Pixel i of a 3-channel run. The top row is loaded from the pixel (8 bytes: a full row
/// follows, no overrun); the bottom row from 2 bytes early (its 6 wanted bytes may end the
/// picture), so its B0 is byte 10.
__attribute__((target("ssse3"), always_inline)) inline std::uint32_t pixel3Ssse3(const uchar *src, std::size_t row,
                                                                                 const std::int32_t *idx,
                                                                                 const std::uint32_t *wts, int i) {
    // Pairs (top left, top right), (bottom left, bottom right) per channel.
    const __m128i order = _mm_setr_epi8(0, 3, 10, 13, 1, 4, 11, 14, 2, 5, 12, 15, -1, -1, -1, -1);
    const uchar *p = src + static_cast<std::size_t>(idx[i]) * 3;
    const __m128i ab = _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)),
                                          _mm_loadl_epi64(reinterpret_cast<const __m128i *>(p + row - 2)));
    return blendSsse3(ab, order, wts[i]);
}

__attribute__((target("ssse3"))) void gather3Ssse3(const uchar *src, std::size_t row, const std::int32_t *idx,
                                                   const std::uint32_t *wts, uchar *dst, int n) {
    // 4-byte stores (the 4th byte is overwritten by the next pixel), 3 bytes for the last.
    // (No lambdas in here: they would not inherit the SSSE3 target.)
    int i = 0;
    for (; i + 1 < n; ++i, dst += 3) {
        const std::uint32_t px = pixel3Ssse3(src, row, idx, wts, i);
        std::memcpy(dst, &px, 4);
    }
    if (i < n) {
        const std::uint32_t px = pixel3Ssse3(src, row, idx, wts, i);
        std::memcpy(dst, &px, 3);
    }
}

bool haveAvx2() {
    static const bool have = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return have;
}

/// Two pixels per step: the SSSE3 blend in each 128-bit lane of AVX2 registers.
__attribute__((target("avx2"))) void gather3Avx2(const uchar *src, std::size_t row, const std::int32_t *idx,
                                                 const std::uint32_t *wts, uchar *dst, int n) {
    const __m256i order = _mm256_setr_epi8(0, 3, 10, 13, 1, 4, 11, 14, 2, 5, 12, 15, -1, -1, -1, -1,  //
                                           0, 3, 10, 13, 1, 4, 11, 14, 2, 5, 12, 15, -1, -1, -1, -1);
    // Weights of pixel i in bytes 0..3 of the broadcast pair, of pixel i + 1 in bytes 4..7.
    const __m256i wx_pick = _mm256_setr_epi8(0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1,  //
                                             4, 5, 4, 5, 4, 5, 4, 5, 4, 5, 4, 5, 4, 5, 4, 5);
    const __m256i wy_pick = _mm256_setr_epi8(2, -1, 3, -1, 2, -1, 3, -1, 2, -1, 3, -1, 2, -1, 3, -1,  //
                                             6, -1, 7, -1, 6, -1, 7, -1, 6, -1, 7, -1, 6, -1, 7, -1);
    const __m256i round = _mm256_set1_epi32(kRound);
    int i = 0;
    for (; i + 2 < n; i += 2, dst += 6) {  // leaves at least one pixel for the tail below
        const uchar *p0 = src + static_cast<std::size_t>(idx[i]) * 3;
        const uchar *p1 = src + static_cast<std::size_t>(idx[i + 1]) * 3;
        const __m128i ab0 = _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p0)),
                                               _mm_loadl_epi64(reinterpret_cast<const __m128i *>(p0 + row - 2)));
        const __m128i ab1 = _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p1)),
                                               _mm_loadl_epi64(reinterpret_cast<const __m128i *>(p1 + row - 2)));
        const __m256i ab = _mm256_inserti128_si256(_mm256_castsi128_si256(ab0), ab1, 1);
        const __m256i wv = _mm256_broadcastq_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(wts + i)));
        const __m256i h = _mm256_maddubs_epi16(_mm256_shuffle_epi8(ab, order), _mm256_shuffle_epi8(wv, wx_pick));
        __m256i sum = _mm256_madd_epi16(h, _mm256_shuffle_epi8(wv, wy_pick));
        sum = _mm256_srli_epi32(_mm256_add_epi32(sum, round), 2 * kBits);
        sum = _mm256_packs_epi32(sum, sum);
        sum = _mm256_packus_epi16(sum, sum);
        const std::uint32_t px0 = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm256_castsi256_si128(sum)));
        const std::uint32_t px1 = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm256_extracti128_si256(sum, 1)));
        std::memcpy(dst, &px0, 4);
        std::memcpy(dst + 3, &px1, 4);
    }
    gather3Ssse3(src, row, idx + i, wts + i, dst, n - i);  // the last one or two pixels
}

__attribute__((target("ssse3"))) void gather4Ssse3(const uchar *src, std::size_t row, const std::int32_t *idx,
                                                   const std::uint32_t *wts, uchar *dst, int n) {
    const __m128i order = _mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
    for (int i = 0; i < n; ++i, dst += 4) {
        const uchar *p = src + static_cast<std::size_t>(idx[i]) * 4;
        const __m128i ab = _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)),
                                              _mm_loadl_epi64(reinterpret_cast<const __m128i *>(p + row)));
        const std::uint32_t px = blendSsse3(ab, order, wts[i]);
        std::memcpy(dst, &px, 4);
    }
}
#endif

/// Source positions (1/32 px) of framebuffer pixels x0 .. x0 + n - 1 of row y, computed as
/// cv::warpPerspective does: M (framebuffer -> source) in double, cvRound of 32 X / W, and
/// W == 0 giving position 0.
void rowPositions(const cv::Matx33d &M, int y, int x0, int n, int *X, int *Y) {
    const double X0 = M(0, 1) * y + M(0, 2), Y0 = M(1, 1) * y + M(1, 2), W0 = M(2, 1) * y + M(2, 2);
    const double lo = static_cast<double>(INT_MIN), hi = static_cast<double>(INT_MAX);
    int i = 0;
#ifdef __SSE2__
    // Two pixels at a time; the same IEEE operations as the scalar loop below, and
    // _mm_cvtpd_epi32 rounds like cvRound (to nearest, ties to even).
    const __m128d m00 = _mm_set1_pd(M(0, 0)), m10 = _mm_set1_pd(M(1, 0)), m20 = _mm_set1_pd(M(2, 0));
    const __m128d vx0 = _mm_set1_pd(X0), vy0 = _mm_set1_pd(Y0), vw0 = _mm_set1_pd(W0);
    const __m128d steps = _mm_set1_pd(kSteps), zero = _mm_setzero_pd(), two = _mm_set1_pd(2.0);
    const __m128d vlo = _mm_set1_pd(lo), vhi = _mm_set1_pd(hi);
    __m128d xs = _mm_setr_pd(x0, x0 + 1.0);
    for (; i + 2 <= n; i += 2, xs = _mm_add_pd(xs, two)) {
        const __m128d w = _mm_add_pd(vw0, _mm_mul_pd(m20, xs));
        const __m128d iw = _mm_and_pd(_mm_cmpneq_pd(w, zero), _mm_div_pd(steps, w));
        const __m128d fx = _mm_max_pd(vlo, _mm_min_pd(vhi, _mm_mul_pd(_mm_add_pd(vx0, _mm_mul_pd(m00, xs)), iw)));
        const __m128d fy = _mm_max_pd(vlo, _mm_min_pd(vhi, _mm_mul_pd(_mm_add_pd(vy0, _mm_mul_pd(m10, xs)), iw)));
        _mm_storel_epi64(reinterpret_cast<__m128i *>(X + i), _mm_cvtpd_epi32(fx));
        _mm_storel_epi64(reinterpret_cast<__m128i *>(Y + i), _mm_cvtpd_epi32(fy));
    }
#endif
    for (; i < n; ++i) {
        const double x = x0 + i;
        double iw = W0 + M(2, 0) * x;
        iw = iw != 0.0 ? kSteps / iw : 0.0;
        X[i] = cvRound(std::max(lo, std::min(hi, (X0 + M(0, 0) * x) * iw)));
        Y[i] = cvRound(std::max(lo, std::min(hi, (Y0 + M(1, 0) * x) * iw)));
    }
}

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

ReducedSource reducedSource(const cv::Mat &picture, const Keystone &k) {
    if (picture.size() != k.picture)
        throw std::invalid_argument("keystone warp: the picture's size differs from the keystone's");
    const WarpSource source = warpSourceFor(k, picture.size());
    ReducedSource r{picture, source.homography};
    if (source.reduce) cv::resize(picture, r.image, source.size, 0, 0, cv::INTER_AREA);
    return r;
}

KeystoneWarper::KeystoneWarper(const Keystone &keystone, bool plan_all) : keystone_(keystone) {
    const int W = keystone_.framebuffer.width, H = keystone_.framebuffer.height;
    if (W < 1 || H < 1 || keystone_.picture.width < 1 || keystone_.picture.height < 1)
        throw std::invalid_argument("keystone warp: the keystone has an empty picture or framebuffer size");
    const WarpSource source = warpSourceFor(keystone_, keystone_.picture);
    reduce_ = source.reduce;
    source_ = source.size;
    inverse_ = source.homography.inv();  // framebuffer -> source, as warpPerspective
    const int w = source_.width, h = source_.height;

    // Columns worth visiting per row: the framebuffer image of the source rectangle widened to
    // [-1 - 1/16, w + 1/16] x [-1 - 1/16, h + 1/16], which holds every pixel whose footprint
    // touches the picture (a rounded position in [-1, w) needs X in [-1 - 1/64, w - 1/64]).
    // When that rectangle crosses the homography's line at infinity, every column is visited.
    const double lo = -1.0 - 1.0 / 16, hx = w + 1.0 / 16, hy = h + 1.0 / 16;
    const double cx[4] = {lo, hx, hx, lo}, cy[4] = {lo, lo, hy, hy};
    bounded_ = true;
    const cv::Vec3d q0 = source.homography * cv::Vec3d(cx[0], cy[0], 1.0);
    for (int i = 0; i < 4; ++i) {
        const cv::Vec3d q = source.homography * cv::Vec3d(cx[i], cy[i], 1.0);
        if (!(std::abs(q[2]) > 1e-12) || (q[2] > 0) != (q0[2] > 0)) bounded_ = false;
        quad_x_[i] = q[0] / q[2];
        quad_y_[i] = q[1] / q[2];
    }
    quad_y_min_ = *std::min_element(quad_y_, quad_y_ + 4);
    quad_y_max_ = *std::max_element(quad_y_, quad_y_ + 4);
    bounded_ = bounded_ && std::isfinite(quad_y_min_) && std::isfinite(quad_y_max_);

    span_begin_.assign(H, 0);
    span_end_.assign(H, 0);
    row_x_.resize(W);
    row_y_.resize(W);
    if (!plan_all) return;
    if (bounded_) {  // room for the quad's pixels (shoelace area) and its edges
        double area = 0.0, perimeter = 0.0;
        for (int i = 0; i < 4; ++i) {
            const int j = (i + 1) % 4;
            area += 0.5 * (quad_x_[i] * quad_y_[j] - quad_x_[j] * quad_y_[i]);
            perimeter += std::hypot(quad_x_[j] - quad_x_[i], quad_y_[j] - quad_y_[i]);
        }
        const double guess = std::min(static_cast<double>(W) * H, std::abs(area) + 2.0 * perimeter + 64.0);
        fast_idx_.reserve(static_cast<std::size_t>(guess));
        fast_w_.reserve(static_cast<std::size_t>(guess));
    }
    for (int y = 0; y < H; ++y) planRow(y);
}

KeystoneWarper::KeystoneWarper(const Keystone &keystone) : KeystoneWarper(keystone, true) {}

/// One framebuffer row being planned: the columns [x_first, x_last] it visits and their source
/// positions X, Y (1/32 px), against the size of the picture sampled.
struct KeystoneWarper::RowPlanner {
    KeystoneWarper &k;
    int y, x_first, x_last;
    const int *X, *Y;
    int w, h;

    /// Narrows the columns to where the row crosses the quad (2 px margin); false when it
    /// misses the quad.
    bool cropToQuad() {
        if (y < k.quad_y_min_ - 2 || y > k.quad_y_max_ + 2) return false;
        const double yc = std::clamp(static_cast<double>(y), k.quad_y_min_, k.quad_y_max_);
        const double *qx = k.quad_x_, *qy = k.quad_y_;
        double xa = HUGE_VAL, xb = -HUGE_VAL;
        for (int i = 0; i < 4; ++i) {
            const int j = (i + 1) % 4;
            if (yc < std::min(qy[i], qy[j]) || yc > std::max(qy[i], qy[j])) continue;
            const double x = qy[i] == qy[j] ? qx[i] : qx[i] + (yc - qy[i]) * (qx[j] - qx[i]) / (qy[j] - qy[i]);
            const double x2 = qy[i] == qy[j] ? qx[j] : x;
            xa = std::min({xa, x, x2});
            xb = std::max({xb, x, x2});
        }
        if (!(xa <= xb)) return false;
        const int W = k.keystone_.framebuffer.width;
        x_first = static_cast<int>(std::clamp(std::floor(xa) - 2.0, 0.0, W - 1.0));
        x_last = static_cast<int>(std::clamp(std::ceil(xb) + 2.0, 0.0, W - 1.0));
        return true;
    }
    // Lit: the bilinear footprint touches the picture (top-left neighbour in [-1, w-1]).
    bool lit(int i) const {
        const int sx = X[i] >> kBits, sy = Y[i] >> kBits;  // arithmetic shift: floor
        return sx >= -1 && sx <= w - 1 && sy >= -1 && sy <= h - 1;
    }
    // Fast: all four neighbours inside (top-left in [0, w-2] x [0, h-2]).
    bool fast(int i) const {
        const int sx = X[i] >> kBits, sy = Y[i] >> kBits;
        return sx >= 0 && sx <= w - 2 && sy >= 0 && sy <= h - 2;
    }
    void addSlow(int i) {
        k.slow_.push_back({y, x_first + i, X[i] >> kBits, Y[i] >> kBits, static_cast<std::uint8_t>(X[i] & (kSteps - 1)),
                           static_cast<std::uint8_t>(Y[i] & (kSteps - 1))});
    }
    /// Fast pixels [begin, end) as one run; false (and nothing added) if one is not fast.
    bool addRun(int begin, int end) {
        const std::size_t at = k.fast_idx_.size();
        k.fast_idx_.resize(at + (end - begin));
        k.fast_w_.resize(at + (end - begin));
        std::int32_t *idx = k.fast_idx_.data() + at;
        std::uint32_t *wts = k.fast_w_.data() + at;
        unsigned outside = 0;
        for (int i = begin; i < end; ++i) {
            const int sx = X[i] >> kBits, sy = Y[i] >> kBits;
            outside |= static_cast<unsigned>(sx > w - 2) | static_cast<unsigned>(sx < 0) |
                       static_cast<unsigned>(sy > h - 2) | static_cast<unsigned>(sy < 0);
            idx[i - begin] = sy * w + sx;
            wts[i - begin] = packWeights(X[i] & (kSteps - 1), Y[i] & (kSteps - 1));
        }
        if (outside) {
            k.fast_idx_.resize(at);
            k.fast_w_.resize(at);
            return false;
        }
        k.runs_.push_back({y, x_first + begin, end - begin, static_cast<int>(at)});
        return true;
    }
    /// Fast pixels in several runs (not expected: the positions are monotonic along a row);
    /// everything else in the lit span [lit_first, lit_last] on the slow path, black where unlit.
    void addRuns(int lit_first, int lit_last) {
        int run_start = -1;
        for (int i = lit_first; i <= lit_last + 1; ++i) {
            const bool in_run = i <= lit_last && fast(i);
            if (in_run && run_start < 0) run_start = i;
            if (!in_run && run_start >= 0) {
                addRun(run_start, i);
                run_start = -1;
            }
            if (!in_run && i <= lit_last) addSlow(i);
        }
    }
};

void KeystoneWarper::planRow(int y) {
    const int W = keystone_.framebuffer.width;
    RowPlanner row{*this, y, 0, W - 1, row_x_.data(), row_y_.data(), source_.width, source_.height};
    if (bounded_ && !row.cropToQuad()) return;
    const int n = row.x_last - row.x_first + 1;
    rowPositions(inverse_, y, row.x_first, n, row_x_.data(), row_y_.data());
    // The lit span from both ends, then the fast pixels inside it from both ends.
    int lit_first = 0, lit_last = n - 1;
    while (lit_first < n && !row.lit(lit_first)) ++lit_first;
    if (lit_first == n) return;
    while (!row.lit(lit_last)) --lit_last;
    span_begin_[y] = row.x_first + lit_first;
    span_end_[y] = row.x_first + lit_last + 1;
    int fast_first = lit_first, fast_last = lit_last;
    while (fast_first <= lit_last && !row.fast(fast_first)) ++fast_first;
    while (fast_last >= fast_first && !row.fast(fast_last)) --fast_last;
    if (fast_first > fast_last || row.addRun(fast_first, fast_last + 1)) {
        // The usual row: edge pixels, one run of fast ones, edge pixels.
        for (int i = lit_first; i < fast_first; ++i) row.addSlow(i);
        for (int i = std::max(fast_first, fast_last + 1); i <= lit_last; ++i) row.addSlow(i);
    } else {
        row.addRuns(lit_first, lit_last);
    }
}

const cv::Mat &KeystoneWarper::prepare(const cv::Mat &in, cv::Mat &framebuffer) {
    if (in.depth() != CV_8U) throw std::invalid_argument("keystone warp: the picture must be 8-bit per channel");
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
    return *src;
}

void KeystoneWarper::blend(const cv::Mat &src, cv::Mat &framebuffer, int y_begin, int y_end) const {
    const int cn = src.channels();
    const int W = keystone_.framebuffer.width;
    for (int y = y_begin; y < y_end; ++y) {  // black outside the lit span
        uchar *row = framebuffer.ptr<uchar>(y);
        std::memset(row, 0, static_cast<std::size_t>(span_begin_[y]) * cn);
        std::memset(row + static_cast<std::size_t>(span_end_[y]) * cn, 0,
                    static_cast<std::size_t>(W - span_end_[y]) * cn);
    }
    const uchar *base = src.ptr<uchar>();
    const std::size_t row_bytes = static_cast<std::size_t>(src.cols) * cn;
#ifdef PROJSURF_WARP_SSSE3
    const bool simd = simd_ != Simd::Plain && haveSsse3();
    const bool avx2 = simd && simd_ == Simd::Best && haveAvx2();
#endif
    for (const Run &r : runs_) {
        uchar *dst = framebuffer.ptr<uchar>(r.y) + static_cast<std::size_t>(r.x) * cn;
        const std::int32_t *idx = fast_idx_.data() + r.data;
        const std::uint32_t *wts = fast_w_.data() + r.data;
#ifdef PROJSURF_WARP_SSSE3
        if (simd && cn == 3) {
            if (avx2)
                gather3Avx2(base, row_bytes, idx, wts, dst, r.count);
            else
                gather3Ssse3(base, row_bytes, idx, wts, dst, r.count);
            continue;
        }
        if (simd && cn == 4) {
            gather4Ssse3(base, row_bytes, idx, wts, dst, r.count);
            continue;
        }
#endif
        switch (cn) {
        case 1: gatherScalar<1>(base, row_bytes, idx, wts, dst, r.count); break;
        case 3: gatherScalar<3>(base, row_bytes, idx, wts, dst, r.count); break;
        case 4: gatherScalar<4>(base, row_bytes, idx, wts, dst, r.count); break;
        default: gatherScalar<0>(base, row_bytes, idx, wts, dst, r.count, cn);
        }
    }
    for (const Slow &s : slow_)
        blendSlow(src, s.sx, s.sy, s.fx, s.fy, framebuffer.ptr<uchar>(s.y) + static_cast<std::size_t>(s.x) * cn);
}

void KeystoneWarper::warp(const cv::Mat &picture, cv::Mat &framebuffer) {
    if (!keystone_.remap.empty()) {  // a distorted projector: the warp is a remap
        framebuffer = remapToFramebuffer(picture, keystone_);
        return;
    }
    const cv::Mat in = picture;  // keeps the pixels alive even if `framebuffer` is the same Mat
    const cv::Mat &src = prepare(in, framebuffer);
    blend(src, framebuffer, 0, framebuffer.rows);
}

cv::Mat KeystoneWarper::warp(const cv::Mat &picture) {
    cv::Mat out;
    warp(picture, out);
    return out;
}

cv::Mat KeystoneWarper::warpOnce(const cv::Mat &picture, const Keystone &keystone, Simd simd) {
    // Plan a row, blend it, forget it: no per-pixel tables for the whole framebuffer.
    if (!keystone.remap.empty()) return remapToFramebuffer(picture, keystone);
    KeystoneWarper once(keystone, false);
    once.simd_ = simd;
    cv::Mat framebuffer;
    const cv::Mat &src = once.prepare(picture, framebuffer);
    for (int y = 0; y < framebuffer.rows; ++y) {
        once.runs_.clear();
        once.slow_.clear();
        once.fast_idx_.clear();
        once.fast_w_.clear();
        once.planRow(y);
        once.blend(src, framebuffer, y, y + 1);
    }
    return framebuffer;
}

}  // namespace projsurf
