#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "projsurf/detection/planes/pixel_lattice.hpp"

using namespace projsurf;

namespace {

/// x/z of the columns [first, last] of a pinhole (fx, cx), `per` readings each, every
/// `skip`-th column missing (0: none), each value as the float a depth image's cloud stores.
std::vector<float> columns(double fx, double cx, int first, int last, int per, int skip) {
    std::vector<float> out;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> depth(0.6, 5.0);
    for (int c = first; c <= last; ++c) {
        if (skip > 0 && c % skip == 0) continue;
        for (int k = 0; k < per; ++k) {
            const float z = static_cast<float>(depth(rng));
            const float x = static_cast<float>((c - cx) * z / fx);
            out.push_back(x / z);
        }
    }
    std::shuffle(out.begin(), out.end(), rng);
    return out;
}

}  // namespace

TEST(PixelLattice, AShuffledDepthImagesColumnsGiveItsFocalLengthAndFirstColumn) {
    // Columns 8-631 of a 585 px camera (cx 320), every 7th column without a reading.
    const auto lattice = pixelLattice(columns(585.0, 320.0, 8, 631, 20, 7));
    ASSERT_TRUE(lattice);
    EXPECT_NEAR(1.0 / lattice->step, 585.0, 0.05);
    EXPECT_NEAR(lattice->origin, (8 - 320.0) / 585.0, 1e-6);
    EXPECT_EQ(lattice->count, 631 - 8 + 1);
    EXPECT_NEAR(lattice->index((500 - 320.0) / 585.0), 500 - 8, 1e-3);
}

TEST(PixelLattice, ValuesPrintedWithFewDecimalsStillFallOnIt) {
    // A PCD written with 4 decimals (0.1 mm): x/z off its column by up to 0.05 mm / 0.6 m.
    std::vector<float> values;
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> depth(0.6, 3.0);
    for (int c = 0; c < 640; ++c)
        for (int k = 0; k < 10; ++k) {
            const double z = std::round(depth(rng) * 1e4) / 1e4;
            const double x = std::round((c - 319.5) * z / 525.0 * 1e4) / 1e4;
            values.push_back(static_cast<float>(x / z));
        }
    const auto lattice = pixelLattice(values);
    ASSERT_TRUE(lattice);
    EXPECT_NEAR(1.0 / lattice->step, 525.0, 0.2);
    EXPECT_EQ(lattice->count, 640);
}

TEST(PixelLattice, RaysOnNoGridHaveNone) {
    // Rays spread evenly (another viewpoint, a voxel grid) and a few scattered ones.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ray(-0.6, 0.6);
    std::vector<float> dense, sparse;
    for (int i = 0; i < 300000; ++i) dense.push_back(static_cast<float>(ray(rng)));
    for (int i = 0; i < 200; ++i) sparse.push_back(static_cast<float>(ray(rng)));
    EXPECT_FALSE(pixelLattice(dense));
    EXPECT_FALSE(pixelLattice(sparse));
    // Half a pixel of jitter on a 525 px camera's columns.
    std::vector<float> jittered;
    std::uniform_real_distribution<double> off(-0.5, 0.5);
    for (int c = 0; c < 640; ++c)
        for (int k = 0; k < 50; ++k) jittered.push_back(static_cast<float>((c + off(rng) - 319.5) / 525.0));
    EXPECT_FALSE(pixelLattice(jittered));
    EXPECT_FALSE(pixelLattice({}));
    EXPECT_FALSE(pixelLattice(std::vector<float>(1000, 0.25f)));  // one column
}
