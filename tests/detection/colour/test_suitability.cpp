// Surface suitability from registered colour and the colour registration check
//: the core on synthetic walls, the detector on the colour suite's scenes, the CLI.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_run.hpp"
#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/detection/colour/surface_suitability.hpp"
#include "projsurf/detection/default/observed_free_space.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/point_grid.hpp"
#include "eval/realistic/colour_suite.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/ray_cast.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/wall_frame.hpp"

using namespace projsurf::eval;  // the evaluation under test

namespace fs = std::filesystem;
using namespace projsurf;

namespace {

const CameraIntrinsics kCam{};  // 640 x 480, f = 525 px

/// A frontal wall `z` m away filling the image, with a box `box_out` m in front of it over
/// the pixels `box` (none when empty).
Cloud wallCloud(double z, const cv::Rect &box = {}, double box_out = 0.5) {
    cv::Mat depth(kCam.height, kCam.width, CV_16U, cv::Scalar(z * 1000.0));
    if (!box.empty()) depth(box).setTo((z - box_out) * 1000.0);
    return depthToCloud(depth, kCam);
}

/// A light wall colour with, in `dark`, a near-black patch and, in `chequer`, 8 px black and
/// white squares.
cv::Mat wallColour(const cv::Rect &dark, const cv::Rect &chequer) {
    cv::Mat img(kCam.height, kCam.width, CV_8UC3, cv::Scalar(200, 205, 210));
    if (!dark.empty()) img(dark).setTo(cv::Scalar(12, 12, 14));
    for (int v = chequer.y; v < chequer.y + chequer.height; ++v)
        for (int u = chequer.x; u < chequer.x + chequer.width; ++u)
            if (((u / 8) + (v / 8)) % 2) img.at<cv::Vec3b>(v, u) = cv::Vec3b(20, 20, 20);
    return img;
}

struct WallRaster {
    Plane plane;
    PlaneFrame frame;
    RasterFrame raster;
};

/// The plane z = `z` with a 1 cm raster over what the camera sees of it.
WallRaster frontalRaster(double z) {
    WallRaster w;
    w.plane = makePlane(Eigen::Vector3d(0, 0, -1), z);
    w.frame = makePlaneFrame(w.plane, Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, z));
    const double hx = 320.0 / 525.0 * z, hy = 240.0 / 525.0 * z;
    w.raster = makeRasterFrame({-hx, -hy}, {hx, hy}, 0.01);
    return w;
}

/// The Unfit verdict of the cell under pixel (u, v) of the frontal wall.
Unfit unfitAt(const CellSuitability &s, const WallRaster &w, double z, int u, int v) {
    const Eigen::Vector3d p((u - kCam.cx) * z / kCam.fx, (v - kCam.cy) * z / kCam.fy, z);
    const Eigen::Vector2d cell = w.raster.toCell(w.frame.toPlane(p));
    return static_cast<Unfit>(s.unfit.at<uchar>(static_cast<int>(cell.y()), static_cast<int>(cell.x())));
}

CellSuitability judge(const Cloud &cloud, const WallRaster &w, const SuitabilityOptions &options = {}) {
    PointGrid grid;
    fillPointGrid(cloud, 2, grid);
    CellSuitability s;
    cellSuitability(grid, grid.gridBox(cv::Rect()), cloud.colours, w.plane, w.frame, w.raster, DepthTolerance{},
                    WallShape{}, options, s);
    return s;
}

/// Paints 8 px squares (chequer) or 8 px columns (stripes) of greys a and b over `r`.
void paintPattern(cv::Mat &img, const cv::Rect &r, int a, int b, bool chequer) {
    for (int v = r.y; v < r.y + r.height; ++v)
        for (int u = r.x; u < r.x + r.width; ++u) {
            const bool odd = ((u / 8) + (chequer ? v / 8 : 0)) % 2;
            img.at<cv::Vec3b>(v, u) = cv::Vec3b::all(static_cast<uchar>(odd ? b : a));
        }
}

}  // namespace

TEST(Suitability, DarkAndEdgyCellsAreFlaggedPlainOnesNot) {
    const double z = 2.5;
    Cloud cloud = wallCloud(z);
    const cv::Rect dark(80, 100, 120, 100), chequer(400, 220, 140, 120);
    ASSERT_TRUE(attachColour(cloud, wallColour(dark, chequer)));
    const WallRaster w = frontalRaster(z);
    const CellSuitability s = judge(cloud, w);
    ASSERT_FALSE(s.empty());
    EXPECT_EQ(unfitAt(s, w, z, 140, 150), Unfit::Dark);
    EXPECT_EQ(unfitAt(s, w, z, 470, 280), Unfit::Textured);
    EXPECT_EQ(unfitAt(s, w, z, 300, 400), Unfit::None);  // plain wall
    EXPECT_EQ(unfitAt(s, w, z, 320, 60), Unfit::None);
    // Plain wall, dark and textured areas in about their true proportions.
    const double share = static_cast<double>(cv::countNonZero(s.unfit)) / s.unfit.total();
    const double truth = (dark.area() + chequer.area()) / (640.0 * 480.0);
    EXPECT_NEAR(share, truth, 0.03);
}

TEST(Suitability, WeakTextureNearWideTextureIsTexturedAloneFit) {
    // Stripes of 200 and 140 grey (window contrast 0.13-0.18: below the texture level, above
    // the weak one) beside a chequer of 200 and 110 (0.29) are part of it, as far as the
    // growth reaches; the same stripes on their own are fit.
    const double z = 2.5;
    Cloud cloud = wallCloud(z);
    cv::Mat img = wallColour({}, {});
    paintPattern(img, cv::Rect(60, 60, 120, 140), 200, 110, true);
    paintPattern(img, cv::Rect(180, 60, 120, 140), 200, 140, false);   // beside the chequer
    paintPattern(img, cv::Rect(400, 300, 160, 140), 200, 140, false);  // alone
    ASSERT_TRUE(attachColour(cloud, img));
    const WallRaster w = frontalRaster(z);
    SuitabilityOptions far;
    far.texture_growth = 0.15;
    const CellSuitability s = judge(cloud, w, far);
    EXPECT_EQ(unfitAt(s, w, z, 120, 130), Unfit::Textured);  // the chequer
    EXPECT_EQ(unfitAt(s, w, z, 200, 130), Unfit::Textured);  // stripes 9 cm from it
    EXPECT_EQ(unfitAt(s, w, z, 480, 370), Unfit::None);      // stripes alone
    SuitabilityOptions strict = far;
    strict.weak_contrast = strict.max_contrast;  // no hysteresis: the stripes beside it are fit too
    EXPECT_EQ(unfitAt(judge(cloud, w, strict), w, z, 200, 130), Unfit::None);
    SuitabilityOptions near = far;
    near.texture_growth = 0.03;  // the growth stops short of them
    EXPECT_EQ(unfitAt(judge(cloud, w, near), w, z, 200, 130), Unfit::None);
    // On a wall with texture of its own (grain of 6 levels: median window contrast about
    // 0.03), weak is judged against it (8 x 0.03 is above the stripes): they stay fit.
    cv::Mat grain(img.size(), CV_16SC3), grainy;
    cv::RNG rng(7);
    rng.fill(grain, cv::RNG::NORMAL, 0.0, 6.0);
    img.convertTo(grainy, CV_16SC3);
    grainy += grain;
    grainy.convertTo(grainy, CV_8UC3);
    Cloud grainy_cloud = wallCloud(z);
    ASSERT_TRUE(attachColour(grainy_cloud, grainy));
    const CellSuitability g = judge(grainy_cloud, w, far);
    EXPECT_EQ(unfitAt(g, w, z, 120, 130), Unfit::Textured);
    EXPECT_EQ(unfitAt(g, w, z, 200, 130), Unfit::None);
}

TEST(Suitability, AThingTheRasterCutsIsJudgedWithTheRestOfIt) {
    // Weak stripes inside the raster (the projector's reach), the chequer they belong to just
    // outside it: judged with the wall about the raster, the stripes join the chequer.
    const double z = 2.5;
    Cloud cloud = wallCloud(z);
    cv::Mat img = wallColour({}, {});
    paintPattern(img, cv::Rect(400, 140, 140, 200), 200, 110, true);
    paintPattern(img, cv::Rect(540, 140, 40, 200), 200, 140, false);
    ASSERT_TRUE(attachColour(cloud, img));
    WallRaster w = frontalRaster(z);
    const double edge = (540 - kCam.cx) * z / kCam.fx;  // where the chequer ends, m
    w.raster = makeRasterFrame({edge, -0.9}, {edge + 0.4, 0.9}, 0.01);
    const int u = 556, v = 240;  // in the stripes, 8 cm inside the raster
    SuitabilityOptions seen;
    seen.context = 0.1;
    seen.texture_growth = 0.15;
    const CellSuitability s = judge(cloud, w, seen);
    ASSERT_EQ(s.rows, w.raster.rows);
    ASSERT_EQ(s.cols, w.raster.cols);
    EXPECT_EQ(unfitAt(s, w, z, u, v), Unfit::Textured);
    EXPECT_EQ(unfitAt(s, w, z, 620, v), Unfit::None);  // the plain wall beyond
    SuitabilityOptions alone = seen;
    alone.context = 0.0;
    EXPECT_EQ(unfitAt(judge(cloud, w, alone), w, z, u, v), Unfit::None);
}

TEST(Suitability, PlainWallOfAnyRoomPaintIsFit) {
    const double z = 3.0;
    for (const cv::Scalar &paint :
         {cv::Scalar(210, 215, 220), cv::Scalar(150, 190, 215), cv::Scalar(80, 110, 175), cv::Scalar(105, 105, 105)}) {
        Cloud cloud = wallCloud(z);
        cv::Mat img(kCam.height, kCam.width, CV_8UC3, paint);
        cv::Mat noise(img.size(), CV_8SC3);
        cv::randn(noise, 0, 3);
        cv::add(img, noise, img, cv::noArray(), CV_8UC3);
        ASSERT_TRUE(attachColour(cloud, img));
        const WallRaster w = frontalRaster(z);
        const CellSuitability s = judge(cloud, w);
        EXPECT_EQ(cv::countNonZero(s.unfit), 0) << paint;
    }
}

TEST(Suitability, RegionReportsTheShareOfUnfitCells) {
    const double z = 2.5;
    Cloud cloud = wallCloud(z);
    ASSERT_TRUE(attachColour(cloud, wallColour(cv::Rect(0, 0, 320, 480), cv::Rect())));  // left half dark
    const WallRaster w = frontalRaster(z);
    const CellSuitability s = judge(cloud, w);
    const RegionSuitability all = regionSuitability(s, w.raster, {-1.0, -0.5}, {1.0, 0.5});
    EXPECT_NEAR(all.unfit_share, 0.5, 0.05);
    const RegionSuitability right = regionSuitability(s, w.raster, {0.2, -0.5}, {1.0, 0.5});
    EXPECT_NEAR(right.unfit_share, 0.0, 1e-9);
    EXPECT_NEAR(right.mean_luminance, 205.0 / 255.0, 0.02);
    EXPECT_LT(right.contrast, 0.02);
}

TEST(ColourRegistration, RegisteredTrueShiftedFalse) {
    // A wall with three boxes in front; the colour shows the same boxes darker.
    const std::vector<cv::Rect> boxes{{100, 80, 120, 160}, {330, 200, 180, 140}, {250, 50, 60, 60}};
    cv::Mat depth(kCam.height, kCam.width, CV_16U, cv::Scalar(3000));
    cv::Mat colour(kCam.height, kCam.width, CV_8UC3, cv::Scalar(190, 195, 200));
    for (const auto &b : boxes) {
        depth(b).setTo(1800);
        colour(b).setTo(cv::Scalar(60, 90, 120));
    }
    const Cloud cloud = depthToCloud(depth, kCam);
    const RegistrationResult same = checkColourRegistration(cloud, colour, RegistrationOptions{});
    EXPECT_TRUE(same.checked);
    EXPECT_TRUE(same.registered) << same.summary();
    for (const cv::Point shift : {cv::Point(12, 0), cv::Point(-8, 10), cv::Point(0, 15)}) {
        cv::Mat moved;
        const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, shift.x, 0, 1, shift.y);
        cv::warpAffine(colour, moved, m, colour.size(), cv::INTER_NEAREST, cv::BORDER_REPLICATE);
        const RegistrationResult r = checkColourRegistration(cloud, moved, RegistrationOptions{});
        EXPECT_TRUE(r.checked) << shift;
        EXPECT_FALSE(r.registered) << shift << ": " << r.summary();
        EXPECT_EQ(r.best_dx, shift.x);
        EXPECT_EQ(r.best_dy, shift.y);
    }
    // No depth edges: it cannot tell.
    EXPECT_FALSE(checkColourRegistration(wallCloud(2.0), colour, RegistrationOptions{}).checked);
    // Another size: not checked, and no colour attached.
    Cloud small = wallCloud(2.0);
    cv::Mat half;
    cv::resize(colour, half, {320, 240});
    EXPECT_FALSE(checkColourRegistration(small, half, RegistrationOptions{}).checked);
    EXPECT_FALSE(attachColour(small, half));
    EXPECT_FALSE(small.hasColour());
}

namespace {

/// A colour-suite scene through the Kinect v1 model, its registered colour attached.
struct ColourFrame {
    eval::ColourScene scene;
    sim::RgbdFrame frame;
    cv::Mat rgb;
    CameraIntrinsics camera;
};
ColourFrame colourFrame(const std::string &name, double distance, double angle_deg) {
    ColourFrame f;
    f.scene = eval::makeColourScene(name, distance, angle_deg);
    // A box on the floor in front of the wall, right of the axis: depth edges for the
    // registration check (the flat things on the wall have none).
    const sim::WallFrame w(distance, angle_deg);
    sim::wallBox(f.scene.scenario.scene, w, -0.6, 0.9, 0.0, 0.6, 0.4, 0.8, {0.35f, 0.55f, 0.70f}, "box");
    const sim::DepthSensor unit = sim::makeDepthSensor(sim::SensorKind::Kinect1, 0);
    const sim::ExactDepth exact = sim::castExactDepth(f.scene.scenario.scene, unit.camera());
    sim::Lighting light;
    light.ambient = 0.8;
    f.rgb = sim::renderView(f.scene.scenario.scene, sim::cameraView(exact.camera), std::nullopt, light);
    sim::fillFrameDepth(sim::measureDepth(f.scene.scenario.scene, exact, unit, 7), exact.camera, f.frame);
    f.camera = exact.camera;
    return f;
}

}  // namespace

TEST(Suitability, DetectorAvoidsThePicturesAndReportsIt) {
    ColourFrame f = colourFrame("pictures", 2.5, 0.0);
    const Projector projector = sim::exampleProjector();
    DetectorConfig cfg;
    const Detection plain = detectSurface(f.frame.cloud, projector, cfg, f.scene.scenario.gravity);
    ASSERT_TRUE(plain.found);
    EXPECT_FALSE(plain.suitability.used);  // no colour: judged by depth only
    EXPECT_FALSE(detectionToJson(plain, cfg).contains("suitability"));

    ASSERT_TRUE(checkColourRegistration(f.frame.cloud, f.rgb, RegistrationOptions{}).registered);
    ASSERT_TRUE(attachColour(f.frame.cloud, f.rgb));
    const Detection avoid = detectSurface(f.frame.cloud, projector, cfg, f.scene.scenario.gravity);
    ASSERT_TRUE(avoid.found);
    ASSERT_TRUE(avoid.suitability.used);
    EXPECT_EQ(avoid.suitability.mode, "avoid");
    EXPECT_LE(avoid.suitability.unsuitable_share, 0.02);
    EXPECT_LT(avoid.rectangle.area(), plain.rectangle.area());  // without colour it covers a picture
    const auto j = detectionToJson(avoid, cfg);
    ASSERT_TRUE(j.contains("suitability"));
    for (const char *key : {"mode", "mean_albedo", "texture", "unsuitable_share"})
        EXPECT_TRUE(j["suitability"].contains(key));
    // The overlay's states: unfit cells are marked in the shown plane's cell states.
    int unfit = 0;
    for (CellState s : {CellState::Glare, CellState::Dark, CellState::Textured, CellState::Saturated})
        unfit += cv::countNonZero(avoid.debug.cell_state == static_cast<int>(s));
    EXPECT_GT(unfit, 100);

    cfg.suitability.mode = SuitabilityMode::Off;
    const Detection off = detectSurface(f.frame.cloud, projector, cfg, f.scene.scenario.gravity);
    EXPECT_FALSE(off.suitability.used);
    EXPECT_NEAR(off.rectangle.area(), plain.rectangle.area(), 1e-9);

    cfg.suitability.mode = SuitabilityMode::Prefer;
    const Detection prefer = detectSurface(f.frame.cloud, projector, cfg, f.scene.scenario.gravity);
    ASSERT_TRUE(prefer.found);
    EXPECT_EQ(prefer.suitability.mode, "prefer");
    // Prefer's rule: area x (1 - unfit share)^2 at least avoid's area.
    const double k = cfg.suitability.prefer_exponent;
    EXPECT_GE(prefer.rectangle.area() * std::pow(1.0 - prefer.suitability.unsuitable_share, k) + 1e-9,
              avoid.rectangle.area() * std::pow(1.0 - avoid.suitability.unsuitable_share, k) - 1e-3);
}

TEST(Suitability, ColourSuiteQuickMeetsTheUnfitTarget) {
    eval::ColourSuiteOptions o = eval::quickColourSuite();
    o.rounds = 1;
    const eval::ColourSuiteResult r = eval::runColourSuite(o);
    ASSERT_EQ(r.rows.size(), o.cases.size());
    for (const auto &row : r.rows) {
        EXPECT_EQ(row.found, row.rounds) << row.scene.scene;
        if (row.plain)
            EXPECT_LE(row.worst_plain_pct, 2.0) << row.scene.scene;
        else
            EXPECT_LE(row.max_unfit_pct, 2.0) << row.scene.scene;
    }
    EXPECT_NE(eval::colourSuiteMarkdown(r).find("| pictures |"), std::string::npos);
}

namespace {

/// A colour-suite frame written as the CLI reads it: depth.png, camera.yaml, rgb.png and a
/// copy of the colour moved by 14 px named rgb_unregistered.png.
fs::path writeColourFrame(const std::string &name) {
    const fs::path dir = test::freshDir(name);
    ColourFrame f = colourFrame("pictures", 2.5, 0.0);
    cv::imwrite((dir / "depth.png").string(), f.frame.depth);
    writeCamera((dir / "camera.yaml").string(), f.camera);
    cv::imwrite((dir / "rgb.png").string(), f.rgb);
    cv::Mat moved;
    const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, 14, 0, 1, -6);
    cv::warpAffine(f.rgb, moved, m, f.rgb.size(), cv::INTER_NEAREST, cv::BORDER_REPLICATE);
    cv::imwrite((dir / "rgb_unregistered.png").string(), moved);
    // The moved colour under an innocent name: the check, not the name, must catch it.
    cv::imwrite((dir / "colour.png").string(), moved);
    return dir;
}

std::string detectArgs(const fs::path &dir) {
    return "detect --depth " + (dir / "depth.png").string() + " --camera " + (dir / "camera.yaml").string() +
           " --calib " + std::string(PROJSURF_SOURCE_DIR) + "/examples/calib/example_calib.yaml --gravity 0,1,0";
}

}  // namespace

TEST(SuitabilityCli, ModesParsedColourKeyOnlyWithColour) {
    const fs::path dir = writeColourFrame("suitability_cli");
    const auto none = test::cli(detectArgs(dir) + " --json " + (dir / "none.json").string(), dir);
    ASSERT_EQ(none.status, 0) << none.err;
    EXPECT_EQ(test::slurp(dir / "none.json").find("\"suitability\""), std::string::npos);

    const auto avoid = test::cli(
        detectArgs(dir) + " --rgb " + (dir / "rgb.png").string() + " --json " + (dir / "avoid.json").string(), dir);
    ASSERT_EQ(avoid.status, 0) << avoid.err;
    EXPECT_EQ(avoid.err, "");
    const std::string j = test::slurp(dir / "avoid.json");
    EXPECT_NE(j.find("\"suitability\""), std::string::npos);
    EXPECT_NE(j.find("\"mode\": \"avoid\""), std::string::npos);

    const auto off = test::cli(detectArgs(dir) + " --rgb " + (dir / "rgb.png").string() + " --suitability off --json " +
                                   (dir / "off.json").string(),
                               dir);
    ASSERT_EQ(off.status, 0) << off.err;
    EXPECT_EQ(test::slurp(dir / "off.json").find("\"suitability\""), std::string::npos);

    const auto prefer =
        test::cli(detectArgs(dir) + " --rgb " + (dir / "rgb.png").string() + " --suitability prefer", dir);
    ASSERT_EQ(prefer.status, 0) << prefer.err;
    EXPECT_NE(prefer.out.find("\"mode\": \"prefer\""), std::string::npos);

    const auto bad =
        test::cli(detectArgs(dir) + " --rgb " + (dir / "rgb.png").string() + " --suitability sometimes", dir);
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err, "projsurf: error: --suitability: expected 'off', 'avoid' or 'prefer', got 'sometimes'\n");
    fs::remove_all(dir);
}

TEST(SuitabilityCli, UnregisteredColourIsCaughtByTheCheckNotTheName) {
    const fs::path dir = writeColourFrame("suitability_unreg");
    for (const char *name : {"rgb_unregistered.png", "colour.png"}) {
        const fs::path rgb = dir / name;
        const auto r =
            test::cli(detectArgs(dir) + " --rgb " + rgb.string() + " --json " + (dir / "u.json").string(), dir);
        ASSERT_EQ(r.status, 0) << r.err;
        const std::string expect = "projsurf: warning: " + rgb.string() + ": colour is not registered to the depth (";
        EXPECT_EQ(r.err.rfind(expect, 0), 0u) << r.err;
        EXPECT_NE(r.err.find("); not used\n"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(test::slurp(dir / "u.json").find("\"suitability\""), std::string::npos);
    }
    fs::remove_all(dir);
}

TEST(SuitabilityCli, EvalColourOnlyWritesTheColourTable) {
    const fs::path dir = fs::temp_directory_path() / "projsurf_eval_colour_only";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto r = test::cli("eval --colour-only --quick --out " + (dir / "out").string(), dir, 300);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("colour suite: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("scenes meet the targets (2 rounds each"), std::string::npos) << r.out;
    ASSERT_TRUE(fs::exists(dir / "out" / "colour.md"));
    EXPECT_FALSE(fs::exists(dir / "out" / "report.md"));  // the suite alone
    const auto both = test::cli("eval --colour-only --projector-only --out " + (dir / "b").string(), dir);
    EXPECT_NE(both.status, 0);
    fs::remove_all(dir);
}

TEST(Suitability, ColourSitsWhereTheCameraRayMeetsTheWall) {
    // Every reading 3 % too far along its ray (a depth camera's scale bias): the wall's plane
    // is the true one, so a reading's normal foot would sit 3 % of its offset from the image
    // centre too far out (3.4 cm at the dark patch's edge), its ray's meeting with the plane
    // where the colour really is.
    const double z = 2.5;
    cv::Mat depth(kCam.height, kCam.width, CV_16U, cv::Scalar(z * 1.03 * 1000.0));
    Cloud cloud = depthToCloud(depth, kCam);
    const cv::Rect dark(560, 0, 80, 480);  // the right eighth, edge 1.14 m right of the axis
    ASSERT_TRUE(attachColour(cloud, wallColour(dark, cv::Rect())));
    const WallRaster w = frontalRaster(z);
    PointGrid grid;
    fillPointGrid(cloud, 2, grid);
    DepthTolerance wide;  // the bias (7.5 cm) inside the band
    wide.min_band = wide.max_band = 0.1;
    CellSuitability s;
    cellSuitability(grid, grid.gridBox(cv::Rect()), cloud.colours, w.plane, w.frame, w.raster, wide, WallShape{},
                    SuitabilityOptions{}, s);
    ASSERT_FALSE(s.empty());
    // 2 cm each side of the patch's edge on the wall (4 px at 2.5 m).
    EXPECT_EQ(unfitAt(s, w, z, 565, 240), Unfit::Dark);
    EXPECT_EQ(unfitAt(s, w, z, 555, 240), Unfit::None);
}
