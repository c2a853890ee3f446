// The paper method's boundaries (detection/paper/hull.hpp): the convex hull and the concave
// hull (alpha shape) of a planar point set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "projsurf/detection/paper/hull.hpp"

using namespace projsurf;
using V2 = Eigen::Vector2d;

namespace {

bool contains(const std::vector<V2> &pts, const V2 &p) {
    return std::any_of(pts.begin(), pts.end(), [&](const V2 &q) { return (q - p).norm() < 1e-12; });
}

double signedArea(const std::vector<V2> &poly) {
    double a = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const V2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
        a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
}

/// Grid points of the L shape [0,2]x[0,1] + [0,1]x[0,2], spacing 0.1 m.
std::vector<V2> lShape() {
    std::vector<V2> pts;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j)
            if (i <= 10 || j <= 10) pts.emplace_back(0.1 * i, 0.1 * j);
    return pts;
}

}  // namespace

TEST(PaperHull, ConvexHullOfASquareWithInteriorPointsIsItsFourCorners) {
    std::vector<V2> pts = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {0.5, 1.5}, {1.9, 0.1}, {1, 0}, {2, 1}, {0, 0}};
    const std::vector<V2> hull = convexHull(pts);
    ASSERT_EQ(hull.size(), 4u);
    for (const V2 &c : {V2(0, 0), V2(2, 0), V2(2, 2), V2(0, 2)}) EXPECT_TRUE(contains(hull, c)) << c.transpose();
    EXPECT_NEAR(signedArea(hull), 4.0, 1e-12);  // counter-clockwise
}

TEST(PaperHull, ConvexHullOfTheLCutsTheNotch) {
    const std::vector<V2> hull = convexHull(lShape());
    // Corners (0,0) (2,0) (2,1) (1,2) (0,2): the inner corner (1,1) is not on it.
    EXPECT_EQ(hull.size(), 5u);
    EXPECT_FALSE(contains(hull, V2(1, 1)));
    EXPECT_NEAR(signedArea(hull), 3.5, 1e-9);
}

TEST(PaperHull, ConcaveHullOfTheLKeepsTheNotch) {
    // Alpha 0.1 m keeps every grid triangle (circumradius 0.071 m) and none across the notch.
    // At the inner corner (1,1) the triangle (1,1) (1.1,1) (1,1.1) is kept too, so the boundary
    // cuts that one cell's corner with its diagonal: the L's perimeter (8 m) less 0.2 m plus
    // 0.1 * sqrt(2). The convex hull would cut the whole notch, from (2,1) to (1,2).
    const auto edges = concaveHullEdges(lShape(), 0.1);
    ASSERT_FALSE(edges.empty());
    double length = 0.0;
    bool corner_diagonal = false;
    for (const Segment2 &e : edges) {
        length += (e[1] - e[0]).norm();
        corner_diagonal = corner_diagonal || ((e[0] - V2(1.1, 1)).norm() < 1e-6 && (e[1] - V2(1, 1.1)).norm() < 1e-6) ||
                          ((e[1] - V2(1.1, 1)).norm() < 1e-6 && (e[0] - V2(1, 1.1)).norm() < 1e-6);
        // No edge crosses the missing square (1,2)x(1,2) beyond that diagonal.
        const V2 mid = 0.5 * (e[0] + e[1]);
        EXPECT_FALSE(mid.x() > 1.06 && mid.y() > 1.06) << e[0].transpose() << " - " << e[1].transpose();
    }
    EXPECT_TRUE(corner_diagonal);
    EXPECT_NEAR(length, 8.0 - 0.2 + 0.1 * std::sqrt(2.0), 1e-4);  // every boundary edge, no interior one
}

TEST(PaperHull, ConcaveHullFindsAHole) {
    // A 2 x 2 m grid with the points strictly inside the 0.6 x 0.6 m square (0.7,1.3)^2 missing:
    // the outer boundary (8 m) and the hole's (2.4 m, each of its 4 corners cut by one cell's
    // diagonal as in the L above).
    std::vector<V2> pts;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j)
            if (!(i > 7 && i < 13 && j > 7 && j < 13)) pts.emplace_back(0.1 * i, 0.1 * j);
    double length = 0.0;
    for (const Segment2 &e : concaveHullEdges(pts, 0.1)) length += (e[1] - e[0]).norm();
    EXPECT_NEAR(length, 8.0 + 2.4 - 4 * (0.2 - 0.1 * std::sqrt(2.0)), 1e-4);
}

TEST(PaperHull, PolygonEdgesCloseThePolygon) {
    const std::vector<V2> tri = {{0, 0}, {1, 0}, {0, 1}};
    const auto edges = polygonEdges(tri);
    ASSERT_EQ(edges.size(), 3u);
    EXPECT_TRUE((edges[2][0] - V2(0, 1)).norm() < 1e-12 && (edges[2][1] - V2(0, 0)).norm() < 1e-12);
}
