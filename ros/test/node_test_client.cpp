// Drives projsurf_node through a real rosmaster (started by run_node_test.sh): publishes
// simulated clouds (and tf for a moving robot), calls ~detect, and checks what the node
// publishes. Also writes a rosbag and reads it back (Bag.*; needs no master).
// Every wait is bounded.
#include <geometry_msgs/PolygonStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "conversions.hpp"
#include "node_test_support.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/rosbag/rosbag_clouds.hpp"
#include "sim_wall.hpp"

using namespace projsurf;
using namespace projsurf::sim_test;
using namespace projsurf::node_test;

namespace {

/// The node's ~result strings and ~markers arrays, as they come.
struct ResultsAndMarkers {
    std::mutex mutex;
    std::vector<std::string> results;
    std::vector<visualization_msgs::MarkerArray> markers;
    ros::Subscriber rsub, msub;

    void open(ros::NodeHandle &nh, const std::string &ns) {
        rsub = nh.subscribe<std_msgs::String>(ns + "/projsurf/result", 10, [this](const std_msgs::StringConstPtr &m) {
            std::lock_guard<std::mutex> lock(mutex);
            results.push_back(m->data);
        });
        msub = nh.subscribe<visualization_msgs::MarkerArray>(ns + "/projsurf/markers", 10,
                                                             [this](const visualization_msgs::MarkerArrayConstPtr &m) {
                                                                 std::lock_guard<std::mutex> lock(mutex);
                                                                 markers.push_back(*m);
                                                             });
    }

    /// Whether a markers array came after the first `shown` with the cells in a person's shadow
    /// drawn (marker 5, at least 100 orange cells).
    bool hasShadowMarkerAfter(std::size_t shown) {
        std::lock_guard<std::mutex> again(mutex);
        if (markers.size() <= shown) return false;
        for (const auto &m : markers.back().markers)
            if (m.id == 5 && std::count_if(m.colors.begin(), m.colors.end(), [](const std_msgs::ColorRGBA &col) {
                                 return col.r > 0.9f && col.g > 0.4f && col.g < 0.6f && col.b < 0.1f;
                             }) >= 100)
                return true;
        return false;
    }
};

/// Before any cloud, ~detect (`service`) gives a clear answer, not a crash.
void expectNoCloudYetAnswer(const std::string &service) {
    std_srvs::Trigger early;
    ASSERT_TRUE(ros::service::call(service, early));
    EXPECT_FALSE(early.response.success);
    EXPECT_NE(early.response.message.find("no cloud"), std::string::npos) << early.response.message;
}

/// The rectangle `c` is on the front wall, 2 m straight ahead (the camera looks at it square
/// on), of the framebuffer's aspect, using most of the projector's footprint, and upright.
void expectUprightOnTheFrontWall(const std::array<Eigen::Vector3d, 4> &c) {
    for (const auto &p : c) EXPECT_NEAR(p.z(), 2.0, 0.03);
    const double width = (c[1] - c[0]).norm(), height = (c[3] - c[0]).norm();
    EXPECT_NEAR(width / height, 1280.0 / 800.0, 0.02) << "default aspect is the framebuffer's";
    EXPECT_GT(width * height, 0.8) << "most of the ~1.43 x 0.85 m projector footprint should be used";
    // Upright: the left edge runs along gravity (camera y), top-left is up-left.
    EXPECT_GT((c[3] - c[0]).normalized().dot(Eigen::Vector3d(0, 1, 0)), std::cos(0.02));
    EXPECT_LT(c[0].x(), c[1].x());
    EXPECT_LT(c[0].y(), c[3].y());
}

/// The picture fills exactly the rectangle's pixels in the 1280x800 framebuffer `fb`: just
/// inside each corner it is lit, just outside (where that is still in the framebuffer) it is
/// black. Fatal failure when a corner does not project into the framebuffer.
void expectPictureFillsTheRectangle(const sensor_msgs::Image &fb, const std::array<Eigen::Vector3d, 4> &c) {
    const Projector proj = testProjector();
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    std::array<Eigen::Vector2d, 4> px;
    for (int i = 0; i < 4; ++i) {
        const auto q = proj.toPixel(c[i]);
        ASSERT_TRUE(q.has_value());
        px[i] = *q;
        centre += 0.25 * px[i];
    }
    int outside_checked = 0;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d dir = (px[i] - centre).normalized();
        // The rectangle reaches the projector's footprint: a corner may lie a few px from the
        // framebuffer's edge, so just outside it is looked at 3 px out.
        const Eigen::Vector2d in = px[i] - 8.0 * dir, out = px[i] + 3.0 * dir;
        EXPECT_FALSE(isBlack(fb, static_cast<int>(std::lround(in.x())), static_cast<int>(std::lround(in.y()))))
            << "corner " << i << " at " << px[i].transpose();
        if (out.x() >= 0 && out.y() >= 0 && out.x() <= 1279 && out.y() <= 799) {
            ++outside_checked;
            EXPECT_TRUE(isBlack(fb, static_cast<int>(std::lround(out.x())), static_cast<int>(std::lround(out.y()))))
                << "corner " << i;
        }
    }
    EXPECT_GE(outside_checked, 1) << "the projector's keystone leaves black framebuffer corners";
}

/// ~result is the contract's JSON for the rectangle `c` and the latest ~markers show it (marker
/// 3, closed); `shown` is set to the number of markers arrays seen. Fatal failure when neither
/// came within 10 s.
void expectResultAndRectangleMarker(ResultsAndMarkers &out, const std::array<Eigen::Vector3d, 4> &c,
                                    std::size_t &shown) {
    ASSERT_TRUE(waitFor(
        [&] {
            std::lock_guard<std::mutex> lock(out.mutex);
            return !out.results.empty() && !out.markers.empty();
        },
        10.0));
    std::lock_guard<std::mutex> lock(out.mutex);
    const auto j = nlohmann::json::parse(out.results.back());
    EXPECT_TRUE(j.at("found").get<bool>());
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(j.at("rectangle").at("corners").at(i).at(k).get<double>(), c[i][k], 1e-4);
    bool has_rect_marker = false;
    for (const auto &m : out.markers.back().markers) has_rect_marker |= m.id == 3 && m.points.size() == 5;
    EXPECT_TRUE(has_rect_marker);
    shown = out.markers.size();
}

// ------------------------------------------------------------------------------------------
// On demand: the paper's start signal (section 5), answered with the outcome.

TEST_F(NodeTest, DetectServiceFindsTheWallAndPublishesRectangleAndFramebuffer) {
    const std::string ns = env("PROJSURF_ONESHOT_NS", "/oneshot");
    Inbox<geometry_msgs::PolygonStamped> rects;
    Inbox<sensor_msgs::Image> fbs;
    rects.open(*nh_, ns + "/projsurf/rectangle");
    fbs.open(*nh_, ns + "/projsurf/framebuffer");
    ResultsAndMarkers out;
    out.open(*nh_, ns);
    ros::Publisher pub = nh_->advertise<sensor_msgs::PointCloud2>(ns + "/points", 1, true);
    const std::string service = ns + "/projsurf/detect";
    ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(60.0))) << service << " never came up";
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 30.0)) << "the node never subscribed to points";

    ASSERT_NO_FATAL_FAILURE(expectNoCloudYetAnswer(service));

    const ros::Time stamp = ros::Time::now();
    pub.publish(ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), {}), header("camera_optical", stamp)));
    // The service answers on the latest cloud; call it until it has answered on this one.
    std_srvs::Trigger call;
    geometry_msgs::PolygonStamped rect;
    ASSERT_TRUE(detectUntilAnswered(service, rects, stamp, call, rect))
        << "no ~rectangle for the cloud; " << rects.received() << "; last answer: " << call.response.message;
    ASSERT_TRUE(call.response.success) << call.response.message;
    EXPECT_FALSE(call.response.message.empty());
    EXPECT_EQ(rect.header.frame_id, "camera_optical");
    ASSERT_EQ(rect.polygon.points.size(), 4u);
    const auto c = corners(rect);
    expectUprightOnTheFrontWall(c);

    sensor_msgs::Image fb;
    // Published with the rectangle; should it not come (once, under load, it did not within 20 s,
    // the cause not found), ~detect is called again on the same cloud, which publishes it again,
    // and what did come is said.
    ASSERT_TRUE(fbs.waitStamp(stamp, 5.0, fb) || detectUntilAnswered(service, fbs, stamp, call, fb))
        << "no ~framebuffer for the cloud; " << fbs.received() << "; " << rects.received();
    EXPECT_EQ(fb.encoding, "bgr8");
    ASSERT_EQ(fb.width, 1280u);
    ASSERT_EQ(fb.height, 800u);
    ASSERT_NO_FATAL_FAILURE(expectPictureFillsTheRectangle(fb, c));

    // ~result is the contract's JSON for the same rectangle; ~markers show it.
    std::size_t shown = 0;
    ASSERT_NO_FATAL_FAILURE(expectResultAndRectangleMarker(out, c, shown));

    // A person at one side of the beam: the picture stays on the wall, and the cells in their
    // shadow there are drawn (marker 5, orange), as the CLI's overlay draws them.
    SceneOptions person;
    person.person = true;
    person.person_y = 0.45;
    pub.publish(
        ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), person), header("camera_optical", ros::Time::now())));
    std::string last;
    EXPECT_TRUE(waitFor(
        [&] {
            call = std_srvs::Trigger();
            if (!ros::service::call(service, call)) return false;
            last = call.response.message;
            return out.hasShadowMarkerAfter(shown);
        },
        20.0))
        << "no marker of the cells in the person's shadow; last answer: " << last;

    // The person straight ahead, 1.2 m away, filling the view's height (a flat slab here): a
    // face narrower than a wall with the wall seen past it on both sides stands in the room.
    // The picture goes on the wall beside them, or nowhere; never on the person.
    person.person_y = 0.0;
    const ros::Time ahead = ros::Time::now();
    pub.publish(ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), person), header("camera_optical", ahead)));
    geometry_msgs::PolygonStamped on;
    ASSERT_TRUE(waitFor(
        [&] {
            call = std_srvs::Trigger();
            return ros::service::call(service, call) && rects.waitStamp(ahead, 0.5, on);
        },
        20.0))
        << "no answer for the cloud with the person ahead: " << call.response.message;
    for (const auto &p : corners(on)) EXPECT_GT(p.z(), 1.6) << call.response.message;
}

TEST_F(NodeTest, DetectServiceSaysWhyWhenThereIsNoWall) {
    const std::string ns = env("PROJSURF_ONESHOT_NS", "/oneshot");
    Inbox<sensor_msgs::Image> fbs;
    fbs.open(*nh_, ns + "/projsurf/framebuffer");
    ros::Publisher pub = nh_->advertise<sensor_msgs::PointCloud2>(ns + "/points", 1, true);
    const std::string service = ns + "/projsurf/detect";
    ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(60.0)));
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 30.0));
    SceneOptions floor_only;
    floor_only.front_wall = false;
    floor_only.side_wall = false;
    const ros::Time stamp = ros::Time::now();
    pub.publish(ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), floor_only), header("camera_optical", stamp)));
    sensor_msgs::Image fb;
    std_srvs::Trigger call;
    // Call until the answer is about this cloud (its framebuffer carries the stamp).
    ASSERT_TRUE(waitFor(
        [&] {
            call = std_srvs::Trigger();
            return ros::service::call(service, call) && fbs.waitStamp(stamp, 0.5, fb);
        },
        20.0));
    EXPECT_FALSE(call.response.success);
    EXPECT_FALSE(call.response.message.empty());
    EXPECT_EQ(call.response.message.find("no cloud"), std::string::npos) << call.response.message;
    // Nothing to show: the framebuffer is black.
    ASSERT_EQ(fb.data.size(), 1280u * 800u * 3u);
    EXPECT_TRUE(std::all_of(fb.data.begin(), fb.data.end(), [](std::uint8_t b) { return b == 0; }));
}

TEST_F(NodeTest, DetectServiceSaysWhenTheLatestCloudWasRejected) {
    const std::string ns = env("PROJSURF_ONESHOT_NS", "/oneshot");
    const std::string service = ns + "/projsurf/detect";
    std_srvs::Trigger call;
    ros::Publisher pub;
    publishRoomAndDetect(*nh_, ns, call, pub);
    if (HasFatalFailure()) return;
    // A hostile cloud: its z field is gone (renamed), so it cannot be used.
    sensor_msgs::PointCloud2 bad =
        ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), {}), header("camera_optical", ros::Time(4242.5)));
    for (auto &f : bad.fields)
        if (f.name == "z") f.name = "q";
    pub.publish(bad);
    ASSERT_TRUE(waitFor(
        [&] {
            call = std_srvs::Trigger();
            return ros::service::call(service, call) && call.response.message.find("rejected") != std::string::npos;
        },
        20.0))
        << "~detect never said the latest cloud was rejected: " << call.response.message;
    EXPECT_NE(call.response.message.find("4242.500"), std::string::npos) << call.response.message;  // which one
    EXPECT_NE(call.response.message.find("'z'"), std::string::npos) << "and why: " << call.response.message;
    EXPECT_NE(call.response.message.find("last valid cloud"), std::string::npos) << call.response.message;
    // A good cloud again: the answer is about it, nothing rejected.
    pub.publish(
        ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), {}), header("camera_optical", ros::Time::now())));
    ASSERT_TRUE(waitFor(
        [&] {
            call = std_srvs::Trigger();
            return ros::service::call(service, call) && call.response.message.find("rejected") == std::string::npos;
        },
        20.0))
        << call.response.message;
    EXPECT_TRUE(call.response.success) << call.response.message;
}

/// The picture: plain green, 640x400 (the framebuffer's aspect, so it fills the rectangle).
sensor_msgs::Image plainGreenPicture() {
    sensor_msgs::Image picture;
    picture.header = header("", ros::Time::now());
    picture.width = 640;
    picture.height = 400;
    picture.encoding = "rgb8";
    picture.step = 640 * 3;
    picture.data.assign(picture.step * picture.height, 0);
    for (std::size_t i = 1; i < picture.data.size(); i += 3) picture.data[i] = 255;  // G of RGB
    return picture;
}

TEST_F(NodeTest, DepthImageInputAndThePictureFromTheImageTopic) {
    const std::string ns = env("PROJSURF_ONESHOT_NS", "/oneshot");
    Inbox<sensor_msgs::Image> fbs;
    Inbox<geometry_msgs::PolygonStamped> rects;
    fbs.open(*nh_, ns + "/projsurf/framebuffer");
    rects.open(*nh_, ns + "/projsurf/rectangle");
    ros::Publisher info_pub = nh_->advertise<sensor_msgs::CameraInfo>(ns + "/depth/camera_info", 10, true);
    ros::Publisher depth_pub = nh_->advertise<sensor_msgs::Image>(ns + "/depth/image_rect", 1, true);
    ros::Publisher picture_pub = nh_->advertise<sensor_msgs::Image>(ns + "/image", 1, true);
    const std::string service = ns + "/projsurf/detect";
    ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(60.0)));
    ASSERT_TRUE(waitFor(
        [&] {
            return info_pub.getNumSubscribers() > 0 && depth_pub.getNumSubscribers() > 0 &&
                   picture_pub.getNumSubscribers() > 0;
        },
        30.0));

    picture_pub.publish(plainGreenPicture());

    // The same wall as a 16-bit depth image (mm) with its camera_info.
    const Cloud cloud = renderScene(cameraPose(0, 0, 0), {});
    const ros::Time stamp = ros::Time::now();
    sensor_msgs::CameraInfo info;
    info.header = header("camera_optical", stamp);
    info.width = 320;
    info.height = 240;
    info.K = {262.5, 0.0, 159.5, 0.0, 262.5, 119.5, 0.0, 0.0, 1.0};
    const sensor_msgs::Image depth = depthImage(cloud, info.header);
    // Its camera_info, then one of a later stamp that does not fit this image (another
    // resolution): the node pairs the depth image with the camera_info of its own stamp.
    info_pub.publish(info);
    ros::WallDuration(0.1).sleep();
    sensor_msgs::CameraInfo later = info;
    later.header.stamp = stamp + ros::Duration(0.033);
    later.width = 640;
    later.height = 480;
    info_pub.publish(later);
    ros::WallDuration(0.2).sleep();
    depth_pub.publish(depth);

    sensor_msgs::Image fb;
    std_srvs::Trigger call;
    ASSERT_TRUE(waitFor(
        [&] {
            call = std_srvs::Trigger();
            return ros::service::call(service, call) && fbs.waitStamp(stamp, 0.5, fb);
        },
        20.0))
        << "no framebuffer for the depth image";
    EXPECT_TRUE(call.response.success) << call.response.message;
    geometry_msgs::PolygonStamped rect;
    ASSERT_TRUE(rects.waitStamp(stamp, 10.0, rect));
    for (const auto &p : corners(rect)) EXPECT_NEAR(p.z(), 2.0, 0.03);
    // The rectangle's centre shows the green picture (BGR in the framebuffer).
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto &p : corners(rect)) centre += 0.25 * p;
    const auto px = testProjector().toPixel(centre);
    ASSERT_TRUE(px.has_value());
    const std::uint8_t *bgr =
        &fb.data[static_cast<std::size_t>(std::lround(px->y())) * fb.step + 3 * std::lround(px->x())];
    EXPECT_LT(bgr[0], 20);
    EXPECT_GT(bgr[1], 235);
    EXPECT_LT(bgr[2], 20);
}

// ------------------------------------------------------------------------------------------
// Continuous mode: a robot drives along the wall; the picture must stay put on it.

/// The transform odom -> camera_optical_moving of the camera at `pose`, stamped `stamp`.
geometry_msgs::TransformStamped odomToMovingCamera(const Eigen::Isometry3d &pose, const ros::Time &stamp) {
    geometry_msgs::TransformStamped t = tf2::eigenToTransform(pose);
    t.header = header("odom", stamp);
    t.child_frame_id = "camera_optical_moving";
    return t;
}

/// What continuous mode showed, in odom: the shown corners per phase, and the centre of the
/// detector's own rectangle in phase 1.
struct ShownInOdom {
    std::vector<std::array<Eigen::Vector3d, 4>> world1, world2;  // shown corners in odom, per phase
    std::vector<Eigen::Vector3d> raw_center1;                    // the detector's own rectangle, phase 1
};

/// The ~rectangle `got` and ~result `results` (by stamp) of each frame sent at `poses`, moved
/// into odom; frames before `phase1` are phase 1.
ShownInOdom shownInOdom(const std::map<ros::Time, Eigen::Isometry3d> &poses,
                        const std::map<ros::Time, geometry_msgs::PolygonStamped> &got, std::mutex &mutex,
                        const std::map<double, nlohmann::json> &results, int phase1) {
    ShownInOdom shown;
    int k = 0;
    for (const auto &[stamp, pose] : poses) {
        const auto it = got.find(stamp);
        if (it != got.end()) {
            auto c = corners(it->second);
            for (auto &p : c) p = pose * p;
            (k < phase1 ? shown.world1 : shown.world2).push_back(c);
        }
        std::lock_guard<std::mutex> lock(mutex);
        const auto r = results.find(stamp.toSec());
        if (k < phase1 && r != results.end() && r->second.at("found").get<bool>()) {
            Eigen::Vector3d centre = Eigen::Vector3d::Zero();
            for (int i = 0; i < 4; ++i)
                for (int d = 0; d < 3; ++d) centre[d] += 0.25 * r->second["rectangle"]["corners"][i][d].get<double>();
            shown.raw_center1.push_back(pose * centre);
        }
        ++k;
    }
    return shown;
}

/// Prints the median and worst continuous frame time of the ~result messages received.
void printContinuousFrameTimes(std::mutex &mutex, const std::map<double, nlohmann::json> &results) {
    std::vector<double> ms;
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto &[stamp, j] : results) ms.push_back(j.at("continuous").at("frame_ms").get<double>());
    std::sort(ms.begin(), ms.end());
    if (!ms.empty())
        std::printf(
            "[ measured ] continuous frame (320x240 cloud: detect + steady + 1280x800 warp): median %.1f ms, max "
            "%.1f ms over %zu frames\n",
            ms[ms.size() / 2], ms.back(), ms.size());
}

TEST_F(NodeTest, ContinuousModeKeepsThePicturePutOnTheWallWhileTheRobotMoves) {
    const std::string ns = env("PROJSURF_MOVING_NS", "/moving");
    Inbox<geometry_msgs::PolygonStamped> rects;
    Inbox<sensor_msgs::Image> fbs;
    rects.open(*nh_, ns + "/projsurf/rectangle");
    fbs.open(*nh_, ns + "/projsurf/framebuffer");
    std::mutex mutex;
    std::map<double, nlohmann::json> results;  // by stamp
    ros::Subscriber rsub =
        nh_->subscribe<std_msgs::String>(ns + "/projsurf/result", 100, [&](const std_msgs::StringConstPtr &m) {
            auto j = nlohmann::json::parse(m->data);
            std::lock_guard<std::mutex> lock(mutex);
            results[j.at("continuous").at("stamp").get<double>()] = j;
        });
    ros::Publisher pub = nh_->advertise<sensor_msgs::PointCloud2>(ns + "/points", 1);
    tf2_ros::TransformBroadcaster tf;
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 60.0)) << "the node never subscribed";

    // Phase 1 (frames 0-29): 5 cm forward and 6 cm sideways, 1 deg of turn: the held picture
    // still fits the projector and must not move. Phase 2 (30-59): 0.6 m sideways: it no
    // longer fits and must move along the same wall (never to the side wall).
    const int frames = 60, phase1 = 30;
    std::map<ros::Time, Eigen::Isometry3d> poses;
    int missing = 0;
    for (int k = 0; k < frames; ++k) {
        const double s1 = std::min(k, phase1 - 1) / double(phase1 - 1);
        const double s2 = k < phase1 ? 0.0 : (k - phase1 + 1) / double(frames - phase1);
        const Eigen::Isometry3d pose = cameraPose(0.05 * s1, 0.06 * s1 + 0.6 * s2, (1.0 * M_PI / 180.0) * s1);
        const ros::Time stamp = ros::Time::now();
        poses[stamp] = pose;
        tf.sendTransform(odomToMovingCamera(pose, stamp));
        ros::WallDuration(0.02).sleep();
        SceneOptions scene;
        scene.seed = 100 + k;
        pub.publish(ros_node::toPointCloud2(renderScene(pose, scene), header("camera_optical_moving", stamp)));
        // Lock-step with the node (2 shared cores in CI): wait for this frame's framebuffer.
        sensor_msgs::Image fb;
        if (!fbs.waitStamp(stamp, 10.0, fb)) ++missing;
    }
    EXPECT_LE(missing, 2) << "frames the node did not answer";

    const ShownInOdom shown = shownInOdom(poses, rects.snapshot(), mutex, results, phase1);
    const auto &world1 = shown.world1, &world2 = shown.world2;
    const auto &raw_center1 = shown.raw_center1;
    ASSERT_GE(world1.size(), static_cast<std::size_t>(phase1 - 2));
    ASSERT_GE(world2.size(), static_cast<std::size_t>(frames - phase1 - 2));

    // Always on the front wall (x = 2 in odom), never the side wall.
    for (const auto *phase : {&world1, &world2})
        for (const auto &c : *phase)
            for (const auto &p : c) EXPECT_NEAR(p.x(), 2.0, 0.03);

    // Phase 1: every corner stays within the tolerance of where it was first shown.
    const double tolerance = std::stod(env("PROJSURF_STEADY_TOLERANCE", "0.01"));  // m
    double worst = 0.0;
    for (const auto &c : world1)
        for (int i = 0; i < 4; ++i) worst = std::max(worst, (c[i] - world1.front()[i]).norm());
    EXPECT_LT(worst, tolerance) << "corners moved in the world while the robot moved 8 cm";
    // ... while the detector's own best rectangle followed the robot.
    ASSERT_GE(raw_center1.size(), 2u);
    EXPECT_GT((raw_center1.back() - raw_center1.front()).norm(), 0.04);
    std::printf("[ measured ] phase 1: worst corner drift %.4f m over %zu frames (raw detection moved %.3f m)\n", worst,
                world1.size(), (raw_center1.back() - raw_center1.front()).norm());

    // Phase 2: the picture had to move (the robot went 0.6 m sideways) and did, along the wall,
    // ending where the robot now is (left of where it started).
    const Eigen::Vector3d first =
        0.25 * (world1.front()[0] + world1.front()[1] + world1.front()[2] + world1.front()[3]);
    const Eigen::Vector3d last = 0.25 * (world2.back()[0] + world2.back()[1] + world2.back()[2] + world2.back()[3]);
    EXPECT_GT(last.y() - first.y(), 0.3);
    // ... and it moved in few jumps, not every frame.
    int jumps = 0;
    for (std::size_t i = 1; i < world2.size(); ++i)
        if ((world2[i][0] - world2[i - 1][0]).norm() > tolerance) ++jumps;
    EXPECT_LE(jumps, 10) << "the picture should move in steps when it must, not follow every frame";
    printContinuousFrameTimes(mutex, results);
    std::printf("[ measured ] phase 2: centre moved %.3f m along the wall in %d jumps over %zu frames\n",
                last.y() - first.y(), jumps, world2.size());
}

// Continuous mode, robot standing still: a person walks into the beam (contract "Blanking").

/// Sampled framebuffer pixels (every second one) on and clear of a person in the beam.
struct BlankingCounts {
    long lit_on_person = 0, on_person = 0, lit_elsewhere = 0, elsewhere = 0;
};

/// Counts, in `n`, the framebuffer pixels whose ray meets the person of `scene` (which should
/// be black in `fb`) and those 10 cm (at the person's distance, more on the wall) clear of
/// them (which should be lit as they were: not set in the ~blanked `mask`).
void countBlanking(const SceneOptions &scene, const Eigen::Isometry3d &pose, const Projector &projector,
                   const sensor_msgs::Image &fb, const sensor_msgs::Image &mask, BlankingCounts &n) {
    for (int v = 0; v < 800; v += 2) {
        for (int u = 0; u < 1280; u += 2) {
            const Eigen::Vector3d dir = pose.linear() * projector.ray(Eigen::Vector2d(u, v));
            const Eigen::Vector3d origin = pose * projector.origin;
            if (hitsPerson(scene, origin, dir)) {
                ++n.on_person;
                if (!isBlack(fb, u, v)) ++n.lit_on_person;
            } else {
                // 10 cm (at the person's distance, more on the wall) clear of them.
                const double t = (scene.person_x - origin.x()) / dir.x();
                const Eigen::Vector3d p = origin + t * dir;
                if (std::abs(p.y() - scene.person_y) > 0.32) {
                    ++n.elsewhere;
                    if (mask.data[static_cast<std::size_t>(v) * mask.step + u] == 0) ++n.lit_elsewhere;
                }
            }
        }
    }
}

TEST_F(NodeTest, ContinuousModeBlanksAPersonWalkingIntoTheBeam) {
    const std::string ns = env("PROJSURF_STILL_NS", "/still");
    Inbox<sensor_msgs::Image> fbs, masks;
    fbs.open(*nh_, ns + "/projsurf/framebuffer");
    masks.open(*nh_, ns + "/projsurf/blanked");
    std::mutex mutex;
    std::map<ros::Time, ros::WallTime> arrived;  // ~blanked arrival, by stamp
    ros::Subscriber asub =
        nh_->subscribe<sensor_msgs::Image>(ns + "/projsurf/blanked", 100, [&](const sensor_msgs::ImageConstPtr &m) {
            std::lock_guard<std::mutex> lock(mutex);
            arrived[m->header.stamp] = ros::WallTime::now();
        });
    float focus = -1.0f;
    ros::Subscriber fsub =
        nh_->subscribe<std_msgs::Float32>(ns + "/projsurf/focus_distance", 10, [&](const std_msgs::Float32ConstPtr &m) {
            std::lock_guard<std::mutex> lock(mutex);
            focus = m->data;
        });
    ros::Publisher pub = nh_->advertise<sensor_msgs::PointCloud2>(ns + "/points", 1);
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 60.0)) << "the node never subscribed";

    // Frames 0-7: the empty wall (the picture is placed); 8-19: a person walks in from the
    // left, 1.2 m from the camera, to the middle of the beam.
    const int frames = 20, walk_from = 8;
    const Projector projector = testProjector();
    const Eigen::Isometry3d pose = cameraPose(0.0, 0.0, 0.0);
    std::vector<double> latency_ms;
    int checked = 0, missing = 0;
    BlankingCounts n;
    for (int k = 0; k < frames; ++k) {
        SceneOptions scene;
        scene.seed = 300 + k;
        scene.person = k >= walk_from;
        scene.person_y = 0.9 - 0.9 * (k - walk_from) / double(frames - 1 - walk_from);
        const ros::Time stamp = ros::Time::now();
        const ros::WallTime sent = ros::WallTime::now();
        pub.publish(ros_node::toPointCloud2(renderScene(pose, scene), header("camera_optical_still", stamp)));
        sensor_msgs::Image fb, mask;
        if (!fbs.waitStamp(stamp, 10.0, fb) || !masks.waitStamp(stamp, 10.0, mask)) {
            ++missing;
            continue;
        }
        // ~blanked's own subscriber may run its callback a moment after the inbox's.
        if (waitFor(
                [&] {
                    std::lock_guard<std::mutex> lock(mutex);
                    return arrived.count(stamp) > 0;
                },
                2.0)) {
            std::lock_guard<std::mutex> lock(mutex);
            latency_ms.push_back((arrived.at(stamp) - sent).toSec() * 1e3);
        }
        ASSERT_EQ(mask.encoding, "mono8");
        ASSERT_EQ(mask.width, 1280u);
        ASSERT_EQ(mask.height, 800u);
        if (!scene.person) continue;
        ++checked;
        countBlanking(scene, pose, projector, fb, mask, n);
    }
    EXPECT_LE(missing, 2);
    EXPECT_GE(checked, frames - walk_from - 2);
    EXPECT_GT(n.on_person, 1000) << "the person never stood in the beam";
    EXPECT_EQ(n.lit_on_person, 0);
    EXPECT_GE(static_cast<double>(n.lit_elsewhere), 0.95 * n.elsewhere);
    {
        std::lock_guard<std::mutex> lock(mutex);
        EXPECT_NEAR(focus, 2.0, 0.1) << "~focus_distance: the wall is 2 m ahead";
    }
    std::sort(latency_ms.begin(), latency_ms.end());
    ASSERT_FALSE(latency_ms.empty());
    std::printf(
        "[ measured ] blanking: %ld of %ld sampled pixels on the person lit, %.2f %% of the rest unblanked; "
        "cloud published -> ~blanked received: median %.1f ms, max %.1f ms over %zu frames\n",
        n.lit_on_person, n.on_person, n.elsewhere > 0 ? 100.0 * n.lit_elsewhere / n.elsewhere : 100.0,
        latency_ms[latency_ms.size() / 2], latency_ms.back(), latency_ms.size());
}

// ~plan (contract "Where to stand"): a robot 1 m from the front wall asks where to stand;
// from there, ~detect finds at least 95 % of the predicted picture.

TEST_F(NodeTest, PlanServiceMovesTheRobotToABiggerPicture) {
    const std::string ns = env("PROJSURF_ONESHOT_NS", "/oneshot");
    Inbox<geometry_msgs::PolygonStamped> rects;
    rects.open(*nh_, ns + "/projsurf/rectangle");
    std::mutex mutex;
    std::vector<geometry_msgs::PoseStamped> poses;
    ros::Subscriber psub = nh_->subscribe<geometry_msgs::PoseStamped>(ns + "/projsurf/plan_pose", 10,
                                                                      [&](const geometry_msgs::PoseStampedConstPtr &m) {
                                                                          std::lock_guard<std::mutex> lock(mutex);
                                                                          poses.push_back(*m);
                                                                      });
    ros::Publisher pub = nh_->advertise<sensor_msgs::PointCloud2>(ns + "/points", 1, true);
    const std::string plan_service = ns + "/projsurf/plan", detect_service = ns + "/projsurf/detect";
    ASSERT_TRUE(ros::service::waitForService(plan_service, ros::Duration(60.0))) << plan_service << " never came up";
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 30.0));

    const Eigen::Isometry3d start = cameraPose(1.0, 0.0, 0.0);  // 1 m from the front wall
    SceneOptions scene;
    scene.side_wall = false;
    ros::Time stamp = ros::Time::now();
    pub.publish(ros_node::toPointCloud2(renderScene(start, scene), header("camera_optical", stamp)));
    // The node still has the previous test's cloud: "not 'no cloud'" would be an answer on
    // that one, and no ~rectangle of this stamp would ever come.
    std_srvs::Trigger detect;
    geometry_msgs::PolygonStamped rect;
    ASSERT_TRUE(detectUntilAnswered(detect_service, rects, stamp, detect, rect))
        << "no ~rectangle for the cloud 1 m from the wall; " << rects.received()
        << "; last answer: " << detect.response.message;
    auto area = [](const geometry_msgs::PolygonStamped &r) {
        const auto c = corners(r);
        return (c[1] - c[0]).norm() * (c[3] - c[0]).norm();
    };
    const double before = area(rect);

    std_srvs::Trigger plan;
    ASSERT_TRUE(ros::service::call(plan_service, plan));
    ASSERT_TRUE(plan.response.success) << plan.response.message;
    const auto j = nlohmann::json::parse(plan.response.message.substr(plan.response.message.find('{')));
    const double predicted = j.at("predicted").at("area_m2").get<double>();
    ASSERT_TRUE(waitFor(
        [&] {
            std::lock_guard<std::mutex> lock(mutex);
            return !poses.empty();
        },
        10.0));
    geometry_msgs::PoseStamped pose;
    {
        std::lock_guard<std::mutex> lock(mutex);
        pose = poses.back();
    }
    EXPECT_EQ(pose.header.frame_id, "camera_optical");
    Eigen::Isometry3d moved;  // the moved camera, today's camera frame
    tf2::fromMsg(pose.pose, moved);
    EXPECT_LE(moved.translation().norm(), 2.0 + 1e-6);

    // Go there and look again.
    stamp = ros::Time::now() + ros::Duration(0.001);
    pub.publish(ros_node::toPointCloud2(renderScene(start * moved, scene), header("camera_optical", stamp)));
    ASSERT_TRUE(waitFor(
        [&] {
            detect = std_srvs::Trigger();
            return ros::service::call(detect_service, detect) && rects.snapshot().count(stamp) > 0;
        },
        20.0));
    ASSERT_TRUE(rects.waitStamp(stamp, 5.0, rect));
    const double after = area(rect);
    std::printf("[ measured ] ~plan: move %.2f m; %.3f m^2 before, %.3f predicted, %.3f realised (%.1f %%)\n",
                moved.translation().norm(), before, predicted, after, 100.0 * after / predicted);
    EXPECT_GE(after, 0.95 * predicted);
    EXPECT_GE(after, 1.5 * before);
}

// ------------------------------------------------------------------------------------------
// Recorded data: a bag written here and read back.

class Bag : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = env("PROJSURF_TEST_TMP", "/tmp") + "/bag_" + std::to_string(::getpid());
        ASSERT_EQ(std::system(("mkdir -p '" + dir_ + "'").c_str()), 0);
        bag_path_ = dir_ + "/walk.bag";
        rosbag::Bag bag(bag_path_, rosbag::bagmode::Write);
        SceneOptions floor_only;
        floor_only.front_wall = floor_only.side_wall = false;
        const std::vector<std::pair<Eigen::Isometry3d, SceneOptions>> frames = {
            {cameraPose(0, 0, 0), SceneOptions{}},
            {cameraPose(0, 0, 0), floor_only},
            {cameraPose(0.3, 0.2, 0.1), SceneOptions{}}};
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const ros::Time t(100.0 + i);
            clouds_.push_back(renderScene(frames[i].first, frames[i].second));
            bag.write("/camera/points", t, ros_node::toPointCloud2(clouds_.back(), header("camera_optical", t)));
            sensor_msgs::Image img;
            img.header = header("camera_optical", t);
            bag.write("/camera/rgb", t, img);
        }
        bag.close();
    }
    void TearDown() override { (void)std::system(("rm -rf '" + dir_ + "'").c_str()); }
    std::string dir_, bag_path_;
    std::vector<Cloud> clouds_;
};

TEST_F(Bag, EveryCloudOfTheTopicComesBackInOrder) {
    std::vector<BagCloudInfo> infos;
    std::vector<Cloud> got;
    const std::size_t n = forEachBagCloud(bag_path_, "/camera/points", [&](const Cloud &c, const BagCloudInfo &i) {
        got.push_back(c);
        infos.push_back(i);
    });
    ASSERT_EQ(n, 3u);
    ASSERT_EQ(got.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(infos[i].index, i);
        EXPECT_DOUBLE_EQ(infos[i].stamp, 100.0 + i);
        EXPECT_EQ(infos[i].frame_id, "camera_optical");
        EXPECT_EQ(got[i].width, 320);
        EXPECT_EQ(got[i].height, 240);
        ASSERT_EQ(got[i].size(), clouds_[i].size());
        std::size_t same = 0;
        for (std::size_t k = 0; k < got[i].size(); ++k)
            same += (got[i].points[k] == clouds_[i].points[k]) ||
                    (!isFinite(got[i].points[k]) && !isFinite(clouds_[i].points[k]));
        EXPECT_EQ(same, got[i].size()) << "message " << i;
    }
}

TEST_F(Bag, CompressedChunksReadTheSame) {
    // projsurf's own bag reader decompresses bz2 and lz4 chunks (rosbag's writer makes them).
    for (const auto compression : {rosbag::compression::BZ2, rosbag::compression::LZ4}) {
        const std::string path = dir_ + "/compressed.bag";
        {
            rosbag::Bag bag(path, rosbag::bagmode::Write);
            bag.setCompression(compression);
            for (std::size_t i = 0; i < clouds_.size(); ++i) {
                const ros::Time t(100.0 + i);
                bag.write("/camera/points", t, ros_node::toPointCloud2(clouds_[i], header("camera_optical", t)));
            }
        }
        std::vector<Cloud> got;
        forEachBagCloud(path, "/camera/points", [&](const Cloud &c, const BagCloudInfo &) { got.push_back(c); });
        ASSERT_EQ(got.size(), clouds_.size()) << "compression " << static_cast<int>(compression);
        for (std::size_t i = 0; i < got.size(); ++i) {
            ASSERT_EQ(got[i].size(), clouds_[i].size());
            std::size_t same = 0;
            for (std::size_t k = 0; k < got[i].size(); ++k)
                same += (got[i].points[k] == clouds_[i].points[k]) ||
                        (!isFinite(got[i].points[k]) && !isFinite(clouds_[i].points[k]));
            EXPECT_EQ(same, got[i].size()) << "message " << i << ", compression " << static_cast<int>(compression);
        }
    }
}

TEST_F(Bag, BadBagsAndTopicsAreInputErrorsNamingTheProblem) {
    auto message = [&](const std::string &path, const std::string &topic) -> std::string {
        try {
            forEachBagCloud(path, topic, [](const Cloud &, const BagCloudInfo &) {});
        } catch (const InputError &e) {
            return e.what();
        }
        return "no error";
    };
    const std::string unknown = message(bag_path_, "/nope");
    EXPECT_NE(unknown.find("/nope"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("/camera/points"), std::string::npos) << "should list the cloud topics: " << unknown;
    const std::string wrong = message(bag_path_, "/camera/rgb");
    EXPECT_NE(wrong.find("sensor_msgs/Image"), std::string::npos) << wrong;
    EXPECT_NE(message(dir_ + "/missing.bag", "/camera/points").find("missing.bag"), std::string::npos);
    const std::string junk = dir_ + "/junk.bag";
    std::ofstream(junk) << "this is not a bag\n";
    EXPECT_NE(message(junk, "/camera/points").find("junk.bag"), std::string::npos);
    // A bag cut short in the middle of its data.
    const std::string cut = dir_ + "/cut.bag";
    {
        std::ifstream in(bag_path_, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    }
    EXPECT_NE(message(cut, "/camera/points").find("cut.bag"), std::string::npos);
}

/// Runs a shell command; returns its exit status and what it printed (stdout + stderr).
std::pair<int, std::string> runCommand(const std::string &cmd) {
    std::string out;
    FILE *pipe = popen((cmd + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return {-1, out};
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST_F(Bag, DetectBagWritesOneJsonLinePerCloud) {
    const std::string calib = dir_ + "/calib.yaml", out = dir_ + "/detections.jsonl";
    writeTestCalibration(calib);
    const std::string cli = PROJSURF_CLI;
    const auto [rc, text] = runCommand("timeout 120 '" + cli + "' detect --bag '" + bag_path_ +
                                       "' --topic /camera/points --calib '" + calib + "' --json '" + out + "'");
    ASSERT_EQ(rc, 0) << text;
    std::ifstream in(out);
    std::vector<nlohmann::json> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    ASSERT_EQ(lines.size(), 3u);
    // Wall, floor only, wall seen from elsewhere.
    EXPECT_TRUE(lines[0].at("found").get<bool>());
    EXPECT_FALSE(lines[1].at("found").get<bool>());
    EXPECT_FALSE(lines[1].at("reason").get<std::string>().empty());
    EXPECT_TRUE(lines[2].at("found").get<bool>());
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(lines[i].at("bag").at("index").get<std::size_t>(), i);
        EXPECT_DOUBLE_EQ(lines[i].at("bag").at("stamp").get<double>(), 100.0 + i);
        EXPECT_EQ(lines[i].at("bag").at("frame_id").get<std::string>(), "camera_optical");
    }
    // The first cloud looks square at the wall 2 m ahead.
    for (const auto &c : lines[0].at("rectangle").at("corners")) EXPECT_NEAR(c.at(2).get<double>(), 2.0, 0.03);

    // Without --json the lines go to stdout.
    const auto [rc2, text2] = runCommand("timeout 120 '" + cli + "' detect --bag '" + bag_path_ +
                                         "' --topic /camera/points --calib '" + calib + "'");
    ASSERT_EQ(rc2, 0) << text2;
    EXPECT_EQ(std::count(text2.begin(), text2.end(), '\n'), 3) << text2;

    // Bad input: exit 2, one line naming the file and the problem, no output file.
    const std::string out3 = dir_ + "/never.jsonl";
    const auto [rc3, text3] = runCommand("timeout 60 '" + cli + "' detect --bag '" + bag_path_ +
                                         "' --topic /nope --calib '" + calib + "' --json '" + out3 + "'");
    EXPECT_EQ(rc3, 2);
    EXPECT_NE(text3.find("projsurf: error: " + bag_path_ + ": no topic '/nope'"), std::string::npos) << text3;
    EXPECT_FALSE(std::ifstream(out3).good());
    // The bag's one cloud topic is taken without --topic.
    const auto [rc4, text4] =
        runCommand("timeout 60 '" + cli + "' detect --bag '" + bag_path_ + "' --calib '" + calib + "'");
    EXPECT_EQ(rc4, 0) << text4;
    EXPECT_EQ(std::count(text4.begin(), text4.end(), '\n'), 3) << text4;
    EXPECT_NE(text4.find("\"topic\":\"/camera/points\""), std::string::npos) << text4;
}
}  // namespace

int main(int argc, char **argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (argc >= 3 && std::string(argv[1]) == "--write-calibration") {
        writeTestCalibration(argv[2]);
        return 0;
    }
    if (argc >= 3 && std::string(argv[1]) == "--wait-for-master") {
        // run_node_test.sh: is the master up yet? (bounded by the given seconds)
        ros::init(argc, argv, "projsurf_wait_master", ros::init_options::AnonymousName | ros::init_options::NoRosout);
        const double seconds = std::stod(argv[2]);
        return waitFor([] { return ros::master::check(); }, seconds) ? 0 : 1;
    }
    ros::init(argc, argv, "projsurf_test_client",
              ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
    return RUN_ALL_TESTS();
}
