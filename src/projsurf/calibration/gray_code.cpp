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

double greyAt(const cv::Mat &g, int y, int x) {
    return g.depth() == CV_8U ? g.at<uchar>(y, x) : g.at<float>(y, x);
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
    // 8-bit captures are read as they are (a float copy of each would quadruple a pose's
    // memory); any other depth makes every plane float. The values are the grey levels either way.
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
    const int col_bits = grayBits(width), row_bits = grayBits(height);
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            const double white = greyAt(grey[0], y, x), black = greyAt(grey[1], y, x);
            const double contrast = white - black;
            if (!(contrast >= cfg.min_contrast)) continue;
            double value[2] = {nan, nan};
            double weakest = 1.0;  // the least resolved bit's margin, share of the contrast
            std::size_t at = 2;
            for (int axis = 0; axis < 2; ++axis) {
                const int bits = axis == 0 ? col_bits : row_bits;
                const int n = axis == 0 ? width : height;
                // Every bit; `unsure` marks those whose pair is too close to call.
                int gray = 0, unsure = 0;
                for (int b = bits - 1; b >= 0; --b, at += 2) {
                    const double diff = greyAt(grey[at], y, x) - greyAt(grey[at + 1], y, x);
                    if (std::abs(diff) < cfg.min_bit_margin * contrast) {
                        unsure |= 1 << b;
                        continue;
                    }
                    weakest = std::min(weakest, std::abs(diff) / contrast);
                    if (diff > 0) gray |= 1 << b;
                }
                auto toBinary = [bits](int g) {
                    int binary = 0;
                    for (int b = bits - 1, prev = 0; b >= 0; --b) {
                        prev ^= (g >> b) & 1;
                        binary |= prev << b;
                    }
                    return binary;
                };
                // The unresolved low bits (stripes finer than the camera sees): the range's centre.
                int low = 0;
                while (low < bits && (unsure >> low) & 1) ++low;
                if (bits - low < std::min(cfg.min_bits, bits)) break;
                const int high_unsure = unsure >> low;
                const int mask_low = (1 << low) - 1;
                double v = 0;
                if (high_unsure == 0) {
                    v = (toBinary(gray & ~mask_low) & ~mask_low) + 0.5 * mask_low;
                } else if ((high_unsure & (high_unsure - 1)) == 0) {
                    // One unsure bit above the resolved ones: on the boundary between two
                    // neighbouring codes (Gray code: only that bit differs), if they are neighbours.
                    const int bit = 1 << (low + __builtin_ctz(high_unsure));
                    const int a = toBinary(gray & ~mask_low & ~bit) & ~mask_low,
                              b = toBinary((gray & ~mask_low) | bit) & ~mask_low;
                    if (std::abs(a - b) != (1 << low)) break;
                    v = 0.5 * (a + b) + 0.5 * mask_low;
                } else {
                    break;
                }
                if (v > n - 1) break;  // codes beyond the framebuffer: a misread
                value[axis] = v;
            }
            if (std::isnan(value[0]) || std::isnan(value[1])) continue;
            d.column.at<double>(y, x) = value[0];
            d.row.at<double>(y, x) = value[1];
            d.confidence.at<uchar>(y, x) = cv::saturate_cast<uchar>(std::max(1.0, 255.0 * weakest));
            ++d.decoded;
        }
    return d;
}

}  // namespace projsurf
