// From PNG frames to a bag and back: `projsurf bag` writes depth images and camera_infos
// (io/rosbag/bag_writer, io/rosbag/ros_messages), `detect --bag` reads them as the node does (each depth
// image with the camera_info of its stamp), picking the topic itself when there is one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/rosbag/bag_writer.hpp"
#include "projsurf/io/rosbag/ros_messages.hpp"
#include "projsurf/io/rosbag/rosbag_depth.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "synthetic_rig.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {

const std::string kCalib = std::string(PROJSURF_SOURCE_DIR) + "/examples/calib/example_calib.yaml";

/// A wall `distance` m ahead, turned by `angle_deg`, as a 16-bit depth image in mm.
cv::Mat wallDepth(const CameraIntrinsics &cam, double distance, double angle_deg) {
    const Plane wall = rig::wall(distance, angle_deg);
    cv::Mat depth(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u)
            if (const auto hit = intersectRay(wall, Eigen::Vector3d::Zero(), cam.backProject(u, v, 1.0)))
                depth.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(std::lround(hit->z() * 1000.0));
    return depth;
}

std::vector<nlohmann::json> jsonLines(const std::string &text) {
    std::vector<nlohmann::json> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(nlohmann::json::parse(line));
    return out;
}

/// dir/frames.bag by `projsurf bag` from 320x240 depth PNGs (dir/depth/0001.png, ...) of a
/// wall at each (distance m, angle deg), 10 frames a second; dir/camera.yaml is their camera.
CliRun wallBag(const fs::path &dir, const std::vector<std::pair<double, double>> &walls) {
    CameraIntrinsics cam;
    cam.width = 320, cam.height = 240, cam.fx = cam.fy = 262.5, cam.cx = 159.5, cam.cy = 119.5;
    writeCamera((dir / "camera.yaml").string(), cam);
    fs::create_directories(dir / "depth");
    for (std::size_t i = 0; i < walls.size(); ++i)
        cv::imwrite((dir / "depth" / ("000" + std::to_string(i + 1) + ".png")).string(),
                    wallDepth(cam, walls[i].first, walls[i].second));
    return cli("bag --depth-dir " + (dir / "depth").string() + " --camera " + (dir / "camera.yaml").string() +
                   " --out " + (dir / "frames.bag").string() + " --fps 10",
               dir);
}

}  // namespace

TEST(CliBag, PngFramesToABagThatDetectReadsLikeTheFrames) {
    const fs::path dir = freshDir("cli_bag");
    const double angles[3] = {0.0, 10.0, 20.0};
    CliRun r = wallBag(dir, {{2.0, angles[0]}, {2.0, angles[1]}, {2.0, angles[2]}});
    const std::string bag = (dir / "frames.bag").string();
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("projsurf bag: 3 depth frames"), std::string::npos) << r.out;

    // What was written: both topics, the stamps 0.1 s apart, the pinhole of camera.yaml.
    const auto infos = readBagCameraInfos(bag, "/camera/depth/camera_info");
    ASSERT_EQ(infos.size(), 3u);
    EXPECT_NEAR(infos[2].header.stamp() - infos[0].header.stamp(), 0.2, 1e-6);
    EXPECT_EQ(infos[0].K[0], 262.5);
    EXPECT_EQ(infos[0].K[2], 159.5);
    EXPECT_EQ(infos[0].width, 320u);

    // detect --bag without --topic (the bag has one depth topic): one line per frame, each the
    // detection of that frame read from its PNG.
    r = cli("detect --bag " + bag + " --calib " + kCalib, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = jsonLines(r.out);
    ASSERT_EQ(lines.size(), 3u) << r.out;
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(lines[i]["bag"]["topic"], "/camera/depth/image_rect");
        EXPECT_EQ(lines[i]["bag"]["index"], i);
        const std::string json = (dir / ("f" + std::to_string(i) + ".json")).string();
        const CliRun one =
            cli("detect --depth " + (dir / "depth" / ("000" + std::to_string(i + 1) + ".png")).string() + " --camera " +
                    (dir / "camera.yaml").string() + " --calib " + kCalib + " --json " + json,
                dir);
        ASSERT_EQ(one.status, 0) << one.err;
        const auto frame = nlohmann::json::parse(slurp(json));
        ASSERT_TRUE(frame["found"].get<bool>());
        EXPECT_EQ(lines[i]["found"], frame["found"]);
        EXPECT_EQ(lines[i]["rectangle"]["corners"], frame["rectangle"]["corners"]) << i;
        EXPECT_NEAR(lines[i]["plane"]["orientation_deg"].get<double>(), angles[i], 1.0);
    }

    // A topic that is not there: the usable ones are listed.
    r = cli("detect --bag " + bag + " --topic /points --calib " + kCalib, dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("usable topics: /camera/depth/image_rect (sensor_msgs/Image)"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(CliBag, TwoUsableTopicsNeedTopicAndEachDepthImageTakesTheCameraInfoOfItsStamp) {
    const fs::path dir = freshDir("cli_bag_pairs");
    CameraIntrinsics cam;
    cam.width = 320, cam.height = 240, cam.fx = cam.fy = 262.5, cam.cx = 159.5, cam.cy = 119.5;
    CameraIntrinsics other = cam;  // a camera_info of another size, one frame later
    other.width = 640, other.height = 480;
    BagWriter w;
    const auto a = w.addConnection("/a/depth/image_rect", kImageType, kImageMd5, kImageDefinition);
    const auto ai = w.addConnection("/a/depth/camera_info", kCameraInfoType, kCameraInfoMd5, kCameraInfoDefinition);
    const auto b = w.addConnection("/b/depth/image", kImageType, kImageMd5, kImageDefinition);
    RosHeader h;
    h.sec = 5;
    h.frame_id = "cam";
    RosHeader later = h;
    later.nsec = 33000000;
    // The depth image last, after the camera_info of its stamp and one of a later stamp.
    w.addMessage(ai, 5, 0, serializeCameraInfo(h, cam));
    w.addMessage(ai, 5, 33000000, serializeCameraInfo(later, other));
    w.addMessage(a, 5, 40000000, serializeDepthImage(h, wallDepth(cam, 2.0, 0.0)));
    w.addMessage(b, 5, 40000000, serializeDepthImage(h, wallDepth(cam, 2.0, 0.0)));
    const std::string bag = (dir / "two.bag").string();
    OutputGroup out;
    out.addFile(bag, w.bytes());
    out.commit();

    CliRun r = cli("detect --bag " + bag + " --calib " + kCalib, dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("has 2 usable topics, give one with --topic: /a/depth/image_rect (sensor_msgs/Image), "
                         "/b/depth/image (sensor_msgs/Image)"),
              std::string::npos)
        << r.err;
    r = cli("detect --bag " + bag + " --topic /a/depth/image_rect --calib " + kCalib, dir);
    ASSERT_EQ(r.status, 0) << r.err;  // the latest camera_info (640x480) would not fit the image
    EXPECT_EQ(r.err, "");
    const auto lines = jsonLines(r.out);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(lines[0]["found"].get<bool>()) << lines[0].dump();
    // /b has no camera_info beside it, and the bag's only one is /a's: taken.
    r = cli("detect --bag " + bag + " --topic /b/depth/image --calib " + kCalib, dir);
    EXPECT_EQ(r.status, 0) << r.err;
    fs::remove_all(dir);
}

namespace {

/// Largest distance of a corner of `a` from the same corner of `b` (rectangle JSON), m.
double cornerMove(const nlohmann::json &a, const nlohmann::json &b) {
    double worst = 0.0;
    for (int i = 0; i < 4; ++i) {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double d = a["corners"][i][k].get<double>() - b["corners"][i][k].get<double>();
            d2 += d * d;
        }
        worst = std::max(worst, std::sqrt(d2));
    }
    return worst;
}

}  // namespace

TEST(CliBag, SteadyKeepsTheShownRectangleWhileTheDetectionOfTheSameWallMoves) {
    const fs::path dir = freshDir("cli_bag_steady");
    // One wall, its distance read 1 cm off either way from frame to frame (a noisy sensor).
    CliRun r = wallBag(dir, {{2.0, 0.0}, {2.01, 0.0}, {1.99, 0.0}, {2.01, 0.0}, {1.99, 0.0}, {2.0, 0.0}});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string bag = (dir / "frames.bag").string();

    r = cli("detect --bag " + bag + " --calib " + kCalib + " --steady", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const auto lines = jsonLines(r.out);
    ASSERT_EQ(lines.size(), 6u) << r.out;
    double raw_moved = 0.0, shown_moved = 0.0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        ASSERT_TRUE(lines[i]["found"].get<bool>()) << lines[i].dump();
        EXPECT_EQ(lines[i]["event"], i == 0 ? "acquired" : "kept") << i;
        ASSERT_TRUE(lines[i]["shown"].is_object()) << lines[i].dump();
        raw_moved = std::max(raw_moved, cornerMove(lines[i]["rectangle"], lines[0]["rectangle"]));
        shown_moved = std::max(shown_moved, cornerMove(lines[i]["shown"], lines[0]["shown"]));
    }
    EXPECT_GT(raw_moved, 0.009);    // the detection follows each frame's wall
    EXPECT_LT(shown_moved, 0.004);  // the shown picture only follows the smoothed plane
    EXPECT_LT(lines[0]["shown"]["width_m"].get<double>(), lines[0]["rectangle"]["width_m"].get<double>());

    // Without --steady the lines are detect's alone; --steady needs a stream.
    r = cli("detect --bag " + bag + " --calib " + kCalib, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(jsonLines(r.out)[0].contains("shown"));
    r = cli("detect --depth " + (dir / "depth" / "0001.png").string() + " --camera " + (dir / "camera.yaml").string() +
                " --calib " + kCalib + " --steady",
            dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err,
              "projsurf: error: arguments: --steady goes with --bag (a stream of frames); one cloud has nothing "
              "to hold\n");
    fs::remove_all(dir);
}
