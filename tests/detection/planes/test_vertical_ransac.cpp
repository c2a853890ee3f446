// RANSAC for the vertical plane with the most points (detection/planes/vertical_ransac.hpp)
// against its plain reference (docs/design.md, "Speed"): the same search written as a plain
// loop, scoring each hypothesis point by point with a branch, drawing the same random numbers.
// Both must choose the same plane with the same inliers on noisy clouds with outliers.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "projsurf/detection/planes/vertical_ransac.hpp"

using namespace projsurf;

namespace {

/// The plain reference: findVerticalPlane's steps one by one, without the vectorised scoring
/// arrays (each hypothesis counts the points within band with an if).
std::optional<PlaneInliers> plainVerticalPlane(const std::vector<Point> &points, const std::vector<int> &active,
                                               const std::vector<float> &band, const Eigen::Vector3d &gravity,
                                               const RansacOptions &options, std::mt19937 &rng) {
    if (active.size() < 3) return std::nullopt;
    const Eigen::Vector3f g = gravity.normalized().cast<float>();
    const float max_sin_tilt = static_cast<float>(std::sin(options.max_tilt));
    std::vector<int> subset = active;
    if (options.score_subset > 0 && static_cast<int>(subset.size()) > options.score_subset) {
        for (std::size_t k = 0; k < static_cast<std::size_t>(options.score_subset); ++k)
            std::swap(subset[k], subset[std::uniform_int_distribution<std::size_t>(k, subset.size() - 1)(rng)]);
        subset.resize(options.score_subset);
    }
    std::uniform_int_distribution<std::size_t> pick(0, active.size() - 1);
    const float span2 = static_cast<float>(options.max_sample_span * options.max_sample_span);
    int best_score = 0;
    Eigen::Vector3f best_n = Eigen::Vector3f::Zero();
    float best_d = 0.0f;
    double needed = options.max_iterations;
    for (int it = 0; it < options.max_iterations && it < needed; ++it) {
        const Point &p1 = points[active[pick(rng)]];
        Point p2 = points[active[pick(rng)]], p3 = points[active[pick(rng)]];
        if (span2 > 0.0f) {
            for (int retry = 0; retry < 8 && (p2 - p1).squaredNorm() > span2; ++retry) p2 = points[active[pick(rng)]];
            for (int retry = 0; retry < 8 && (p3 - p1).squaredNorm() > span2; ++retry) p3 = points[active[pick(rng)]];
        }
        Eigen::Vector3f n = (p2 - p1).cross(p3 - p1);
        const float len = n.norm();
        if (!(len > 1e-6f)) continue;
        n /= len;
        if (std::abs(n.dot(g)) > max_sin_tilt) continue;
        const float d = -n.dot(p1);
        int score = 0;
        for (int i : subset) {
            const Point &p = points[i];
            if (std::abs(n.x() * p.x() + n.y() * p.y() + n.z() * p.z() + d) <= band[i]) ++score;
        }
        if (score > best_score) {
            best_score = score;
            best_n = n;
            best_d = d;
            const double w = static_cast<double>(score) / subset.size();
            const double p_good = w * w * w;
            if (p_good >= 1.0)
                needed = 0;
            else if (p_good > 0.0)
                needed = std::log(1.0 - options.probability) / std::log(1.0 - p_good);
        }
    }
    if (best_score < 3) return std::nullopt;
    PlaneInliers result;
    result.plane = makePlane(best_n.cast<double>(), best_d);
    for (int i : active)
        if (std::abs(result.plane.normal.cast<float>().dot(points[i]) + static_cast<float>(result.plane.d)) <= band[i])
            result.inliers.push_back(i);
    return result;
}

struct Cloud3 {
    std::vector<Point> points;
    std::vector<float> band;
    int wall_points = 0;
};

/// y is up (gravity -y). A wall z = 3 + 0.2 x (vertical), a larger floor y = -1 (horizontal,
/// must be ignored), a smaller second wall x = -1.5, uniform outliers; Gaussian noise 1 cm.
Cloud3 scene(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::normal_distribution<float> noise(0.0f, 0.01f);
    Cloud3 c;
    for (int i = 0; i < 1500; ++i) {
        const float x = 1.2f * u(rng), y = u(rng);
        c.points.emplace_back(x + noise(rng), y + noise(rng), 3.0f + 0.2f * x + noise(rng));
    }
    c.wall_points = 1500;
    for (int i = 0; i < 2500; ++i) c.points.emplace_back(1.5f * u(rng), -1.0f + noise(rng), 2.0f + u(rng));
    for (int i = 0; i < 600; ++i) c.points.emplace_back(-1.5f + noise(rng), u(rng), 2.0f + u(rng));
    for (int i = 0; i < 800; ++i) c.points.emplace_back(2.0f * u(rng), 1.5f * u(rng), 1.0f + 2.0f * std::abs(u(rng)));
    c.band.assign(c.points.size(), 0.03f);
    return c;
}

}  // namespace

TEST(VerticalRansac, MatchesItsPlainReference) {
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u, 17u}) {
        const Cloud3 c = scene(seed);
        std::vector<int> active(c.points.size());
        for (int i = 0; i < static_cast<int>(active.size()); ++i) active[i] = i;
        for (int subset : {0, 1000}) {
            RansacOptions opt;
            opt.score_subset = subset;
            std::mt19937 rng_a(100 + seed), rng_b(100 + seed);
            const auto got = findVerticalPlane(c.points, active, c.band, Eigen::Vector3d(0, -1, 0), opt, rng_a);
            const auto want = plainVerticalPlane(c.points, active, c.band, Eigen::Vector3d(0, -1, 0), opt, rng_b);
            ASSERT_TRUE(got && want) << "seed " << seed;
            EXPECT_NEAR(std::abs(got->plane.normal.dot(want->plane.normal)), 1.0, 1e-9) << "seed " << seed;
            EXPECT_NEAR(got->plane.d * got->plane.normal.dot(want->plane.normal), want->plane.d, 1e-6) << "seed " << seed;
            EXPECT_EQ(got->inliers, want->inliers) << "seed " << seed << " subset " << subset;
            // And both found the big wall, not the larger floor nor the smaller wall.
            const Eigen::Vector3d wall = Eigen::Vector3d(-0.2, 0.0, 1.0).normalized();
            EXPECT_GT(std::abs(got->plane.normal.dot(wall)), std::cos(2.0 * M_PI / 180.0)) << "seed " << seed;
            EXPECT_GE(static_cast<int>(got->inliers.size()), c.wall_points * 9 / 10) << "seed " << seed;
            EXPECT_LE(static_cast<int>(got->inliers.size()), c.wall_points + 200) << "seed " << seed;
            // Same random numbers consumed: the streams are still in step.
            EXPECT_EQ(rng_a(), rng_b()) << "seed " << seed;
        }
    }
}

TEST(VerticalRansac, PlaneInliersIsThePlainBandTest) {
    const Cloud3 c = scene(9);
    std::vector<int> active;
    for (int i = 0; i < static_cast<int>(c.points.size()); i += 2) active.push_back(i);
    const Plane wall = makePlane(Eigen::Vector3d(-0.2, 0.0, 1.0).normalized(), -3.0 / std::sqrt(1.04));
    std::vector<int> want;
    for (int i : active)
        if (std::abs(wall.normal.cast<float>().dot(c.points[i]) + static_cast<float>(wall.d)) <= c.band[i]) want.push_back(i);
    EXPECT_EQ(planeInliers(c.points, active, c.band, wall), want);
    EXPECT_GT(want.size(), 600u);
}

TEST(VerticalRansac, OnlyHorizontalPlanesGiveNothingVertical) {
    // A floor alone: no hypothesis within max_tilt of vertical scores.
    std::mt19937 gen(4);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Point> pts;
    for (int i = 0; i < 500; ++i) pts.emplace_back(u(gen), -1.0f, 2.0f + u(gen));
    std::vector<int> active(pts.size());
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) active[i] = i;
    std::mt19937 rng(1);
    EXPECT_FALSE(findVerticalPlane(pts, active, std::vector<float>(pts.size(), 0.02f), Eigen::Vector3d(0, -1, 0),
                                   RansacOptions{}, rng));
}
