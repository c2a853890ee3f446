#pragma once
// Structured light for projector calibration : Gray-code stripes of the framebuffer
// columns and rows, each with its inverse (a camera pixel's bit is whichever of the pair is
// brighter, so no global threshold), plus all-white and all-black. Decoding is per camera
// pixel; bits the camera cannot resolve (stripes finer than a camera pixel, blur) are left
// open and the pixel's projector coordinate is the centre of the range its resolved bits
// allow.
#include <Eigen/Core>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace projsurf {

/// One pattern: the framebuffer image and the name it is stored and captured under.
struct GrayPattern {
    std::string name;  ///< "white", "black", "col_<b>", "col_<b>_inv", "row_<b>", "row_<b>_inv"
    enum class Kind { White, Black, Column, Row } kind = Kind::White;
    int bit = 0;  ///< for Column/Row: bit index, most significant = bits - 1
    bool inverse = false;
};

/// The patterns in the order to project: white, black, then columns and rows from the most
/// significant bit, each followed by its inverse.
std::vector<GrayPattern> grayPatterns(int width, int height);
/// OpenCV's order (cv::structured_light::GrayCodePattern::generate, as procam-calibration
/// tools project it): columns then rows from the most significant bit, each followed by its
/// inverse, then white and black appended. The same images as grayPatterns, reordered.
std::vector<GrayPattern> openCvGrayPatterns(int width, int height);
/// Bits to code `n` values.
int grayBits(int n);
/// The 8-bit framebuffer image (width x height, CV_8UC1) of a pattern.
cv::Mat grayPatternImage(const GrayPattern &pattern, int width, int height);

struct GrayDecodeConfig {
    double min_contrast = 20.0;    ///< white - black, grey levels: below this the pixel is unlit or dark
    /// |pattern - inverse| a bit needs, share of the pixel's direct light (its largest
    /// |pattern - inverse|, a coarse stripe's): less, and inter-reflected light could flip it.
    double min_bit_margin = 0.25;
    /// |pattern - inverse| a bit needs, in the pixel's measured noise (the spread over the
    /// pairs of pattern + inverse - white - black, which complementary patterns make zero);
    /// 3 sigma: a pair with no light between them passes it one time in 740. The pixel's direct
    /// light must reach it too.
    double noise_sigmas = 3.0;
    int min_bits = 6;              ///< resolved most-significant bits needed per axis
    /// Camera px; > 0: pixels that do not decode alone are decoded again from the means of
    /// their (2 pool_px + 1)^2 neighbourhoods (noise that much smaller, position blurred by
    /// pool_px). 0: no second pass.
    int pool_px = 0;
};

/// Per camera pixel: the decoded framebuffer position (pixel centres at integers) or NaN.
struct GrayDecoding {
    cv::Mat column;      ///< CV_64F, framebuffer u, NaN where not decoded
    cv::Mat row;         ///< CV_64F, framebuffer v, NaN where not decoded
    /// CV_8U, 0 where not decoded; else the weakest resolved bit's |pattern - inverse| as a
    /// share of the pixel's direct light (its largest |pattern - inverse|), times 255 (pattern
    /// and inverse: independent of gamma and of ambient light, which both add to or scale the
    /// pair alike).
    cv::Mat confidence;
    /// CV_32F, grey levels: the pixel's direct light from the projector (its largest |pattern -
    /// inverse|), 0 where not decoded.
    cv::Mat direct;
    int decoded = 0;     ///< pixels with both
    int pooled = 0;      ///< of them, decoded from neighbourhood means (GrayDecodeConfig::pool_px)
};

/// `captures[i]` is the camera's grey (or colour: converted) image while grayPatterns(width,
/// height)[i] was projected; all of one size. Throws std::invalid_argument on a count or size
/// mismatch.
GrayDecoding decodeGray(const std::vector<cv::Mat> &captures, int width, int height,
                        const GrayDecodeConfig &config = {});
/// The same for captures in any order of the same set: `captures[i]` taken while `order[i]`
/// was projected (every column and row bit with its inverse, white and black, once each; else
/// std::invalid_argument).
GrayDecoding decodeGray(const std::vector<cv::Mat> &captures, const std::vector<GrayPattern> &order, int width,
                        int height, const GrayDecodeConfig &config = {});

}  // namespace projsurf
