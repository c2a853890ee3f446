// The translation layer the CLI, the node and Python share (src/projsurf/frontend/): aspect
// ratios and gravity as users write them, depth images as clouds, the test card, the
// framebuffer render and the progress line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "projsurf/frontend/answer/detection_summary.hpp"
#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/frontend/inputs/stamp_pairing.hpp"
#include "projsurf/frontend/render/framebuffer_render.hpp"
#include "projsurf/frontend/render/progress.hpp"
#include "projsurf/frontend/render/test_card.hpp"
#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/gravity_sanity.hpp"
#include "projsurf/frontend/settings/gravity_warnings.hpp"
#include "projsurf/frontend/settings/ignored_settings.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/types/camera.hpp"
#include "synthetic_rig.hpp"

using namespace projsurf;
using namespace projsurf::frontend;

namespace {

std::string messageOf(const std::function<void()> &f) {
    try {
        f();
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

/// A room seen by a 160x120 camera 1.2 m above the floor, pitched down by `pitch_deg`: the
/// floor and a wall 3 m ahead, in the camera frame. True down: R (0, 1, 0).
Cloud pitchedRoom(double pitch_deg, Eigen::Vector3d &down) {
    // Camera -> level frame; a positive angle about -x turns the optical axis down (y is down).
    const Eigen::Matrix3d R = Eigen::AngleAxisd(-pitch_deg * rig::kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
    down = R.transpose() * Eigen::Vector3d::UnitY();  // level frame -> camera frame
    CameraIntrinsics cam;
    cam.width = 160, cam.height = 120, cam.fx = cam.fy = 130.0, cam.cx = 79.5, cam.cy = 59.5;
    Cloud cloud;
    cloud.width = cam.width;
    cloud.height = cam.height;
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            const Eigen::Vector3d ray_cam = cam.backProject(u, v, 1.0);
            const Eigen::Vector3d ray = R * ray_cam;  // in the level frame (y down)
            double t = std::numeric_limits<double>::infinity();
            if (ray.y() > 1e-6) t = std::min(t, 1.2 / ray.y());  // floor y = 1.2
            if (ray.z() > 1e-6) t = std::min(t, 3.0 / ray.z());  // wall z = 3
            cloud.points.push_back((t * ray_cam).cast<float>());
        }
    return cloud;
}

}  // namespace

TEST(FrontendAspect, ReadsWColonHAndOneNumber) {
    EXPECT_DOUBLE_EQ(parseAspect("--aspect", "16:9"), 16.0 / 9.0);
    EXPECT_DOUBLE_EQ(parseAspect("--aspect", "4:3"), 4.0 / 3.0);
    EXPECT_DOUBLE_EQ(parseAspect("--aspect", "1.5"), 1.5);
}

TEST(FrontendAspect, RefusesWithOneLineThatSaysHowToWriteIt) {
    EXPECT_EQ(messageOf([] { parseAspect("--aspect", "16x9"); }),
              "--aspect: expected a positive aspect ratio W:H, got '16x9' (write 16:9)");
    EXPECT_EQ(messageOf([] { parseAspect("aspect", "16/9"); }),
              "aspect: expected a positive aspect ratio W:H, got '16/9' (write 16:9)");
    for (const char *bad : {"", "abc", "0:1", "1:0", "-4:3", "16:9:1", "1e400", "1000", "16:"})
        EXPECT_NE(messageOf([&] { parseAspect("--aspect", bad); }).find("expected a positive aspect ratio W:H"),
                  std::string::npos)
            << bad;
}

TEST(FrontendSuitabilityMode, ReadsTheThreeWordsAndRefusesOthers) {
    for (const SuitabilityMode m : {SuitabilityMode::Off, SuitabilityMode::Avoid, SuitabilityMode::Prefer})
        EXPECT_EQ(parseSuitabilityMode("--suitability", projsurf::suitabilityModeName(m)), m);
    EXPECT_EQ(parseSuitabilityMode("--suitability", ""), SuitabilityMode::Avoid);  // the default with colour
    EXPECT_EQ(messageOf([] { parseSuitabilityMode("~suitability", "Avoid"); }),
              "~suitability: expected 'off', 'avoid' or 'prefer', got 'Avoid'");
}

TEST(FrontendGravity, ParsesLevelAutoAndVectors) {
    const GravityChoice level = parseGravityChoice("--gravity", "");
    EXPECT_FALSE(level.from_floor);
    EXPECT_EQ(level.gravity, Eigen::Vector3d(0, 1, 0));
    EXPECT_TRUE(parseGravityChoice("--gravity", "auto").from_floor);
    EXPECT_EQ(parseGravityChoice("--gravity", "0,0.9,0.4").gravity, Eigen::Vector3d(0, 0.9, 0.4));
    EXPECT_EQ(parseGravityChoice("~gravity", "0 2 0").gravity, Eigen::Vector3d(0, 2, 0));
    EXPECT_EQ(messageOf([] { parseGravityChoice("--gravity", "0,0,0"); }), "--gravity: the vector is zero");
    EXPECT_NE(messageOf([] { parseGravityChoice("--gravity", "1,2"); }).find("expected three numbers"),
              std::string::npos);
    EXPECT_NE(messageOf([] { parseGravityChoice("--gravity", "down"); }).find("expected three numbers"),
              std::string::npos);
    const double nan3[3] = {0, std::nan(""), 1};
    EXPECT_EQ(messageOf([&] { gravityChoiceFrom("gravity", nan3, 3); }), "gravity: the vector is not finite");
}

TEST(FrontendGravity, AutoTakesDownFromTheFloorElseKeepsTheFallback) {
    Eigen::Vector3d down;
    const Cloud room = pitchedRoom(25.0, down);
    GravityChoice choice = parseGravityChoice("--gravity", "auto");
    const ResolvedGravity r = resolveGravity(choice, room);
    ASSERT_TRUE(r.floor_found);
    EXPECT_LT(std::acos(std::clamp(r.gravity.normalized().dot(down), -1.0, 1.0)) / rig::kDeg, 1.0);
    const auto tilt = floorTiltFromLevelDeg(room);
    ASSERT_TRUE(tilt);
    EXPECT_NEAR(*tilt, 25.0, 1.0);

    // A wall only: no floor, the fallback (a level camera) is kept.
    Cloud wall =
        depthToCloud(cv::Mat(120, 160, CV_16UC1, cv::Scalar(2000)), pinholeCamera("c", 160, 120, 130, 130, 79.5, 59.5));
    const ResolvedGravity none = resolveGravity(choice, wall);
    EXPECT_FALSE(none.floor_found);
    EXPECT_EQ(none.gravity, Eigen::Vector3d(0, 1, 0));
    EXPECT_FALSE(floorTiltFromLevelDeg(wall));
    // A given vector is used as it is, floor or not.
    choice = parseGravityChoice("--gravity", "0,1,0.1");
    EXPECT_EQ(resolveGravity(choice, room).gravity, Eigen::Vector3d(0, 1, 0.1));
}

// Issue 40: an unorganized cloud whose floor and wall are neither level nor vertical for a
// level camera (pitched beyond where the floor search looks) is warned about, and so is one
// whose floor search and largest plane disagree; a lone level wall is not.
TEST(FrontendGravity, AnUnorganizedCloudWhosePlanesAreObliqueForALevelCameraIsWarnedAbout) {
    Eigen::Vector3d down;
    auto unorganized = [](Cloud c) {
        c.width = static_cast<int>(c.points.size());
        c.height = 1;
        return c;
    };
    const Cloud pitched = pitchedRoom(40.0, down);
    EXPECT_FALSE(floorTiltFromLevelDeg(unorganized(pitched)));  // beyond the floor search: no floor warning
    const std::vector<double> planes = largestPlanesToLevelDeg(unorganized(pitched));
    ASSERT_EQ(planes.size(), 2u);
    for (const double a : planes) EXPECT_TRUE(std::abs(a - 40.0) < 2.0 || std::abs(a - 50.0) < 2.0) << a;
    const auto w = levelCameraWarning("--gravity auto", unorganized(pitched));
    ASSERT_TRUE(w);
    EXPECT_EQ(w->rfind("this unorganized cloud does not look like a level camera's view: its 2 largest planes lie ", 0),
              0u)
        << *w;
    EXPECT_NE(w->find("give --gravity auto or the robot's gravity"), std::string::npos) << *w;
    // The level room, unorganized: its floor shows as a strip before the wall, and the floor
    // search takes a plane across the strip and the wall's foot (33 deg); the wall, the largest
    // plane, is vertical: the two disagree, and the warning says so rather than ask for auto.
    const Cloud level = unorganized(pitchedRoom(0.0, down));
    const std::vector<double> level_planes = largestPlanesToLevelDeg(level);
    ASSERT_FALSE(level_planes.empty());
    EXPECT_NEAR(level_planes.front(), 90.0, 2.0);
    const auto tilt = floorTiltFromLevelDeg(level);
    ASSERT_TRUE(tilt && *tilt > kTiltWarningDeg);
    const auto disagree = levelCameraWarning("--gravity auto", level);
    ASSERT_TRUE(disagree);
    EXPECT_NE(disagree->find("deg from horizontal, a wall of a level camera: the two disagree"), std::string::npos)
        << *disagree;
    // A level wall alone, unorganized: a wall is vertical, nothing to say.
    const Cloud wall =
        depthToCloud(cv::Mat(120, 160, CV_16UC1, cv::Scalar(2000)), pinholeCamera("c", 160, 120, 130, 130, 79.5, 59.5));
    EXPECT_FALSE(levelCameraWarning("--gravity auto", unorganized(wall)));
}

TEST(FrontendDepthImage, MillimetresAndMetresGiveTheSameCloud) {
    const CameraIntrinsics cam = pinholeCamera("camera_info", 8, 6, 5.0, 5.5, 3.5, 2.5);
    cv::Mat mm(6, 8, CV_16UC1), m(6, 8, CV_32FC1);
    for (int v = 0; v < 6; ++v)
        for (int u = 0; u < 8; ++u) {
            const int raw = (u == 2 && v == 3) ? 0 : 1000 + 10 * u + 100 * v;
            mm.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(raw);
            m.at<float>(v, u) = raw == 0 ? std::nanf("") : raw * 1e-3f;
        }
    const Cloud a = depthImageToCloud("depth", mm, cam), b = depthImageToCloud("depth", m, cam);
    ASSERT_EQ(a.size(), 48u);
    ASSERT_EQ(b.size(), 48u);
    EXPECT_TRUE(a.organized());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(isFinite(a.points[i]), isFinite(b.points[i])) << i;
        if (isFinite(a.points[i])) {
            EXPECT_LT((a.points[i] - b.points[i]).norm(), 1e-5f) << i;
        }
    }
    EXPECT_FALSE(isFinite(a.points[3 * 8 + 2]));
    const Eigen::Vector3d p = cam.backProject(5, 4, 1.45);
    EXPECT_LT((a.points[4 * 8 + 5].cast<double>() - p).norm(), 1e-5);
}

TEST(FrontendDepthImage, RefusesOtherTypesSizesAndCameras) {
    const CameraIntrinsics cam = pinholeCamera("camera_info", 8, 6, 5.0, 5.0, 3.5, 2.5);
    EXPECT_NE(messageOf([&] {
                  depthImageToCloud("depth", cv::Mat(6, 8, CV_8UC1, cv::Scalar(1)), cam);
              }).find("expected a 16-bit depth image"),
              std::string::npos);
    EXPECT_EQ(messageOf([&] { depthImageToCloud("depth", cv::Mat(5, 8, CV_16UC1, cv::Scalar(1)), cam); }),
              "depth: image is 8x5, the camera's is 8x6");
    EXPECT_NE(messageOf([] { pinholeCamera("camera_info", 8, 6, 0.0, 5.0, 3.5, 2.5); }).find("no focal length"),
              std::string::npos);
    EXPECT_NE(messageOf([] { pinholeCamera("camera_info", 8, 6, 5.0, 5.0, std::nan(""), 2.5); }).find("finite"),
              std::string::npos);
}

TEST(FrontendTestCard, ShowsWhichWayIsUpAndWhereItEnds) {
    const cv::Mat card = testCard({1280, 800});
    ASSERT_EQ(card.type(), CV_8UC3);
    ASSERT_EQ(card.size(), cv::Size(1280, 800));
    auto white_in_rows = [&](int y0, int y1) {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < card.cols; ++x) {
                const cv::Vec3b c = card.at<cv::Vec3b>(y, x);
                n += c[0] > 200 && c[1] > 200 && c[2] > 200;
            }
        return n;
    };
    // The title (white) stands near the bottom; the mirrored band near the top has no white,
    // so a picture upside down is obvious.
    EXPECT_GT(white_in_rows(670, 740), 1000);
    EXPECT_EQ(white_in_rows(40, 70), 0);
    // The green border marks the card's outer pixels, so a cut-off edge is obvious.
    EXPECT_EQ(card.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 220, 0));  // the border
    EXPECT_EQ(card.at<cv::Vec3b>(799, 1279), cv::Vec3b(0, 220, 0));
    // Every size is the size asked for, down to a pixel.
    for (const cv::Size size : {cv::Size(64, 40), cv::Size(3, 2), cv::Size(1, 1)})
        EXPECT_EQ(testCard(size).size(), size);
    EXPECT_TRUE(testCard({0, 0}).empty());
}

TEST(FrontendFramebuffer, WarpsThePictureIntoTheRectangleAndSaysWhenItLetterboxed) {
    const Projector proj = rig::trueProjector();
    const Rectangle rect = rig::rectangleInWorkspace(proj, rig::wall(2.0, 10.0));
    const cv::Mat picture(800, 1280, CV_8UC3, cv::Scalar(255, 255, 255));
    const FramebufferRender same = renderFramebuffer(proj, rect, picture, 0.5);
    ASSERT_TRUE(same.keystone) << same.problem;
    EXPECT_EQ(same.image.size(), cv::Size(proj.width, proj.height));
    EXPECT_FALSE(same.letterboxed);  // the rectangle has the picture's aspect
    EXPECT_GT(cv::countNonZero(same.image.reshape(1)), 0);
    const cv::Mat square(500, 500, CV_8UC3, cv::Scalar(255, 255, 255));
    const FramebufferRender boxed = renderFramebuffer(proj, rect, square, 0.5);
    ASSERT_TRUE(boxed.keystone);
    EXPECT_TRUE(boxed.letterboxed);
    EXPECT_LT(cv::countNonZero(boxed.image.reshape(1)), cv::countNonZero(same.image.reshape(1)));
    // Behind the projector: refused, with the reason.
    Rectangle behind = rect;
    for (auto &c : behind.corners) c.z() = -c.z();
    const FramebufferRender refused = renderFramebuffer(proj, behind, picture, 0.5);
    EXPECT_FALSE(refused.keystone);
    EXPECT_TRUE(refused.image.empty());
    EXPECT_FALSE(refused.problem.empty());
}

TEST(FrontendProgress, InALogWritesALineEveryTenPercent) {
    std::FILE *log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    {
        ProgressLine p("correct", "frames", false, log);
        for (long i = 1; i <= 200; ++i) p.update(i, 200);
        p.finish(200);
    }
    std::rewind(log);
    std::string text;
    char buf[256];
    while (std::fgets(buf, sizeof buf, log)) text += buf;
    std::fclose(log);
    EXPECT_NE(text.find("correct: 0% (1/200 frames)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("correct: 50% (100/200 frames)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("correct: 100% (200/200 frames)\n"), std::string::npos) << text;
    int lines = 0;
    for (char c : text) lines += c == '\n';
    EXPECT_EQ(lines, 11);
}

TEST(FrontendStampPairing, FindsTheSameStampNotTheLatest) {
    StampedBuffer<int> infos(3);
    EXPECT_EQ(infos.exact(1.0), nullptr);
    infos.add(1.0, 10);
    infos.add(1.0333333, 11);
    infos.add(1.0666666, 12);
    ASSERT_NE(infos.exact(1.0333333), nullptr);
    EXPECT_EQ(*infos.exact(1.0333333), 11);
    EXPECT_EQ(infos.exact(1.05), nullptr);
    double at = 0;
    ASSERT_NE(infos.nearest(1.05, at), nullptr);
    EXPECT_EQ(*infos.nearest(1.03, at), 11);
    EXPECT_DOUBLE_EQ(at, 1.0333333);
    infos.add(1.1, 13);  // capacity 3: the oldest goes
    EXPECT_EQ(infos.exact(1.0), nullptr);
    EXPECT_EQ(*infos.exact(1.1), 13);
}

TEST(FrontendSummary, OneLineForAFoundAndANotFoundDetection) {
    Detection det;
    det.reason = "no vertical plane in view";
    EXPECT_EQ(detectionSummary(det), "not found: no vertical plane in view");
    det.reason.clear();
    EXPECT_EQ(detectionSummary(det), "not found: no projection surface found");
    det.found = true;
    det.rectangle.width = 1.344;
    det.rectangle.height = 0.84;
    det.plane.d = 2.0;
    det.orientation_deg = 10.04;
    det.timing_ms["total"] = 2.07;
    EXPECT_EQ(detectionSummary(det), "found 1.34 x 0.84 m (1.13 m^2) on a plane 2.00 m away at 10.0 deg in 2.1 ms");
}

// The warnings on the gravity used, one set of sentences for the CLI, Python and the node, each
// naming the setting as its users write it (frontend/settings/gravity_warnings.hpp).
TEST(FrontendGravityWarnings, NameTheFrontEndsSettingAndSearchTheFloorOnlyWhenAsked) {
    Eigen::Vector3d down;
    const Cloud room = pitchedRoom(25.0, down);
    const GravityWords node{"~gravity", "~gravity auto"};
    GravityUsed used;  // nothing given: a level camera, which the floor says is tilted 25 deg
    used.level_assumed = true;
    std::vector<std::string> w = gravityUsedWarnings(node, used, room);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], *levelCameraWarning("~gravity auto", room));
    EXPECT_NE(w[0].find("tilted 25 deg from level; give ~gravity auto"), std::string::npos) << w[0];
    EXPECT_TRUE(gravityUsedWarnings(node, used, room, false).empty()) << "no floor search when not asked";
    // A z-up world's down taken for the optical frame's.
    used.level_assumed = false;
    used.choice = parseGravityChoice("~gravity", "0,0,-1");
    w = gravityUsedWarnings(node, used, room);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].rfind("~gravity 0,0,-1 points along the camera's optical axis", 0), 0u) << w[0];
    // auto with no floor in view: said on every cloud, no search needed.
    used.choice = parseGravityChoice("~gravity", "auto");
    used.resolved.floor_found = false;
    w = gravityUsedWarnings(node, used, room, false);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "~gravity auto found no floor; assuming a level camera");
    used.resolved.floor_found = true;
    EXPECT_TRUE(gravityUsedWarnings(node, used, room).empty());
}

TEST(FrontendIgnoredSettings, OneSentenceSpelledAsEachFrontEndSpellsTheSetting) {
    auto given = [](const std::string &s) { return s == "max_planes" || s == "voxel_leaf"; };
    EXPECT_EQ(ignoredSettingWarnings(Method::Paper, given, optionName),
              std::vector<std::string>{"--max-planes is ignored by the paper method"});
    EXPECT_EQ(ignoredSettingWarnings(Method::Default, given, [](const std::string &s) { return "~" + s; }),
              std::vector<std::string>{"~voxel_leaf is ignored by the default method"});
    EXPECT_TRUE(ignoredSettingWarnings(Method::Default, [](const std::string &) { return false; }, optionName).empty());
}
