#pragma once
// The keystone warp for many pictures shown with one Keystone (a video, a steady detection):
// where each framebuffer pixel samples the picture is worked out once, so a frame costs only
// the bilinear gather over the pixels inside the picture's quad.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/keystone/keystone.hpp"

namespace projsurf {

/// What the warp samples: pictures shrunk below half size (the least-shrunk edge of the picture
/// under the homography) are first reduced with area averaging (cv::INTER_AREA) to `size`,
/// and `homography` maps that reduced picture into the framebuffer. For other pictures
/// `reduce` is false, `size` the picture's and `homography` the keystone's.
struct WarpSource {
    bool reduce = false;
    cv::Size size;
    cv::Matx33d homography;
};
WarpSource warpSourceFor(const Keystone &keystone, cv::Size picture);

/// What the one-off warps (warpToFramebuffer, remapToFramebuffer) sample: `picture` itself or
/// its area-reduced copy (warpSourceFor), and the homography from that image into the
/// framebuffer. A picture of another size than keystone.picture: std::invalid_argument.
struct ReducedSource {
    cv::Mat image;
    cv::Matx33d homography;
};
ReducedSource reducedSource(const cv::Mat &picture, const Keystone &keystone);

/// Warps pictures of `keystone.picture`'s size into its framebuffer; the result equals
/// cv::warpPerspective(picture, keystone.homography, INTER_LINEAR, BORDER_CONSTANT 0) after the
/// same area-averaging prepass as warpToFramebuffer (pictures shrunk below half size), up to
/// the rounding of source positions (see keystone_warper.cpp).
///
/// Construction computes every framebuffer pixel's source position once (1/32 px fixed point,
/// like OpenCV's remap), only for the pixels whose bilinear footprint touches the picture;
/// the rest of the framebuffer is black. The tables take 8 bytes per such pixel (about 5.5 MB
/// for a picture filling most of a 1280x800 framebuffer). One object must not warp from two
/// threads at once (it keeps a scratch image for the prepass).
class KeystoneWarper {
public:
    explicit KeystoneWarper(const Keystone &keystone);

    /// `picture`: 8-bit, any number of channels, of the keystone's picture size, else
    /// std::invalid_argument. `framebuffer` is (re)allocated to the keystone's framebuffer
    /// size and the picture's type, and every one of its pixels is written. Fast paths for 1,
    /// 3 and 4 channels (SIMD when the CPU has it, see Simd; plain C++ otherwise).
    void warp(const cv::Mat &picture, cv::Mat &framebuffer);
    cv::Mat warp(const cv::Mat &picture);

    /// How the blend runs for 3- and 4-channel pictures. Best: AVX2 (two pixels per step, 3
    /// channels) or SSSE3, whichever the CPU has (checked at run time; the library is built for
    /// generic x86-64), else plain C++. The others are for tests and benchmarks: at most SSSE3,
    /// or plain C++ only. Every choice gives the same pixels.
    enum class Simd { Best, Ssse3, Plain };
    void setSimd(Simd simd) { simd_ = simd; }

    /// One picture with a keystone used once: the same result as KeystoneWarper(keystone)
    /// .warp(picture), but each row's source positions are blended as soon as they are worked
    /// out (no tables for the whole framebuffer). warpToFramebuffer uses this.
    static cv::Mat warpOnce(const cv::Mat &picture, const Keystone &keystone, Simd simd = Simd::Best);

    const Keystone &keystone() const { return keystone_; }
    /// Framebuffer pixels that sample the picture (the rest stay black).
    std::size_t pixelsInside() const { return fast_idx_.size() + slow_.size(); }

private:
    /// Consecutive framebuffer pixels of one row whose four bilinear neighbours are all inside
    /// the picture; their data starts at fast_idx_[data].
    struct Run {
        int y, x, count, data;
    };
    /// A pixel at the picture's edge: some neighbours are outside and count as black.
    struct Slow {
        int y, x;
        int sx, sy;           ///< top-left neighbour, picture pixels (may be -1)
        std::uint8_t fx, fy;  ///< position inside the cell, 1/32 px
    };

    KeystoneWarper(const Keystone &keystone, bool plan_all);
    void planRow(int y);  ///< appends row y's span, run and edge pixels
    struct RowPlanner;    ///< one row being planned (keystone_warper.cpp)
    /// Checks the picture, reduces it or makes it continuous if needed, (re)allocates the
    /// framebuffer; returns what to sample.
    const cv::Mat &prepare(const cv::Mat &picture, cv::Mat &framebuffer);
    /// Blends the planned runs and edge pixels; black outside the spans of rows [y_begin, y_end).
    void blend(const cv::Mat &src, cv::Mat &framebuffer, int y_begin, int y_end) const;

    Keystone keystone_;
    bool reduce_ = false;  ///< area-average the picture to source_ first
    Simd simd_ = Simd::Best;
    cv::Size source_;      ///< the size the positions refer to (the picture, or its reduction)
    cv::Matx33d inverse_;  ///< framebuffer -> source
    bool bounded_ = true;  ///< the quad below is finite (else every column is visited)
    double quad_x_[4] = {}, quad_y_[4] = {}, quad_y_min_ = 0, quad_y_max_ = 0;  ///< where lit pixels can be
    std::vector<int> row_x_, row_y_;          ///< scratch: one row's source positions, 1/32 px
    std::vector<int> span_begin_, span_end_;  ///< per framebuffer row: pixels [begin, end) may be lit
    std::vector<Run> runs_;
    std::vector<std::int32_t> fast_idx_;  ///< sy * source_.width + sx of the top-left neighbour
    std::vector<std::uint32_t> fast_w_;   ///< weight bytes 32 - fx, fx, 32 - fy, fy (1/32 px)
    std::vector<Slow> slow_;
    cv::Mat reduced_, contiguous_;  ///< scratch: the area-averaged picture; a continuous copy
};

}  // namespace projsurf
