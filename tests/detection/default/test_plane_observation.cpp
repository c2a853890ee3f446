// The default method's per-point pass: the point grid, what one pass sees of a plane, the
// surface check read off it (against checkSurface, the point-by-point reference), and the
// camera intrinsics fitted to an organized cloud.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "projsurf/detection/default/plane_observation.hpp"
#include "projsurf/detection/surface_check.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/point_grid.hpp"

using namespace projsurf;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

/// A frontal wall at z = 2 seen by a 64x48 camera, as an organized cloud.
struct FrontalWall {
    CameraIntrinsics camera;
    Cloud cloud;
    Plane plane = makePlane({0, 0, -1}, 2.0);
    PlaneFrame frame;
    RasterFrame raster;

    FrontalWall() {
        camera.width = 64;
        camera.height = 48;
        camera.fx = camera.fy = 50.0;
        camera.cx = 31.5;
        camera.cy = 23.5;
        cv::Mat depth(48, 64, CV_16UC1, cv::Scalar(2000));
        cloud = depthToCloud(depth, camera);
        frame = makePlaneFrame(plane, {0, 1, 0}, {0, 0, 2});
        // 10 cm cells over u, v in [-1.4, 1.4] x [-1.1, 1.1] (the camera sees +-1.28 x +-0.96 m).
        raster = makeRasterFrame({-1.4, -1.1}, {1.4, 1.1}, 0.1);
    }
    /// Cell (row * cols + col) where the plane point (u, v) falls.
    int cellOf(double u, double v) const {
        const Eigen::Vector2d c = raster.toCell({u, v});
        return static_cast<int>(std::floor(c.y())) * raster.cols + static_cast<int>(std::floor(c.x()));
    }
    Eigen::Vector2d uvOfPixel(int u, int v) const {
        return frame.toPlane(cloud.points[v * cloud.width + u].cast<double>());
    }
};

int at(const cv::Mat &m, int cell) { return m.ptr<std::int32_t>()[cell]; }

}  // namespace

TEST(PointGrid, KeepsEveryStepthPixelAndMarksMissingOnes) {
    Cloud cloud;
    cloud.width = 5;
    cloud.height = 4;
    for (int i = 0; i < 20; ++i) cloud.points.emplace_back(static_cast<float>(i), 0.0f, 1.0f);
    cloud.points[2 * 5 + 2] = Point(kNaN, kNaN, kNaN);
    cloud.points[0] = Point(1.0f, std::numeric_limits<float>::infinity(), 1.0f);
    PointGrid grid;
    fillPointGrid(cloud, 2, grid);
    ASSERT_EQ(grid.cols, 3);
    ASSERT_EQ(grid.rows, 2);
    EXPECT_EQ(grid.cloudIndex(1, 2), 14);
    EXPECT_FLOAT_EQ(grid.x[1 * 3 + 2], 14.0f);
    EXPECT_TRUE(std::isnan(grid.z[1 * 3 + 1]));                                            // pixel (2, 2) is missing
    EXPECT_TRUE(std::isnan(grid.x[0]) && std::isnan(grid.y[0]) && std::isnan(grid.z[0]));  // an infinite reading too
    // Pixels [1, 4) x [1, 3) hold grid columns 1 (pixel 2) and rows 1 (pixel 2).
    EXPECT_EQ(grid.gridBox(cv::Rect(1, 1, 3, 2)), cv::Rect(1, 1, 1, 1));
    EXPECT_EQ(grid.gridBox(cv::Rect()), cv::Rect(0, 0, 3, 2));

    cloud.height = 1;
    cloud.width = 20;
    fillPointGrid(cloud, 2, grid);  // unorganized: every point, step 1
    EXPECT_EQ(grid.cols, 20);
    EXPECT_EQ(grid.rows, 1);
    EXPECT_EQ(grid.cloudIndex(0, 7), 7);
}

TEST(PlaneObservation, SortsPointsIntoSupportHolesAndShadows) {
    FrontalWall w;
    // Pixel (10, 10): something 0.5 m in front of the wall; pixel (40, 30): seen through a
    // hole, 1 m behind it; pixel (50, 5): missing; pixel (20, 40): 2 cm off, beyond the inlier
    // band at 2 m (3 sigma = 1.7 cm) but within the obstacle margin (3.4 cm): neither.
    const auto put = [&](int u, int v, float z) {
        const Eigen::Vector3d p = w.camera.backProject(u, v, z);
        w.cloud.points[v * w.cloud.width + u] = p.cast<float>();
    };
    put(10, 10, 1.5f);
    put(40, 30, 3.0f);
    w.cloud.points[5 * w.cloud.width + 50] = Point(kNaN, kNaN, kNaN);
    put(20, 40, 1.98f);
    PointGrid grid;
    fillPointGrid(w.cloud, 1, grid);
    const Eigen::Vector3d lens(0.0, 0.12, 0.0);
    PlaneObservation obs;
    observePlane(grid, grid.gridBox({}), w.plane, w.frame, w.raster, lens, DepthTolerance{}, obs);

    EXPECT_EQ(obs.support_points, 64 * 48 - 4);  // all but those four
    EXPECT_EQ(cv::sum(obs.support)[0], obs.support_points);
    EXPECT_EQ(cv::sum(obs.seen)[0], 64 * 48 - 1);  // every finite point's camera ray meets the wall
    // The hole: its camera ray crosses the wall where pixel (40, 30) looks.
    const Eigen::Vector2d hole = w.uvOfPixel(40, 30) * (2.0 / 3.0);
    EXPECT_EQ(cv::sum(obs.behind)[0], 1);
    EXPECT_EQ(at(obs.behind, w.cellOf(hole.x(), hole.y())), 1);
    // The obstacle's projector shadow: the lens ray through it, extended to the wall.
    const Eigen::Vector3d obstacle = w.camera.backProject(10, 10, 1.5);
    const Eigen::Vector3d on_wall = lens + (2.0 - lens.z()) / (obstacle.z() - lens.z()) * (obstacle - lens);
    const Eigen::Vector2d shadow = w.frame.toPlane(on_wall);
    EXPECT_EQ(cv::sum(obs.shadow)[0], 1);
    EXPECT_EQ(at(obs.shadow, w.cellOf(shadow.x(), shadow.y())), 1);
    // Off the plane beyond the margin: the obstacle and the hole, not the point 2 cm off; where
    // their camera rays cross the wall, and which points they are.
    const Eigen::Vector2d obstacle_uv = w.uvOfPixel(10, 10) * (2.0 / 1.5);
    EXPECT_EQ(cv::sum(obs.off)[0], 2);
    EXPECT_EQ(at(obs.off, w.cellOf(hole.x(), hole.y())), 1);
    EXPECT_EQ(at(obs.off, w.cellOf(obstacle_uv.x(), obstacle_uv.y())), 1);
    std::vector<int> off =
        offPlanePoints(grid, grid.gridBox({}), w.plane, w.frame, w.raster, DepthTolerance{}, {-1.4, -1.1}, {1.4, 1.1});
    std::sort(off.begin(), off.end());
    EXPECT_EQ(off, (std::vector<int>{10 * 64 + 10, 30 * 64 + 40}));
    // Only those whose camera ray crosses the wall inside the rectangle asked about.
    const Eigen::Vector2d lo = hole - Eigen::Vector2d(0.2, 0.2), hi = hole + Eigen::Vector2d(0.2, 0.2);
    EXPECT_EQ(offPlanePoints(grid, grid.gridBox({}), w.plane, w.frame, w.raster, DepthTolerance{}, lo, hi),
              (std::vector<int>{30 * 64 + 40}));
    EXPECT_EQ(checkObservedSurface(obs, w.raster, lo, hi, 0.03).outliers, 1);
}

TEST(PlaneObservation, LooksOnlyInsideTheBoxAndTheRaster) {
    FrontalWall w;
    PointGrid grid;
    fillPointGrid(w.cloud, 2, grid);
    PlaneObservation obs;
    // Pixels [0, 32) x [0, 24): the top-left quarter of the image, 16 x 12 grid points.
    observePlane(grid, grid.gridBox({0, 0, 32, 24}), w.plane, w.frame, w.raster, {0, 0.12, 0}, DepthTolerance{}, obs);
    EXPECT_EQ(obs.support_points, 16 * 12);
    // A raster over the right half of the wall only: the top-left points fall outside it.
    w.raster = makeRasterFrame({0.05, -1.1}, {1.4, 1.1}, 0.1);
    observePlane(grid, grid.gridBox({0, 0, 32, 24}), w.plane, w.frame, w.raster, {0, 0.12, 0}, DepthTolerance{}, obs);
    EXPECT_EQ(obs.support_points, 0);
    EXPECT_EQ(cv::sum(obs.seen)[0], 0);
}

TEST(PlaneObservation, SurfaceCheckAgreesWithThePointByPointReference) {
    // A wall with small obstacles in front, at 2 m (simulated Kinect): the check over
    // rectangles across it, read off one observation, against checkSurface.
    const sim::Scenario sc = sim::makeScenario("small_obstacles", 2.0, 20.0);
    const sim::RgbdFrame frame = sim::renderFrame(sc.scene, sim::SensorModel{}, 3);
    const Plane wall = sc.wall;
    const PlaneFrame pf = makePlaneFrame(wall, sc.gravity, wall.project({0, 0, 2}));
    const RasterFrame raster = makeRasterFrame({-1.5, -1.0}, {1.5, 1.2}, 0.01);
    PointGrid grid;
    fillPointGrid(frame.cloud, 2, grid);
    PlaneObservation obs;
    observePlane(grid, grid.gridBox({}), wall, pf, raster, sim::exampleProjector().origin, DepthTolerance{}, obs);
    int compared = 0, rejected = 0;
    for (double u = -1.2; u < 0.8; u += 0.35)
        for (double v = -0.8; v < 0.6; v += 0.3) {
            const Eigen::Vector2d lo(u, v), hi(u + 0.6, v + 0.45);
            const Rectangle rect = makeRectangle(pf, lo, hi);
            const SurfaceCheckResult ref = checkSurface(frame.cloud, pf, rect, DepthTolerance{}, 0.03, 2);
            const SurfaceCheckResult got = checkObservedSurface(obs, raster, lo, hi, 0.03);
            if (ref.points < 500) continue;
            ++compared;
            rejected += !ref.accepted;
            // Cells whose centre is inside vs exact containment: at most half a cell (5 mm)
            // differs along a 2.1 m perimeter, under 2 % of the points here.
            EXPECT_NEAR(got.points, ref.points, 0.02 * ref.points) << u << " " << v;
            EXPECT_NEAR(got.outliers, ref.outliers, 0.02 * ref.points + 2) << u << " " << v;
            EXPECT_EQ(got.outliers,
                      static_cast<int>(
                          offPlanePoints(grid, grid.gridBox({}), wall, pf, raster, DepthTolerance{}, lo, hi).size()));
            if (std::abs(ref.outliers - 0.03 * ref.points) > 0.01 * ref.points) {
                EXPECT_EQ(got.accepted, ref.accepted) << u << " " << v;
            }
        }
    EXPECT_GT(compared, 20);
    EXPECT_GT(rejected, 0);  // some rectangles hold an obstacle
    EXPECT_LT(rejected, compared);
}

TEST(FitIntrinsics, RecoversThePinholeOfADepthImage) {
    CameraIntrinsics k;
    k.width = 160;
    k.height = 120;
    k.fx = 131.0;
    k.fy = 129.5;
    k.cx = 81.2;
    k.cy = 57.9;
    cv::Mat depth(120, 160, CV_16UC1);
    cv::randu(depth, 500, 4000);
    depth(cv::Rect(10, 10, 30, 30)).setTo(0);  // missing readings are skipped
    const Cloud cloud = depthToCloud(depth, k);
    std::vector<int> all(cloud.points.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    const auto fit = fitIntrinsics(cloud, all);
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->fx, k.fx, 1e-3);
    EXPECT_NEAR(fit->fy, k.fy, 1e-3);
    EXPECT_NEAR(fit->cx, k.cx, 1e-3);
    EXPECT_NEAR(fit->cy, k.cy, 1e-3);
    EXPECT_EQ(fit->width, 160);
    EXPECT_EQ(fit->height, 120);

    // Not a pinhole image: shuffled pixels, or an unorganized cloud.
    Cloud shuffled = cloud;
    std::mt19937 rng(1);
    std::shuffle(shuffled.points.begin(), shuffled.points.end(), rng);
    EXPECT_FALSE(fitIntrinsics(shuffled, all));
    Cloud flat = cloud;
    flat.width = static_cast<int>(flat.points.size());
    flat.height = 1;
    EXPECT_FALSE(fitIntrinsics(flat, all));
}
