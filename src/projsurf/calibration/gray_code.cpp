#include "projsurf/calibration/gray_code.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/greyscale.hpp"

namespace projsurf {

int grayBits(int n) {
    int b = 1;
    while ((1 << b) < n) ++b;
    return b;
}

std::vector<GrayPattern> grayPatterns(int width, int height) {
    std::vector<GrayPattern> out;
    out.push_back({"white", GrayPattern::Kind::White, 0, false});
    out.push_back({"black", GrayPattern::Kind::Black, 0, false});
    for (int axis = 0; axis < 2; ++axis) {
        const int bits = grayBits(axis == 0 ? width : height);
        const char *prefix = axis == 0 ? "col_" : "row_";
        const auto kind = axis == 0 ? GrayPattern::Kind::Column : GrayPattern::Kind::Row;
        for (int b = bits - 1; b >= 0; --b) {
            out.push_back({prefix + std::to_string(b), kind, b, false});
            out.push_back({prefix + std::to_string(b) + "_inv", kind, b, true});
        }
    }
    return out;
}

std::vector<GrayPattern> openCvGrayPatterns(int width, int height) {
    std::vector<GrayPattern> out = grayPatterns(width, height);
    std::rotate(out.begin(), out.begin() + 2, out.end());
    return out;
}

cv::Mat grayPatternImage(const GrayPattern &p, int width, int height) {
    cv::Mat img(height, width, CV_8UC1, cv::Scalar(p.kind == GrayPattern::Kind::Black ? 0 : 255));
    if (p.kind == GrayPattern::Kind::White || p.kind == GrayPattern::Kind::Black) return img;
    const bool columns = p.kind == GrayPattern::Kind::Column;
    const int n = columns ? width : height;
    std::vector<uchar> line(n);
    for (int i = 0; i < n; ++i) {
        const int gray = i ^ (i >> 1);
        const bool on = ((gray >> p.bit) & 1) != p.inverse;
        line[i] = on ? 255 : 0;
    }
    for (int y = 0; y < height; ++y) {
        uchar *r = img.ptr<uchar>(y);
        for (int x = 0; x < width; ++x) r[x] = columns ? line[x] : line[y];
    }
    return img;
}

namespace {

/// A grey level: 8-bit captures are kept as they are (a float copy of each would quadruple a
/// pose's memory), their neighbourhood sums as 16-bit (`scale` = 1 / the neighbourhood's size),
/// anything else as float.
double greyAt(const cv::Mat &g, int y, int x, double scale) {
    switch (g.depth()) {
        case CV_8U: return g.at<uchar>(y, x);
        case CV_16U: return scale * g.at<ushort>(y, x);
        default: return g.at<float>(y, x);
    }
}

/// Gray code to binary, `bits` wide.
int grayToBinary(int g, int bits) {
    int binary = 0;
    for (int b = bits - 1, prev = 0; b >= 0; --b) {
        prev ^= (g >> b) & 1;
        binary |= prev << b;
    }
    return binary;
}

/// One axis from its bits' pattern - inverse differences (most significant first) and the
/// margin a bit needs: the framebuffer coordinate, or NaN. `weakest` takes the least resolved
/// bit's |difference|.
double decodeAxis(const double *diff, int bits, int n, double margin, int min_bits, double &weakest) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Every bit; `unsure` marks those whose pair is too close to call.
    int gray = 0, unsure = 0;
    for (int k = 0; k < bits; ++k) {
        const int b = bits - 1 - k;
        if (std::abs(diff[k]) < margin) {
            unsure |= 1 << b;
            continue;
        }
        weakest = std::min(weakest, std::abs(diff[k]));
        if (diff[k] > 0) gray |= 1 << b;
    }
    // The unresolved low bits (stripes finer than the camera sees): the range's centre.
    int low = 0;
    while (low < bits && (unsure >> low) & 1) ++low;
    if (bits - low < std::min(min_bits, bits)) return nan;
    const int high_unsure = unsure >> low;
    const int mask_low = (1 << low) - 1;
    double v = 0;
    if (high_unsure == 0) {
        v = (grayToBinary(gray & ~mask_low, bits) & ~mask_low) + 0.5 * mask_low;
    } else if ((high_unsure & (high_unsure - 1)) == 0) {
        // One unsure bit above the resolved ones: on the boundary between two neighbouring
        // codes (Gray code: only that bit differs), if they are neighbours.
        const int bit = 1 << (low + __builtin_ctz(high_unsure));
        const int a = grayToBinary(gray & ~mask_low & ~bit, bits) & ~mask_low,
                  b = grayToBinary((gray & ~mask_low) | bit, bits) & ~mask_low;
        if (std::abs(a - b) != (1 << low)) return nan;
        v = 0.5 * (a + b) + 0.5 * mask_low;
    } else {
        return nan;
    }
    if (v > n - 1) return nan;  // codes beyond the framebuffer: a misread
    return v;
}

/// Whether a pixel lit enough to decode (white - black >= min_contrast) is still undecoded.
bool anyLitUndecoded(const std::vector<cv::Mat> &grey, const GrayDecoding &d, double min_contrast) {
    for (int y = 0; y < d.column.rows; ++y)
        for (int x = 0; x < d.column.cols; ++x)
            if (std::isnan(d.column.at<double>(y, x)) &&
                greyAt(grey[0], y, x, 1.0) - greyAt(grey[1], y, x, 1.0) >= min_contrast)
                return true;
    return false;
}

/// 8-bit rounding alone puts 1/sqrt(12) grey levels of noise on each capture; a pattern -
/// inverse difference carries sqrt(2) of that.
constexpr double kQuantisationNoise = 0.40824829046386301;  // 1/sqrt(6), grey levels

/// Decodes the pixels whose column is still NaN from `grey` (white, black, then the pairs in
/// grayPatterns' order); `pooled` marks the pass that decodes from neighbourhood means.
void decodePass(const std::vector<cv::Mat> &grey, int width, int height, const GrayDecodeConfig &cfg,
                bool pooled, GrayDecoding &d) {
    const int col_bits = grayBits(width), row_bits = grayBits(height);
    const int pairs = col_bits + row_bits;
    std::vector<double> diff(pairs), sum(pairs);
    const cv::Size size = grey[0].size();
    const double scale = 1.0 / ((2 * cfg.pool_px + 1) * (2 * cfg.pool_px + 1));
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            if (!std::isnan(d.column.at<double>(y, x))) continue;
            const double white = greyAt(grey[0], y, x, scale), black = greyAt(grey[1], y, x, scale);
            if (!(white - black >= cfg.min_contrast)) continue;
            // The pixel's direct light from the projector: the largest pattern - inverse
            // difference (a coarse stripe's; light scattered from the board's neighbourhood
            // falls on pattern and inverse alike and cancels there, unlike in white - black).
            // Its noise, measured: pattern + inverse should equal white + black for every pair
            // (complementary patterns), so the spread of that sum over the pairs is noise.
            double direct = 0, mean_sum = 0;
            for (int i = 0; i < pairs; ++i) {
                const double p = greyAt(grey[2 + 2 * i], y, x, scale), q = greyAt(grey[3 + 2 * i], y, x, scale);
                diff[i] = p - q;
                sum[i] = p + q - white - black;
                direct = std::max(direct, std::abs(diff[i]));
                mean_sum += sum[i];
            }
            mean_sum /= pairs;
            double var = 0;
            for (int i = 0; i < pairs; ++i) var += (sum[i] - mean_sum) * (sum[i] - mean_sum);
            // White + black is the same for every pair, so over the pairs the sum varies by the
            // pattern's and the inverse's noise alone: 2 sigma^2, as p - q does.
            const double sigma = std::max(std::sqrt(var / std::max(1, pairs - 1)),
                                          pooled ? kQuantisationNoise / (2 * cfg.pool_px + 1) : kQuantisationNoise);
            const double noise_margin = cfg.noise_sigmas * sigma;
            if (!(direct >= noise_margin) || !(direct > 0)) continue;  // the projector's light is not told from noise
            const double margin = std::max(cfg.min_bit_margin * direct, noise_margin);
            double weakest = direct;
            const double u = decodeAxis(diff.data(), col_bits, width, margin, cfg.min_bits, weakest);
            if (std::isnan(u)) continue;
            const double v = decodeAxis(diff.data() + col_bits, row_bits, height, margin, cfg.min_bits, weakest);
            if (std::isnan(v)) continue;
            d.column.at<double>(y, x) = u;
            d.row.at<double>(y, x) = v;
            d.confidence.at<uchar>(y, x) = cv::saturate_cast<uchar>(std::max(1.0, 255.0 * weakest / direct));
            d.direct.at<float>(y, x) = static_cast<float>(direct);
            ++d.decoded;
            if (pooled) ++d.pooled;
        }
}

}  // namespace

GrayDecoding decodeGray(const std::vector<cv::Mat> &captures, int width, int height, const GrayDecodeConfig &cfg) {
    return decodeGray(captures, grayPatterns(width, height), width, height, cfg);
}

GrayDecoding decodeGray(const std::vector<cv::Mat> &captures, const std::vector<GrayPattern> &order, int width,
                        int height, const GrayDecodeConfig &cfg) {
    // Where each pattern of grayPatterns' order was captured.
    const auto patterns = grayPatterns(width, height);
    std::vector<int> slot(patterns.size(), -1);
    if (order.size() != patterns.size())
        throw std::invalid_argument("gray decode: " + std::to_string(order.size()) + " patterns in the order for " +
                                    std::to_string(patterns.size()));
    for (std::size_t i = 0; i < order.size(); ++i) {
        std::size_t k = 0;
        while (k < patterns.size() && !(patterns[k].kind == order[i].kind && patterns[k].bit == order[i].bit &&
                                        patterns[k].inverse == order[i].inverse))
            ++k;
        if (k == patterns.size() || slot[k] >= 0)
            throw std::invalid_argument("gray decode: pattern '" + order[i].name + "' unknown or repeated");
        slot[k] = static_cast<int>(i);
    }
    if (captures.size() != patterns.size())
        throw std::invalid_argument("gray decode: " + std::to_string(captures.size()) + " captures for " +
                                    std::to_string(patterns.size()) + " patterns");
    const cv::Size size = captures[0].size();
    std::vector<cv::Mat> grey;
    for (const auto &c : captures)
        if (c.size() != size || c.empty()) throw std::invalid_argument("gray decode: captures of different sizes");
    bool eight_bit = true;
    for (const int i : slot) {
        grey.push_back(greyscale(captures[i]));
        eight_bit = eight_bit && grey.back().depth() == CV_8U;
    }
    if (!eight_bit)
        for (auto &g : grey) g.convertTo(g, CV_32F);
    GrayDecoding d;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    d.column = cv::Mat(size, CV_64F, cv::Scalar(nan));
    d.row = cv::Mat(size, CV_64F, cv::Scalar(nan));
    d.confidence = cv::Mat(size, CV_8U, cv::Scalar(0));
    d.direct = cv::Mat(size, CV_32F, cv::Scalar(0));
    decodePass(grey, width, height, cfg, false, d);
    if (cfg.pool_px > 0 && anyLitUndecoded(grey, d, cfg.min_contrast)) {
        // Pixels too dark to decode alone (a board's black squares): the same rules on the
        // means of their neighbourhoods, whose noise is (2 pool_px + 1) times smaller.
        const cv::Size box(2 * cfg.pool_px + 1, 2 * cfg.pool_px + 1);
        for (auto &g : grey) {
            if (g.depth() == CV_8U && 255 * box.area() <= 65535) {  // exact sums in 16 bits, read back scaled
                cv::Mat sums;
                cv::boxFilter(g, sums, CV_16U, box, cv::Point(-1, -1), false, cv::BORDER_REPLICATE);
                g = sums;
            } else {
                if (g.depth() != CV_32F) g.convertTo(g, CV_32F);
                cv::blur(g, g, box, cv::Point(-1, -1), cv::BORDER_REPLICATE);
            }
        }
        decodePass(grey, width, height, cfg, true, d);
    }
    return d;
}

}  // namespace projsurf
