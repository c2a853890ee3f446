#pragma once
// What the node tests share: bounded waits, an inbox of one topic's messages by stamp, the
// fixture that connects to the master run_node_test.sh started.
#include <geometry_msgs/PolygonStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_srvs/Trigger.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "conversions.hpp"
#include "sim_wall.hpp"

namespace projsurf::node_test {

inline std::string env(const char *name, const std::string &fallback = "") {
    const char *v = std::getenv(name);
    return v != nullptr ? v : fallback;
}

/// Polls `done` until it is true or `seconds` pass (wall clock).
inline bool waitFor(const std::function<bool()> &done, double seconds) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::WallTime::now() < end) {
        if (done()) return true;
        ros::WallDuration(0.01).sleep();
    }
    return done();
}

/// Keeps the messages of one topic, by header stamp.
template <typename Msg>
struct Inbox {
    std::mutex mutex;
    std::map<ros::Time, Msg> by_stamp;
    ros::Subscriber sub;

    void open(ros::NodeHandle &nh, const std::string &topic) {
        sub = nh.subscribe<Msg>(topic, 100, [this](const boost::shared_ptr<const Msg> &m) {
            std::lock_guard<std::mutex> lock(mutex);
            by_stamp[m->header.stamp] = *m;
        });
    }
    bool waitStamp(const ros::Time &stamp, double seconds, Msg &out) {
        const bool ok = waitFor(
            [&] {
                std::lock_guard<std::mutex> lock(mutex);
                return by_stamp.count(stamp) > 0;
            },
            seconds);
        if (!ok) return false;
        std::lock_guard<std::mutex> lock(mutex);
        out = by_stamp.at(stamp);
        return true;
    }
    std::map<ros::Time, Msg> snapshot() {
        std::lock_guard<std::mutex> lock(mutex);
        return by_stamp;
    }
    /// For a failed wait: what did come ("2 messages, stamps 12.300 12.400; 1 publisher").
    std::string received() {
        std::lock_guard<std::mutex> lock(mutex);
        std::string text = std::to_string(by_stamp.size()) + " messages on " + sub.getTopic();
        if (!by_stamp.empty()) text += ", stamps";
        char stamp[32];
        for (const auto &[t, m] : by_stamp) {
            std::snprintf(stamp, sizeof stamp, " %.3f", t.toSec());
            text += stamp;
        }
        return text + "; " + std::to_string(sub.getNumPublishers()) + " publisher(s) connected";
    }
};

inline std_msgs::Header header(const std::string &frame, const ros::Time &stamp) {
    std_msgs::Header h;
    h.frame_id = frame;
    h.stamp = stamp;
    return h;
}

inline std::array<Eigen::Vector3d, 4> corners(const geometry_msgs::PolygonStamped &p) {
    std::array<Eigen::Vector3d, 4> c;
    for (int i = 0; i < 4; ++i)
        c[i] = Eigen::Vector3d(p.polygon.points[i].x, p.polygon.points[i].y, p.polygon.points[i].z);
    return c;
}

/// The cloud as a 16UC1 depth image (mm, 0 = no reading).
inline sensor_msgs::Image depthImage(const Cloud &cloud, const std_msgs::Header &h) {
    sensor_msgs::Image depth;
    depth.header = h;
    depth.width = cloud.width;
    depth.height = cloud.height;
    depth.encoding = "16UC1";
    depth.step = depth.width * 2;
    depth.data.assign(depth.step * depth.height, 0);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const float z = cloud.points[i].z();
        const std::uint16_t mm = std::isfinite(z) ? static_cast<std::uint16_t>(std::lround(z * 1000.0f)) : 0;
        std::memcpy(&depth.data[2 * i], &mm, 2);
    }
    return depth;
}

inline bool isBlack(const sensor_msgs::Image &img, int u, int v) {
    const std::uint8_t *p = &img.data[static_cast<std::size_t>(v) * img.step + 3 * u];
    return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

/// Calls `service` until the node has answered on the cloud of `stamp`, i.e. published its
/// message of that stamp in `inbox`; `call` keeps the last answer. A successful answer alone
/// does not say which cloud it was about: the node answers on the latest cloud it has, which
/// may still be an earlier test's while this cloud is on its way (slow under load).
template <typename Msg>
bool detectUntilAnswered(const std::string &service, Inbox<Msg> &inbox, const ros::Time &stamp, std_srvs::Trigger &call,
                         Msg &out, double seconds = 20.0) {
    return waitFor(
        [&] {
            call = std_srvs::Trigger();
            return ros::service::call(service, call) && inbox.waitStamp(stamp, 0.5, out);
        },
        seconds);
}

/// Publishes the simulated room (sim_wall.hpp, the camera at the origin) on `ns`/points and
/// calls `ns`/projsurf/detect until it has answered on that cloud, with success (bounded
/// waits); `call` keeps the last answer.
inline void publishRoomAndDetect(ros::NodeHandle &nh, const std::string &ns, std_srvs::Trigger &call,
                                 ros::Publisher &pub) {
    Inbox<geometry_msgs::PolygonStamped> rects;
    rects.open(nh, ns + "/projsurf/rectangle");
    pub = nh.advertise<sensor_msgs::PointCloud2>(ns + "/points", 1, true);
    const std::string service = ns + "/projsurf/detect";
    ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(60.0))) << service << " never came up";
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 30.0)) << "the node never subscribed to points";
    const ros::Time stamp = ros::Time::now();
    pub.publish(ros_node::toPointCloud2(sim_test::renderScene(sim_test::cameraPose(0, 0, 0), {}),
                                        header("camera_optical", stamp)));
    geometry_msgs::PolygonStamped rect;
    ASSERT_TRUE(detectUntilAnswered(service, rects, stamp, call, rect))
        << "no ~rectangle for the room's cloud; " << rects.received() << "; last answer: " << call.response.message;
    ASSERT_TRUE(call.response.success) << call.response.message;
}

class NodeTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(ros::master::check()) << "no rosmaster at " << ros::master::getURI();
        nh_ = std::make_unique<ros::NodeHandle>();
        spinner_ = std::make_unique<ros::AsyncSpinner>(2);
        spinner_->start();
    }
    void TearDown() override {
        if (spinner_) spinner_->stop();
    }
    std::unique_ptr<ros::NodeHandle> nh_;
    std::unique_ptr<ros::AsyncSpinner> spinner_;
};

}  // namespace projsurf::node_test
