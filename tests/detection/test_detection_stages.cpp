// The default method's stages, one by one, on inputs whose answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <tuple>

#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/detection/default/planar_regions.hpp"
#include "projsurf/detection/default/step_edges.hpp"
#include "projsurf/detection/default/wall_shape.hpp"
#include "projsurf/detection/image_boxes.hpp"
#include "projsurf/detection/planes/point_sampling.hpp"
#include "projsurf/detection/planes/vertical_planes.hpp"
#include "projsurf/detection/planes/virtual_depth_image.hpp"
#include "projsurf/detection/projector_footprint.hpp"
#include "projsurf/detection/rectangle_growth.hpp"

using namespace projsurf;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();

/// An organized cloud of a frontal wall at depth z, seen by `camera`, with NaN where `hole`.
Cloud wallImage(const CameraIntrinsics &camera, double z, const cv::Rect &hole = {}) {
    Cloud c;
    c.width = camera.width;
    c.height = camera.height;
    for (int v = 0; v < camera.height; ++v)
        for (int u = 0; u < camera.width; ++u)
            c.points.push_back(hole.contains({u, v}) ? Point(kNaN, kNaN, kNaN)
                                                     : camera.backProject(u, v, z).cast<float>());
    return c;
}

/// Counts views of an observation whose cells are set by hand.
PlaneObservation observation(int rows, int cols) {
    PlaneObservation o;
    for (cv::Mat *m : {&o.support, &o.behind, &o.shadow, &o.seen, &o.off}) *m = cv::Mat::zeros(rows, cols, CV_32SC1);
    return o;
}

}  // namespace

TEST(PointSampling, OrganizedCloudIsSampledOnAPixelGridOfFinitePoints) {
    CameraIntrinsics cam;
    const Cloud cloud = wallImage(cam, 2.0, cv::Rect(0, 0, 320, 480));  // left half missing
    const std::vector<int> s = samplePoints(cloud, 12000);
    // 640 x 480 / 12000 -> every 5th pixel; only the right half is finite.
    EXPECT_NEAR(static_cast<double>(s.size()), 64.0 * 96.0, 200.0);
    for (int i : s) {
        EXPECT_TRUE(isFinite(cloud.points[i]));
        EXPECT_GE(i % cloud.width, 320);
    }
}

TEST(PointSampling, UnorganizedCloudKeepsEveryKthFinitePoint) {
    Cloud cloud;
    for (int i = 0; i < 10000; ++i) cloud.points.emplace_back(i % 7 == 0 ? kNaN : 0.001f * i, 0.0f, 2.0f);
    cloud.width = static_cast<int>(cloud.points.size());
    const std::vector<int> s = samplePoints(cloud, 1000);
    EXPECT_NEAR(static_cast<double>(s.size()), 1000.0, 100.0);
    for (int i : s) EXPECT_TRUE(isFinite(cloud.points[i]));
}

TEST(PointSampling, SpacingOfAWallIsTheDistanceBetweenNeighbouringPixels) {
    CameraIntrinsics cam;
    const Cloud cloud = wallImage(cam, 2.0);
    std::vector<int> inliers;
    for (int v = 10; v < 470; v += 7)
        for (int u = 10; u < 630; u += 7) inliers.push_back(v * cam.width + u);
    const Plane wall = makePlane({0, 0, -1}, 2.0);
    // 2 px apart at 2 m with f = 525 px.
    EXPECT_NEAR(sampleSpacing(cloud, inliers, wall, 2, DepthTolerance{}, 0.0, 1), 2.0 * 2.0 / cam.fx, 1e-4);
}

TEST(VerticalPlanes, FindsBothWallsButNotTheFloorAndMergesASlice) {
    std::vector<Point> pts;
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 3000; ++i)
        pts.emplace_back(u(rng), u(rng), i % 2 ? 3.0f : 3.02f);                    // back wall, two 2 cm slices
    for (int i = 0; i < 1500; ++i) pts.emplace_back(1.5f, u(rng), 2.0f + u(rng));  // side wall
    for (int i = 0; i < 3000; ++i) pts.emplace_back(u(rng), 1.0f, 2.0f + u(rng));  // floor (y down)
    std::vector<float> band(pts.size(), 0.015f);  // narrower than the slices are apart: RANSAC takes one at a time
    VerticalPlaneOptions opt;
    opt.min_points = 200;
    std::mt19937 ransac(7);
    const auto planes = findVerticalPlanes(pts, band, Eigen::Vector3d::UnitY(), DepthTolerance{}, opt, ransac);
    ASSERT_EQ(planes.size(), 2u);
    EXPECT_GT(std::abs(planes[0].plane.normal.z()), 0.99);  // the back wall, both slices
    EXPECT_NEAR(std::abs(planes[0].plane.d), 3.01, 0.02);
    EXPECT_GE(planes[0].inliers.size(), 2900u);
    EXPECT_GT(std::abs(planes[1].plane.normal.x()), 0.99);                      // the side wall
    for (const auto &p : planes) EXPECT_LT(std::abs(p.plane.normal.y()), 0.1);  // never the floor
}

TEST(ObservedFreeSurface, ClosesSampleGapsIgnoresLoneNoiseAndSaysWhyCellsAreNotFree) {
    PlaneObservation o = observation(40, 60);
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 60; c += 2) o.support.at<int>(r, c) = 3;  // every other column sampled
    for (int r = 10; r < 40; ++r)
        for (int c = 30; c < 40; ++c) o.support.at<int>(r, c) = 0;  // no reading here
    o.shadow.at<int>(5, 5) = 1;                                     // a lone noisy point
    for (int r = 20; r < 26; ++r)
        for (int c = 5; c < 15; ++c) o.shadow.at<int>(r, c) = 2;  // something in front
    for (int r = 2; r < 6; ++r)
        for (int c = 45; c < 55; ++c) o.behind.at<int>(r, c) = 9;  // seen through
    const SurfaceCells cells = observedFreeSurface(o, 1, 2);
    auto state = [&](int r, int c) { return static_cast<CellState>(cells.state.at<uchar>(r, c)); };
    EXPECT_EQ(state(5, 5), CellState::Free);  // the lone point is noise, the gap is closed
    EXPECT_EQ(state(5, 6), CellState::Free);
    EXPECT_EQ(state(22, 10), CellState::InFront);
    EXPECT_EQ(state(3, 50), CellState::SeenThrough);
    EXPECT_EQ(state(30, 35), CellState::NoReading);
    EXPECT_EQ(state(0, 20), CellState::Edge);  // the raster's border is trimmed
    EXPECT_EQ(cells.free.at<uchar>(22, 10), 0);
    EXPECT_EQ(cells.free.at<uchar>(15, 20), 255);
}

/// An observation of a wall seen everywhere, 3 readings a cell, each off the wall's shape by
/// `offset(r, c)` plus independent noise of `sigma` m.
PlaneObservation offsetObservation(int rows, int cols, double sigma, const std::function<double(int, int)> &offset) {
    PlaneObservation o = observation(rows, cols);
    o.near = cv::Mat::zeros(rows, cols, CV_32SC1);
    o.offset = cv::Mat::zeros(rows, cols, CV_32FC1);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, sigma);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            o.support.at<int>(r, c) = o.seen.at<int>(r, c) = o.near.at<int>(r, c) = 3;
            for (int k = 0; k < 3; ++k) o.offset.at<float>(r, c) += static_cast<float>(offset(r, c) + noise(rng));
        }
    return o;
}

TEST(ObservedFreeSurface, AFrameTwoCentimetresProudIsNotFreeOverAreaThoughEachReadingIsWithinTheBand) {
    // 1 cm cells, 9 mm of noise per reading (Kinect v1 at 2.5 m: a 3-sigma band of 2.7 cm).
    const auto wall = [](int r, int c) {
        if (r >= 20 && r < 50 && c >= 10 && c < 50) return 0.02;    // a picture frame 2 cm proud
        if (r >= 20 && r < 50 && c >= 70 && c < 110) return 0.003;  // a whiteboard 3 mm proud
        return 0.0;
    };
    const PlaneObservation o = offsetObservation(70, 130, 0.009, wall);
    const SurfaceCells cells = observedFreeSurface(o, 1, 2, ProudEvidence{}, 0.01);
    auto state = [&](int r, int c) { return static_cast<CellState>(cells.state.at<uchar>(r, c)); };
    for (int r = 24; r < 46; r += 3)
        for (int c = 14; c < 46; c += 3) EXPECT_EQ(state(r, c), CellState::Proud) << r << " " << c;
    int free_board = 0, free_wall = 0;
    for (int r = 20; r < 50; ++r)
        for (int c = 70; c < 110; ++c) free_board += state(r, c) == CellState::Free;
    for (int r = 55; r < 69; ++r)
        for (int c = 1; c < 129; ++c) free_wall += state(r, c) == CellState::Free;
    EXPECT_EQ(free_board, 30 * 40);  // the whiteboard stays free
    EXPECT_EQ(free_wall, 14 * 128);  // and the plain wall
    // Off: the same readings are free (each is within the band).
    ProudEvidence off;
    off.enabled = false;
    EXPECT_EQ(observedFreeSurface(o, 1, 2, off, 0.01).state.at<uchar>(35, 30), static_cast<uchar>(CellState::Free));
}

TEST(ObservedFreeSurface, TheNoiseOfAWindowMeanIsMeasuredOnTheWallNotAssumedIndependent) {
    // A sensor whose error is correlated in patches of 8 cm (+-1.8 cm, a stereo unit's): the
    // window means spread by far more than 9 mm / sqrt(147) allows, and no patch is an obstacle.
    const auto patches = [](int r, int c) { return ((r / 8 + c / 8) % 2 ? 0.018 : -0.018); };
    const PlaneObservation o = offsetObservation(70, 130, 0.009, patches);
    ProudEvidence proud;
    proud.min_offset = 0.01;
    const SurfaceCells cells = observedFreeSurface(o, 1, 2, proud, 0.01);
    EXPECT_EQ(cv::countNonZero(cells.state == static_cast<int>(CellState::Proud)), 0);
}

TEST(StepEdges, AFrameOnABentWallIsBoundedByItsStepsWhereItsMeanIsNot) {
    // 1 cm cells, 13 mm of noise per reading and a smooth bend of +-2.5 cm over 1.1 m (a
    // Kinect v1 at 3 m: its distortion at that depth), a frame 3 cm proud: the window means over
    // the wall spread as far as the frame stands, but the frame's border is a sharp step.
    constexpr double kPi = 3.14159265358979;
    const auto wall = [&](int r, int c) {
        const double bend = 0.025 * std::sin(2 * kPi * c / 110.0) * std::cos(2 * kPi * r / 110.0);
        if (r >= 40 && r < 80 && c >= 60 && c < 110) return bend + 0.03;    // a frame 50 x 40 cm
        if (r >= 40 && r < 80 && c >= 150 && c < 200) return bend + 0.003;  // a poster
        return bend;
    };
    const PlaneObservation o = offsetObservation(120, 240, 0.013, wall);
    const cv::Mat edges = stepEdgeCells(o, StepEvidence{}, 0.01);
    ASSERT_FALSE(edges.empty());
    // Along each side of the frame (away from its corners), the border is marked within a cell.
    auto marked = [&](int r, int c) {
        for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc)
                if (edges.at<uchar>(r + dr, c + dc)) return true;
        return false;
    };
    int top = 0, bottom = 0, left = 0, right = 0;
    for (int c = 70; c < 100; ++c) top += marked(40, c), bottom += marked(79, c);
    for (int r = 50; r < 70; ++r) left += marked(r, 60), right += marked(r, 109);
    EXPECT_GE(top, 27);
    EXPECT_GE(bottom, 27);
    EXPECT_GE(left, 18);
    EXPECT_GE(right, 18);
    // Nothing on the poster's border or on the bent wall away from the frame.
    cv::Mat away = edges.clone();
    away(cv::Rect(55, 35, 60, 50)).setTo(0);
    EXPECT_EQ(cv::countNonZero(away), 0);
    // So a rectangle over part of the frame is not free; off, the same readings are.
    const SurfaceCells cells = observedFreeSurface(o, 1, 2, ProudEvidence{}, 0.01, StepEvidence{});
    EXPECT_EQ(cells.free.at<uchar>(40, 85), 0);
    StepEvidence off;
    off.enabled = false;
    EXPECT_EQ(observedFreeSurface(o, 1, 2, ProudEvidence{}, 0.01, off).free.at<uchar>(40, 85), 255);
}

TEST(RectangleGrowth, GrowsAgainstTheExactFootprintAndStopsAtWhatIsNotFree) {
    const Plane wall = makePlane({0, 0, -1}, 2.0);
    const PlaneFrame frame = makePlaneFrame(wall, Eigen::Vector3d::UnitY(), {0, 0, 2});
    const RasterFrame raster = makeRasterFrame({-1.0, -1.0}, {1.0, 1.0}, 0.01);
    cv::Mat surface(raster.rows, raster.cols, CV_8UC1, cv::Scalar(255));
    const std::array<Eigen::Vector2d, 4> footprint{Eigen::Vector2d(-0.503, 0.4), Eigen::Vector2d(0.503, 0.4),
                                                   Eigen::Vector2d(0.503, -0.4), Eigen::Vector2d(-0.503, -0.4)};
    const Rectangle start = makeRectangle(frame, {-0.2, -0.1}, {0.2, 0.1});  // 2:1, inside
    const Rectangle grown = growRectangle(start, frame, raster, surface, footprint, 2.0);
    EXPECT_NEAR(grown.width, 1.006, 0.002);  // limited by the footprint's width, to a fraction of a cell
    EXPECT_NEAR(grown.height, 0.503, 0.001);
    // An obstacle above the start: the rectangle slides down and grows below it.
    surface(cv::Rect(0, 0, raster.cols, raster.toCell({0, 0.15}).y())).setTo(0);
    const Rectangle blocked = growRectangle(start, frame, raster, surface, footprint, 2.0);
    EXPECT_LE(frame.toPlane(blocked.corners[0]).y(), 0.15 + 1e-9);
    EXPECT_GT(blocked.height, 0.3 + 0.05);  // more than fits about the start (0.3), by sliding down
}

TEST(ProjectorFootprint, CornerRaysMeetTheWallAndMissAPlaneBehindTheLens) {
    const Plane wall = makePlane({0, 0, -1}, 2.0);
    const PlaneFrame frame = makePlaneFrame(wall, Eigen::Vector3d::UnitY(), {0, 0, 2});
    const std::array<Eigen::Vector3d, 4> rays{Eigen::Vector3d(-0.5, -0.3, 1), Eigen::Vector3d(0.5, -0.3, 1),
                                              Eigen::Vector3d(0.5, 0.3, 1), Eigen::Vector3d(-0.5, 0.3, 1)};
    const auto f = footprintOnPlane(wall, frame, Eigen::Vector3d::Zero(), rays);
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(f->uv[0].x(), -1.0, 1e-9);  // top-left: left of and above the centre
    EXPECT_NEAR(f->uv[0].y(), 0.6, 1e-9);
    EXPECT_TRUE(insideConvex(f->uv, {0.9, -0.5}));
    EXPECT_NEAR((quadCentre(f->uv) - Eigen::Vector2d(0.0, 0.0)).norm(), 0.0, 1e-9);  // the rays are symmetric
    EXPECT_FALSE(insideConvex(f->uv, {1.1, 0.0}));
    EXPECT_FALSE(footprintOnPlane(makePlane({0, 0, 1}, 2.0), frame, Eigen::Vector3d::Zero(), rays).has_value());
}

TEST(ImageBoxes, BoxesHoldWhatTheyAreAboutAndSayAllWhenAPointIsBehindTheCamera) {
    CameraIntrinsics cam;
    const cv::Rect box = pixelBox(cam, {{-0.2, -0.1, 2.0}, {0.3, 0.2, 2.5}}, 3);
    const Eigen::Vector2d a = cam.project({-0.2, -0.1, 2.0}), b = cam.project({0.3, 0.2, 2.5});
    EXPECT_TRUE(box.contains({static_cast<int>(a.x()), static_cast<int>(a.y())}));
    EXPECT_TRUE(box.contains({static_cast<int>(b.x()), static_cast<int>(b.y())}));
    EXPECT_LT(box.area(), 640 * 480 / 4);
    EXPECT_TRUE(pixelBox(cam, {{0, 0, 2}, {0, 0, -1}}, 0).empty());
    EXPECT_TRUE(pixelBox(cam, {{0, 0, 2}, {kNaN, 0, 2}}, 0).empty());
    // The beam from a lens below the camera towards a raster on a wall is seen below the raster.
    const Plane wall = makePlane({0, 0, -1}, 3.0);
    const PlaneFrame frame = makePlaneFrame(wall, Eigen::Vector3d::UnitY(), {0, 0, 3});
    const RasterFrame raster = makeRasterFrame({-0.2, -0.2}, {0.2, 0.2}, 0.01);
    const cv::Rect beam = beamImageBox(cam, frame, raster, {0, 0.3, 0}, 1.0, 0);
    const cv::Rect wall_only = pixelBox(cam, {frame.toCamera({-0.2, -0.2}), frame.toCamera({0.2, 0.2})}, 0);
    EXPECT_EQ(beam & wall_only, wall_only);
    EXPECT_GT(beam.br().y, wall_only.br().y + 30);
    // Index boxes: where the points lie in the image.
    const Cloud cloud = wallImage(cam, 2.0);
    EXPECT_EQ(indexImageBox(cloud, {5 * 640 + 7, 9 * 640 + 20}, 1), cv::Rect(6, 4, 16, 7));
}

namespace {

/// A frontal wall at depth z seen by `camera`, bent by `bend(x, y)` (m, towards the camera),
/// with independent depth noise of `sigma` (m), and what `box` says stands proud of it.
Cloud bentWall(const CameraIntrinsics &cam, double z, const std::function<double(double, double)> &bend, double sigma,
               unsigned seed, const cv::Rect &box = {}, double box_height = 0.0) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    Cloud c;
    c.width = cam.width;
    c.height = cam.height;
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            const Eigen::Vector3d ray = cam.backProject(u, v, 1.0);
            const double x = ray.x() * z, y = ray.y() * z;
            double depth = z - bend(x, y) - (box.contains({u, v}) ? box_height : 0.0);
            depth += sigma > 0 ? noise(rng) : 0.0;
            c.points.push_back((ray * depth).cast<float>());
        }
    return c;
}

/// The points of `sample` and the default tolerance's inlier band at each.
std::pair<std::vector<Point>, std::vector<float>> sampledWithBands(const Cloud &cloud, const std::vector<int> &sample) {
    std::pair<std::vector<Point>, std::vector<float>> out;
    const DepthTolerance tol;
    for (int i : sample) {
        out.first.push_back(cloud.points[i]);
        out.second.push_back(tol.band(cloud.points[i].z()));
    }
    return out;
}

/// A frontal bent wall at depth z (bentWall), its 12000-point sample with their bands, and the
/// plane and upright frame the shape is fitted about.
struct WallSample {
    Cloud cloud;
    std::vector<int> sample;
    std::vector<Point> pts;
    std::vector<float> band;
    Plane wall;
    PlaneFrame frame;
};

WallSample frontalWallSample(double z, const std::function<double(double, double)> &bend, double sigma, unsigned seed,
                             const cv::Rect &box = {}, double box_height = 0.0) {
    WallSample w;
    w.cloud = bentWall(CameraIntrinsics{}, z, bend, sigma, seed, box, box_height);
    w.sample = samplePoints(w.cloud, 12000);
    std::tie(w.pts, w.band) = sampledWithBands(w.cloud, w.sample);
    w.wall = makePlane({0, 0, -1}, z);
    w.frame = makePlaneFrame(w.wall, Eigen::Vector3d::UnitY(), {0, 0, z});
    return w;
}

}  // namespace

TEST(WallShape, FollowsASmoothBendButNotWhatStandsProudOfTheWall) {
    auto bend = [](double x, double y) { return 0.012 * (x * x + y * y) - 0.01 * x; };  // 4 cm at the image corners
    const WallSample w = frontalWallSample(2.5, bend, 0.004, 3, cv::Rect(400, 100, 120, 120), 0.10);
    const auto &[cloud, sample, pts, band, wall, frame] = w;
    const auto shape = fitWallShape(pts, band, wall, frame);
    ASSERT_TRUE(shape.has_value());
    // Plane coordinates: u = x (right), v = -y (up).
    for (const Eigen::Vector2d &uv : {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.9, 0.6), Eigen::Vector2d(-1.0, -0.6)})
        EXPECT_NEAR(shape->height(uv), bend(uv.x(), -uv.y()), 0.004) << uv.transpose();
    // The noise about the shape is the sensor's, not the box's.
    EXPECT_NEAR(shape->noise_k * 2.5 * 2.5, 0.004, 0.0015);
    EXPECT_NEAR(localNoiseK(cloud, sample, band, wall, 2.5, 8) * 2.5 * 2.5, 0.004, 0.001);
    // Too few points: no shape.
    EXPECT_FALSE(
        fitWallShape({pts.begin(), pts.begin() + 10}, {band.begin(), band.begin() + 10}, wall, frame).has_value());
}

TEST(WallShape, AFarWallMayBendAsMuchAsTheSensorsDisparityErrorGrows) {
    // A wall at 4 m bent by 11 cm at the image corners (a Kinect v1's +-3-5 cm at 3 m, grown
    // with z^2): more than the 8 cm allowed at any depth, less than 0.0089 z^2 = 13.5 cm there.
    auto bend = [](double x, double y) { return 0.0118 * (x * x + y * y); };
    const WallSample w = frontalWallSample(4.0, bend, 0.010, 5);
    const auto &[cloud, sample, pts, band, wall, frame] = w;
    const auto shape = fitWallShape(pts, band, wall, frame);
    ASSERT_TRUE(shape.has_value());
    for (const Eigen::Vector2d &uv : {Eigen::Vector2d(0, 0), Eigen::Vector2d(2.0, 1.4), Eigen::Vector2d(-2.0, -1.4)})
        EXPECT_NEAR(shape->height(uv), bend(uv.x(), -uv.y()), 0.01) << uv.transpose();
    // With the bend held to 8 cm at every depth, the same wall gets no shape.
    WallShapeOptions flat_limit;
    flat_limit.bend_per_z2 = 0.0;
    EXPECT_FALSE(fitWallShape(pts, band, wall, frame, flat_limit).has_value());
}

TEST(WallShape, ItsReliefFollowsADistortionWaveAQuadraticCannotButNotABoxProudOfTheWall) {
    // A Kinect-v1-like distortion (features of about 100 px: waves of 1 m, 210 px, at 2.5 m) of
    // 2 cm amplitude, and a box 8 cm proud.
    CameraIntrinsics cam;
    auto wave = [](double x, double y) { return 0.02 * std::sin(2 * M_PI * x / 1.0) * std::cos(2 * M_PI * y / 1.0); };
    const cv::Rect box(420, 120, 90, 90);
    const Cloud cloud = bentWall(cam, 2.5, wave, 0.003, 5, box, 0.08);
    const std::vector<int> sample = samplePoints(cloud, 12000);
    const auto [pts, band] = sampledWithBands(cloud, sample);
    const Plane wall = makePlane({0, 0, -1}, 2.5);
    const PlaneFrame frame = makePlaneFrame(wall, Eigen::Vector3d::UnitY(), {0, 0, 2.5});
    WallShapeOptions flat;
    flat.relief.enabled = false;
    const auto with = fitWallShape(pts, band, wall, frame, {}, cam.fx);
    const auto without = fitWallShape(pts, band, wall, frame, flat, cam.fx);
    ASSERT_TRUE(with && without);
    EXPECT_FALSE(with->relief.empty());
    EXPECT_TRUE(without->relief.empty());
    // On the wall away from the box (plane coordinates: u = x, v = -y): the relief follows the
    // wave, the quadratic alone misses it by about its amplitude somewhere.
    double worst_with = 0.0, worst_without = 0.0, sum_with = 0.0;
    int n = 0;
    for (double x = -0.9; x <= 0.9; x += 0.05)
        for (double y = -0.6; y <= 0.6; y += 0.05) {
            const Eigen::Vector2d uv(x, -y);
            const Eigen::Vector2d px = cam.project(Eigen::Vector3d(x, y, 2.5));
            if (std::abs(px.x() - (box.x + box.width / 2)) < 90 && std::abs(px.y() - (box.y + box.height / 2)) < 90)
                continue;
            worst_with = std::max(worst_with, std::abs(with->height(uv) - wave(x, y)));
            sum_with += std::abs(with->height(uv) - wave(x, y));
            ++n;
            worst_without = std::max(worst_without, std::abs(without->height(uv) - wave(x, y)));
        }
    EXPECT_LT(worst_with, 0.008);
    EXPECT_LT(sum_with / n, 0.004);
    EXPECT_GT(worst_without, 0.015);
    // The box (8 cm proud) is not followed: the relief stays near the wall at its centre.
    const Eigen::Vector3d centre = cam.backProject(box.x + box.width / 2.0, box.y + box.height / 2.0, 2.5);
    const Eigen::Vector2d cuv(centre.x(), -centre.y());
    EXPECT_LT(with->height(cuv) - wave(centre.x(), centre.y()), 0.03);
}

TEST(PlanarRegions, FindsEachWallOfACornerOnceAndNeverTheFloorWhateverTheOrder) {
    // A room corner seen by a level camera: a back wall at z = 3, a side wall at x = 1, a floor at y = 1.
    CameraIntrinsics cam;
    Cloud c;
    c.width = cam.width;
    c.height = cam.height;
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 0.003);
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            const Eigen::Vector3d r = cam.backProject(u, v, 1.0);
            double t = 3.0 / r.z();
            if (r.x() > 0) t = std::min(t, 1.0 / r.x());
            if (r.y() > 0) t = std::min(t, 1.0 / r.y());
            c.points.push_back((r * (t + noise(rng))).cast<float>());
        }
    PointGrid grid;
    fillPointGrid(c, 2, grid);
    const auto regions = findVerticalRegions(grid, Eigen::Vector3d::UnitY(), DepthTolerance{});
    ASSERT_GE(regions.size(), 2u);
    int back = 0, side = 0;
    for (const auto &r : regions) {
        EXPECT_LT(std::abs(r.plane.normal.y()), 0.1);  // never the floor
        if (std::abs(r.plane.normal.z()) > 0.99 && std::abs(r.plane.d - 3.0) < 0.02) ++back;
        if (std::abs(r.plane.normal.x()) > 0.99 && std::abs(r.plane.d - 1.0) < 0.02) ++side;
    }
    EXPECT_EQ(back, 1);
    EXPECT_EQ(side, 1);
    EXPECT_GT(regions[0].points, regions[1].points);  // biggest first
}

namespace {

/// A 640x480 pinhole image of a wall at 2 m with a box in front, 10 % of its pixels without a
/// reading (spread out), as a shuffled point list; `jitter` px moves each ray off its pixel
/// (uniform, a cloud on no pixel grid). `pixel_of` gets each point's pixel (row-major).
Cloud shuffledFrame(double jitter, std::vector<int> *pixel_of = nullptr) {
    const double f = 525.0, cx = 319.5, cy = 239.5;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> off(-jitter, jitter);
    Cloud loose;
    std::vector<int> pixels;
    for (int v = 0; v < 480; ++v)
        for (int u = 0; u < 640; ++u) {
            if ((u * 7 + v * 3) % 10 == 0) continue;
            const double x = (u + off(rng) - cx) / f, y = (v + off(rng) - cy) / f;
            const bool box = u > 250 && u < 350 && v > 300 && v < 420;
            const double z = box ? 1.5 : 2.0;
            loose.points.emplace_back(static_cast<float>(x * z), static_cast<float>(y * z), static_cast<float>(z));
            pixels.push_back(v * 640 + u);
        }
    std::vector<int> order(loose.points.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    Cloud out;
    for (int i : order) out.points.push_back(loose.points[static_cast<std::size_t>(i)]);
    out.width = static_cast<int>(out.points.size());
    if (pixel_of)
        for (int i : order) pixel_of->push_back(pixels[static_cast<std::size_t>(i)]);
    return out;
}

}  // namespace

TEST(VirtualDepthImage, AShuffledFrameComesBackAsTheImageItWas) {
    // The points of a depth image lie on its pixel grid (x/z on a lattice of step 1 / fx): the
    // virtual image is that image, every point on the pixel it was read at.
    std::vector<int> pixel_of;
    const Cloud loose = shuffledFrame(0.0, &pixel_of);
    const auto image = virtualDepthImage(loose, VirtualImageConfig{});
    ASSERT_TRUE(image);
    ASSERT_EQ(image->cloud.width, 640);
    ASSERT_EQ(image->cloud.height, 480);
    for (std::size_t i = 0; i < loose.points.size(); ++i) {
        const auto at = static_cast<std::size_t>(pixel_of[i]);
        ASSERT_EQ(image->source[at], static_cast<int>(i)) << "pixel " << at;
        EXPECT_EQ(image->cloud.points[at], loose.points[i]);
    }
    int holes = 0;
    for (std::size_t at = 0; at < image->cloud.points.size(); ++at) holes += image->source[at] < 0;
    EXPECT_EQ(holes, 640 * 480 - static_cast<int>(loose.points.size()));
    // Cropped (the first 37 columns and 11 rows gone): the grid starts at the first column held.
    Cloud cropped;
    for (std::size_t i = 0; i < loose.points.size(); ++i)
        if (pixel_of[i] % 640 >= 37 && pixel_of[i] / 640 >= 11) cropped.points.push_back(loose.points[i]);
    cropped.width = static_cast<int>(cropped.points.size());
    const auto part = virtualDepthImage(cropped, VirtualImageConfig{});
    ASSERT_TRUE(part);
    EXPECT_EQ(part->cloud.width, 640 - 37);
    EXPECT_EQ(part->cloud.height, 480 - 11);
}

TEST(VirtualDepthImage, ACloudOnNoPixelGridGetsOneAtItsOwnDensity) {
    // Rays moved off their pixels by up to half a pixel (another viewpoint, a voxel grid): the
    // virtual image has about the camera's focal length (its density: sqrt(0.9) of it with 10 %
    // of the readings missing), every pixel holds a point of the input (the nearest of those
    // that fall on it) and says which.
    const Cloud loose = shuffledFrame(0.5);
    const auto image = virtualDepthImage(loose, VirtualImageConfig{});
    ASSERT_TRUE(image);
    EXPECT_TRUE(image->cloud.organized());
    EXPECT_NEAR(image->cloud.width, 640 * std::sqrt(0.9), 12);
    EXPECT_NEAR(image->cloud.height, 480 * std::sqrt(0.9), 9);
    int filled = 0;
    for (std::size_t i = 0; i < image->cloud.points.size(); ++i) {
        const Point &p = image->cloud.points[i];
        if (!isFinite(p)) {
            EXPECT_EQ(image->source[i], -1);
            continue;
        }
        ++filled;
        ASSERT_GE(image->source[i], 0);
        EXPECT_EQ(p, loose.points[static_cast<std::size_t>(image->source[i])]);
    }
    // Rays off a grid fall two to a pixel now and then: most, not all, get one of their own.
    EXPECT_GT(filled, 0.7 * loose.points.size());
    // Neighbouring pixels are neighbouring rays: along a row, x/z grows by about 1/f per pixel.
    const int row = image->cloud.height / 2;
    std::vector<double> steps;
    for (int c = 1; c < image->cloud.width; ++c) {
        const Point &a = image->cloud.points[static_cast<std::size_t>(row) * image->cloud.width + c - 1];
        const Point &b = image->cloud.points[static_cast<std::size_t>(row) * image->cloud.width + c];
        if (isFinite(a) && isFinite(b)) steps.push_back(b.x() / b.z() - a.x() / a.z());
    }
    ASSERT_GT(steps.size(), 300u);
    std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
    EXPECT_NEAR(steps[steps.size() / 2] * 525.0, 1.0 / std::sqrt(0.9), 0.15);
}

TEST(VirtualDepthImage, NotForOrganizedSparseOrStrayClouds) {
    Cloud organized;
    organized.width = 2;
    organized.height = 2;
    organized.points.assign(4, Point(0, 0, 1));
    EXPECT_FALSE(virtualDepthImage(organized, VirtualImageConfig{}));
    Cloud few;
    for (int i = 0; i < 100; ++i) few.points.emplace_back(0.01f * i, 0.0f, 2.0f);
    few.width = 100;
    EXPECT_FALSE(virtualDepthImage(few, VirtualImageConfig{}));  // below min_points
    VirtualImageConfig off;
    off.enabled = false;
    Cloud wall;
    for (int i = 0; i < 4000; ++i) wall.points.emplace_back(0.001f * (i % 100), 0.001f * (i / 100), 2.0f);
    wall.points.emplace_back(1e20f, 0.0f, 1.0f);  // far off the axis: dropped
    wall.points.emplace_back(0.0f, 0.0f, -2.0f);  // behind the camera: dropped
    wall.points.emplace_back(std::numeric_limits<float>::quiet_NaN(), 0.0f, 1.0f);
    wall.width = static_cast<int>(wall.points.size());
    EXPECT_FALSE(virtualDepthImage(wall, off));
    const auto image = virtualDepthImage(wall, VirtualImageConfig{});
    ASSERT_TRUE(image);
    EXPECT_LE(static_cast<long>(image->cloud.points.size()), 2L * 4000);  // the stray point does not spread it
}

TEST(VirtualDepthImage, StrayPointsBeyondTheExtentAreLeftOutOfTheImageAndItsCoverage) {
    // A wall 2 m away scattered off any pixel lattice (so the image is laid out by the points'
    // density) and three points far to the upper left, fewer than the 0.1 % the extent leaves
    // out: they lie beyond the extent on both axes. Before the coverage grid clamped them, they
    // indexed it before its start (caught by UBSan on a real frame's cloud).
    Cloud cloud;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> across(0.0f, 0.1f);
    for (int i = 0; i < 4000; ++i) cloud.points.emplace_back(across(rng), across(rng), 2.0f);
    for (int i = 0; i < 3; ++i) cloud.points.emplace_back(-3.0f - 0.0137f * i, -3.0f - 0.0071f * i, 2.0f);
    cloud.width = static_cast<int>(cloud.points.size());
    const auto image = virtualDepthImage(cloud, VirtualImageConfig{});
    ASSERT_TRUE(image);
    int filled = 0;
    for (std::size_t i = 0; i < image->cloud.points.size(); ++i) {
        if (image->source[i] < 0) continue;
        ++filled;
        EXPECT_LT(image->source[i], 4000) << "a stray point was imaged";
    }
    EXPECT_GT(filled, 2000);  // random points share pixels: about 1 - 1/e of them find one of their own
    EXPECT_LE(static_cast<long>(image->cloud.points.size()), 2L * 4000);  // the strays do not spread it
}
