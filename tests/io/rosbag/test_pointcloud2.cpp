// The ROS-free PointCloud2 parser shared by the node and the bag reader.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/rosbag/pointcloud2.hpp"

using namespace projsurf;

namespace {

// x, y, z float32 at 0, 4, 8 plus an rgb float at 16; point_step 32 with padding.
struct Packed {
    std::vector<std::uint8_t> bytes;
    PointCloud2View view;
};

Packed pack(const std::vector<Eigen::Vector3f> &pts, std::uint32_t width, std::uint32_t height) {
    Packed p;
    p.view.width = width;
    p.view.height = height;
    p.view.point_step = 32;
    p.view.row_step = width * 32 + 8;  // rows may be padded
    p.view.fields = {{"x", 0, kPointFieldFloat32, 1},
                     {"y", 4, kPointFieldFloat32, 1},
                     {"z", 8, kPointFieldFloat32, 1},
                     {"rgb", 16, kPointFieldFloat32, 1}};
    p.bytes.assign(static_cast<std::size_t>(p.view.row_step) * height, 0xAB);
    for (std::uint32_t r = 0; r < height; ++r)
        for (std::uint32_t c = 0; c < width; ++c) {
            const auto &q = pts[r * width + c];
            std::memcpy(&p.bytes[r * p.view.row_step + c * 32], q.data(), 12);
        }
    p.view.data = p.bytes.data();
    p.view.data_size = p.bytes.size();
    return p;
}

}  // namespace

TEST(PointCloud2, ReadsAnOrganizedCloudWithPaddingAndNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<Eigen::Vector3f> pts = {{0, 0, 1}, {1, 2, 3}, {nan, nan, nan}, {-1, 0.5f, 2}, {4, 5, 6}, {7, 8, 9}};
    Packed p = pack(pts, 3, 2);
    const Cloud c = cloudFromPointCloud2(p.view, "test");
    ASSERT_TRUE(c.organized());
    EXPECT_EQ(c.width, 3);
    EXPECT_EQ(c.height, 2);
    EXPECT_EQ(c.points[1], Eigen::Vector3f(1, 2, 3));
    EXPECT_TRUE(std::isnan(c.points[2].x()));
    EXPECT_EQ(c.points[3], Eigen::Vector3f(-1, 0.5f, 2));
    EXPECT_EQ(countFinite(c), 5u);
}

TEST(PointCloud2, ReadsFloat64Fields) {
    PointCloud2View v;
    v.width = 2;
    v.height = 1;
    v.point_step = 24;
    v.row_step = 48;
    v.fields = {{"x", 0, kPointFieldFloat64, 1}, {"y", 8, kPointFieldFloat64, 1}, {"z", 16, kPointFieldFloat64, 1}};
    const double vals[6] = {1.5, -2.0, 3.25, 0.0, 0.0, 1.0};
    v.data = reinterpret_cast<const std::uint8_t *>(vals);
    v.data_size = sizeof vals;
    const Cloud c = cloudFromPointCloud2(v, "test");
    EXPECT_FALSE(c.organized());
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c.points[0], Eigen::Vector3f(1.5f, -2.0f, 3.25f));
}

TEST(PointCloud2, RejectsBadLayoutsWithAClearMessage) {
    std::vector<Eigen::Vector3f> pts(4, Eigen::Vector3f(0, 0, 1));
    {
        Packed p = pack(pts, 2, 2);
        p.view.fields.erase(p.view.fields.begin() + 2);  // no z
        try {
            cloudFromPointCloud2(p.view, "bag.bag:/points");
            FAIL() << "no throw";
        } catch (const InputError &e) {
            EXPECT_NE(std::string(e.what()).find("bag.bag:/points"), std::string::npos);
            EXPECT_NE(std::string(e.what()).find("'z'"), std::string::npos);
        }
    }
    {
        Packed p = pack(pts, 2, 2);
        p.view.data_size -= 9;  // truncated into the last point (the 8 padding bytes may go)
        EXPECT_THROW(cloudFromPointCloud2(p.view, "t"), InputError);
    }
    {
        Packed p = pack(pts, 2, 2);
        p.view.fields[0].datatype = 2;  // UINT8 x
        EXPECT_THROW(cloudFromPointCloud2(p.view, "t"), InputError);
    }
    {
        Packed p = pack(pts, 2, 2);
        p.view.fields[1].offset = 30;  // y would read past the point
        EXPECT_THROW(cloudFromPointCloud2(p.view, "t"), InputError);
    }
    {
        Packed p = pack(pts, 2, 2);
        p.view.width = 0;
        EXPECT_THROW(cloudFromPointCloud2(p.view, "t"), InputError);
    }
}
