// The paper method's voxel grid (detection/paper/voxel_grid.hpp): each occupied cube of side
// `leaf` becomes the centroid of its points, in voxel-key order; NaN points are dropped.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "projsurf/detection/paper/voxel_grid.hpp"

using namespace projsurf;

TEST(PaperVoxelGrid, KnownVoxelsGiveTheirCentroidsInKeyOrder) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<Point> pts = {
        {0.01f, 0.01f, 0.01f},  {0.15f, 0.02f, 0.02f}, {0.03f, 0.05f, 0.07f},
        {nan, 0.0f, 0.0f},      {-0.05f, 0.01f, 0.01f}, {0.05f, 0.03f, 0.04f},
    };
    const std::vector<Point> out = voxelDownsample(pts, 0.1);
    ASSERT_EQ(out.size(), 3u);
    // x voxel -1, then 0 (three points), then 1.
    EXPECT_TRUE(out[0].isApprox(Point(-0.05f, 0.01f, 0.01f), 1e-6f)) << out[0].transpose();
    EXPECT_NEAR(out[1].x(), 0.03f, 1e-6f);
    EXPECT_NEAR(out[1].y(), 0.03f, 1e-6f);
    EXPECT_NEAR(out[1].z(), 0.04f, 1e-6f);
    EXPECT_TRUE(out[2].isApprox(Point(0.15f, 0.02f, 0.02f), 1e-6f)) << out[2].transpose();
}

TEST(PaperVoxelGrid, CellsAreFlooredNotTruncated) {
    // -0.001 and +0.001 lie in different voxels (cells -1 and 0); truncation would merge them.
    const std::vector<Point> pts = {{-0.001f, 0.5f, 1.0f}, {0.001f, 0.5f, 1.0f}};
    EXPECT_EQ(voxelDownsample(pts, 0.05).size(), 2u);
    // Points of one voxel merge however many there are.
    std::vector<Point> same;
    for (int i = 0; i < 100; ++i) same.emplace_back(0.2f + 0.0001f * i, 0.21f, 0.22f);
    const auto one = voxelDownsample(same, 0.05);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_NEAR(one[0].x(), 0.2f + 0.0001f * 49.5f, 1e-5f);
}

TEST(PaperVoxelGrid, ALatticeKeepsOnePointPerVoxel) {
    // A 10 x 10 x 10 lattice of spacing 0.02 m in 0.1 m voxels: 2 x 2 x 2 voxels of 125 points.
    std::vector<Point> pts;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k) pts.emplace_back(0.01f + 0.02f * i, 0.01f + 0.02f * j, 0.01f + 0.02f * k);
    const auto out = voxelDownsample(pts, 0.1);
    ASSERT_EQ(out.size(), 8u);
    for (const Point &p : out)
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::fmod(p[a], 0.1f), 0.05f, 1e-5f) << p.transpose();
    EXPECT_TRUE(voxelDownsample({}, 0.1).empty());
}
