// KeystoneWarper (the per-frame keystone warp with the source positions computed once) against
// cv::warpPerspective on the same homography, and its handling of bad or unusual pictures.
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "projsurf/keystone/keystone.hpp"
#include "projsurf/keystone/keystone_warper.hpp"
#include "synthetic_rig.hpp"

using namespace projsurf;

namespace {

/// A keystone that puts a picture of `picture` size onto the framebuffer quad `corners`
/// (top-left, top-right, bottom-right, bottom-left).
Keystone keystoneOnto(cv::Size picture, const Corners2 &corners, cv::Size framebuffer = {1280, 800}) {
    const float w = static_cast<float>(picture.width), h = static_cast<float>(picture.height);
    const std::vector<cv::Point2f> src = {{-0.5f, -0.5f}, {w - 0.5f, -0.5f}, {w - 0.5f, h - 0.5f}, {-0.5f, h - 0.5f}};
    std::vector<cv::Point2f> dst;
    for (const auto &c : corners) dst.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
    Keystone k;
    k.picture = picture;
    k.framebuffer = framebuffer;
    k.homography = cv::Matx33d(cv::getPerspectiveTransform(src, dst));
    for (int i = 0; i < 4; ++i) {  // exactly where this homography puts the corners
        const cv::Vec3d q = k.homography * cv::Vec3d(src[i].x, src[i].y, 1.0);
        k.picture_px[i] = Eigen::Vector2d(q[0] / q[2], q[1] / q[2]);
    }
    return k;
}

/// Mild: the test rig's projector and a wall turned 10 deg (what computeKeystone gives).
Keystone mildKeystone(cv::Size picture) {
    const Projector p = rig::trueProjector();
    const auto r = computeKeystone(p, rig::rectangleInWorkspace(p, rig::wall(2.0, 10.0)), picture);
    if (!r.keystone) throw std::runtime_error(r.problem);
    return *r.keystone;
}

/// Strong: the far edge at less than half the near edge's height, and tilted.
Keystone strongKeystone(cv::Size picture) {
    return keystoneOnto(picture, {Eigen::Vector2d(40.3, 20.7), Eigen::Vector2d(1150.2, 260.4),
                                  Eigen::Vector2d(1210.9, 530.1), Eigen::Vector2d(15.6, 780.8)});
}

/// Smooth detail everywhere (blurred noise): the largest step between neighbours stays small,
/// so the bound below is meaningful.
cv::Mat noisePicture(cv::Size size, int type, int seed) {
    cv::Mat m(size, type);
    cv::setRNGSeed(seed);
    cv::randu(m, cv::Scalar::all(0), cv::Scalar::all(256));
    cv::GaussianBlur(m, m, cv::Size(7, 7), 2.0);
    return m;
}

cv::Mat reference(const cv::Mat &picture, const Keystone &k) {
    cv::Mat out;
    cv::warpPerspective(picture, out, cv::Mat(k.homography), k.framebuffer, cv::INTER_LINEAR, cv::BORDER_CONSTANT,
                        cv::Scalar::all(0));
    return out;
}

/// Largest gap between horizontally or vertically adjacent samples, grey levels.
double largestStep(const cv::Mat &m) {
    cv::Mat a, b;
    cv::absdiff(m.colRange(1, m.cols), m.colRange(0, m.cols - 1), a);
    cv::absdiff(m.rowRange(1, m.rows), m.rowRange(0, m.rows - 1), b);
    double ma = 0, mb = 0;
    cv::minMaxLoc(a.reshape(1), nullptr, &ma);
    cv::minMaxLoc(b.reshape(1), nullptr, &mb);
    return std::max(ma, mb);
}

/// True when framebuffer pixel (x, y) maps to a picture position that the bilinear footprint
/// cannot reach (more than `margin` px outside [-1, w] x [-1, h]).
bool farOutside(const Keystone &k, int x, int y, double margin) {
    const cv::Vec3d s = k.homography.inv() * cv::Vec3d(x, y, 1.0);
    const double sx = s[0] / s[2], sy = s[1] / s[2];
    return sx < -1.0 - margin || sy < -1.0 - margin || sx > k.picture.width + margin || sy > k.picture.height + margin;
}

struct Comparison {
    double max_diff = 0;      ///< over every framebuffer pixel and channel
    int differing = 0;        ///< pixels with any difference
    int lit_far_outside = 0;  ///< ours not black where the picture cannot reach
    int lit = 0;              ///< ours not black
};

Comparison compare(const cv::Mat &ours, const cv::Mat &ref, const Keystone &k) {
    Comparison c;
    cv::Mat diff;
    cv::absdiff(ours, ref, diff);
    cv::minMaxLoc(diff.reshape(1), nullptr, &c.max_diff);
    cv::Mat any_diff;
    cv::transform(diff, any_diff, cv::Mat::ones(1, diff.channels(), CV_32F));  // sum of the channels
    c.differing = cv::countNonZero(any_diff);
    for (int y = 0; y < ours.rows; ++y)
        for (int x = 0; x < ours.cols; ++x) {
            const uchar *p = ours.ptr<uchar>(y) + x * ours.channels();
            bool lit = false;
            for (int ch = 0; ch < ours.channels(); ++ch) lit = lit || p[ch] != 0;
            if (!lit) continue;
            ++c.lit;
            if (farOutside(k, x, y, 0.05)) ++c.lit_far_outside;
        }
    std::printf("  %d channel(s): max difference %.0f, %d of %d lit pixels differ\n", ours.channels(), c.max_diff,
                c.differing, c.lit);
    return c;
}

}  // namespace

// Both warps round the source position to 1/32 px and blend with the same exact integer
// weights (keystone_warper.cpp), so they agree exactly except where a position lies within
// floating-point noise of a 1/32 px boundary; there one sample moves by 1/32 px and changes by
// at most (largest neighbour step) / 32 + 1 grey levels. These pictures' steps are below 32,
// so the bound is 2 levels everywhere, the picture's edge included, and such pixels are rare.
TEST(KeystoneWarper, AgreesWithWarpPerspectiveMildAndStrong8UC3And8UC1) {
    const cv::Size size(1280, 800);
    int checked = 0;
    for (const int type : {CV_8UC3, CV_8UC1, CV_8UC4}) {
        const cv::Mat pic = noisePicture(size, type, 7 + type);
        ASSERT_LT(largestStep(pic), 32.0);
        for (const Keystone &k : {mildKeystone(size), strongKeystone(size)}) {
            ASSERT_FALSE(warpSourceFor(k, size).reduce);  // compared without the area prepass
            KeystoneWarper warper(k);
            const cv::Mat ours = warper.warp(pic);
            ASSERT_EQ(ours.size(), k.framebuffer);
            ASSERT_EQ(ours.type(), type);
            const cv::Mat ref = reference(pic, k);
            const Comparison c = compare(ours, ref, k);
            SCOPED_TRACE("type " + std::to_string(type));
            EXPECT_LE(c.max_diff, 2.0);
            EXPECT_LE(c.differing, 100) << "of " << c.lit << " lit pixels";
            EXPECT_EQ(c.lit_far_outside, 0);
            EXPECT_GT(c.lit, 200000);  // the picture is there
            EXPECT_EQ(cv::countNonZero(ref.reshape(1)) > 0, true);
            // The same through warpToFramebuffer (KeystoneWarper::warpOnce, row by row).
            EXPECT_EQ(cv::norm(warpToFramebuffer(pic, k), ours, cv::NORM_INF), 0.0);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 6);
}

TEST(KeystoneWarper, SmallPictureMagnifiedAndTwoChannels) {
    // A 160x100 picture magnified about 8x (every framebuffer pixel between the same few
    // source pixels) and a 2-channel picture (the generic path).
    for (const int type : {CV_8UC3, CV_8UC2}) {
        const cv::Size size(160, 100);
        const cv::Mat pic = noisePicture(size, type, 3);
        const Keystone k = strongKeystone(size);
        const cv::Mat ours = KeystoneWarper(k).warp(pic);
        const Comparison c = compare(ours, reference(pic, k), k);
        EXPECT_LE(c.max_diff, 2.0) << "type " << type;
        EXPECT_LE(c.differing, 100);
        EXPECT_EQ(c.lit_far_outside, 0);
    }
}

TEST(KeystoneWarper, StrongShrinkUsesTheAreaPrepass) {
    // A 3200x2000 picture into a small quad: reduced with INTER_AREA, then warped.
    const cv::Size size(3200, 2000);
    const cv::Mat pic = noisePicture(size, CV_8UC3, 11);
    const Keystone k = keystoneOnto(size, {Eigen::Vector2d(400, 300), Eigen::Vector2d(800, 330),
                                           Eigen::Vector2d(790, 560), Eigen::Vector2d(410, 540)});
    const WarpSource source = warpSourceFor(k, size);
    ASSERT_TRUE(source.reduce);
    EXPECT_LT(source.size.width, size.width / 2);
    cv::Mat small;
    cv::resize(pic, small, source.size, 0, 0, cv::INTER_AREA);
    Keystone ks = k;
    ks.homography = source.homography;
    ks.picture = source.size;
    const cv::Mat ours = KeystoneWarper(k).warp(pic);
    EXPECT_EQ(cv::norm(warpToFramebuffer(pic, k), ours, cv::NORM_INF), 0.0);  // row by row, same
    const Comparison c = compare(ours, reference(small, ks), ks);
    EXPECT_LE(c.max_diff, 2.0);
    EXPECT_LE(c.differing, 100);
    EXPECT_EQ(c.lit_far_outside, 0);
    EXPECT_GT(c.lit, 50000);
}

TEST(KeystoneWarper, WrongPictureIsRefusedClearly) {
    const Keystone k = mildKeystone(cv::Size(640, 480));
    KeystoneWarper warper(k);
    cv::Mat out;
    try {
        warper.warp(cv::Mat(480, 641, CV_8UC3, cv::Scalar::all(9)), out);
        FAIL() << "a 641x480 picture was accepted";
    } catch (const std::invalid_argument &e) {
        EXPECT_NE(std::string(e.what()).find("641x480"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("640x480"), std::string::npos) << e.what();
    }
    EXPECT_THROW(warper.warp(cv::Mat(480, 640, CV_16UC3, cv::Scalar::all(9)), out), std::invalid_argument);
    EXPECT_THROW(warpToFramebuffer(cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(9)), k), std::invalid_argument);
    EXPECT_THROW(KeystoneWarper(Keystone{}), std::invalid_argument);
    // An empty picture still gives a black framebuffer, as before.
    const cv::Mat black = warpToFramebuffer(cv::Mat(), k);
    EXPECT_EQ(black.size(), k.framebuffer);
    EXPECT_EQ(cv::countNonZero(black), 0);
}

TEST(KeystoneWarper, ReusedOutputViewsAndInPlace) {
    const cv::Size size(640, 480);
    const Keystone k = strongKeystone(size);
    KeystoneWarper warper(k);
    const cv::Mat a = noisePicture(size, CV_8UC3, 1), b = noisePicture(size, CV_8UC3, 2);
    const cv::Mat expected_b = warper.warp(b);
    // A dirty output buffer of the right size: every pixel is rewritten (outside black).
    cv::Mat out(k.framebuffer, CV_8UC3, cv::Scalar::all(255));
    warper.warp(a, out);
    warper.warp(b, out);
    EXPECT_EQ(cv::norm(out, expected_b, cv::NORM_INF), 0.0);
    // A picture that is a view into a bigger image (rows not contiguous).
    cv::Mat big(600, 800, CV_8UC3, cv::Scalar::all(0));
    b.copyTo(big(cv::Rect(50, 60, 640, 480)));
    EXPECT_EQ(cv::norm(warper.warp(big(cv::Rect(50, 60, 640, 480))), expected_b, cv::NORM_INF), 0.0);
    // Output and input the same Mat: the picture is read before anything is written.
    const Keystone square = strongKeystone(cv::Size(1280, 800));
    KeystoneWarper same(square);
    cv::Mat m = noisePicture(cv::Size(1280, 800), CV_8UC3, 5);
    const cv::Mat expected_m = same.warp(m);
    same.warp(m, m);
    EXPECT_EQ(cv::norm(m, expected_m, cv::NORM_INF), 0.0);
}

TEST(KeystoneWarper, PlainAndSimdBlendsAgree) {
    // The AVX2 and SSSE3 blends (when this CPU has them) against the plain C++ reference,
    // exactly; run lengths of 1, 2 and 3 pixels included (the small quad's corners).
    const cv::Size size(640, 480);
    const Keystone tiny = keystoneOnto(size, {Eigen::Vector2d(600, 400), Eigen::Vector2d(606.3, 401.2),
                                              Eigen::Vector2d(605.1, 405.9), Eigen::Vector2d(599.4, 404.6)});
    for (const int type : {CV_8UC3, CV_8UC4, CV_8UC1}) {
        const cv::Mat pic = noisePicture(size, type, 21);
        for (const Keystone &k : {mildKeystone(size), strongKeystone(size), tiny}) {
            KeystoneWarper warper(k);
            warper.setSimd(KeystoneWarper::Simd::Plain);
            const cv::Mat plain = warper.warp(pic);
            EXPECT_GT(cv::countNonZero(plain.reshape(1)), 10);
            for (const auto simd : {KeystoneWarper::Simd::Best, KeystoneWarper::Simd::Ssse3}) {
                warper.setSimd(simd);
                EXPECT_EQ(cv::norm(warper.warp(pic), plain, cv::NORM_INF), 0.0) << "type " << type;
                EXPECT_EQ(cv::norm(KeystoneWarper::warpOnce(pic, k, simd), plain, cv::NORM_INF), 0.0);
            }
        }
    }
}
