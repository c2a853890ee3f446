// The node with ~explain true (run_node_test.sh starts one on demand and one continuous): its
// ~result carries `candidates`, every vertical plane considered with its verdict and reason in
// words, as `projsurf detect --explain` writes them.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>

#include <cmath>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "conversions.hpp"
#include "node_test_support.hpp"
#include "sim_wall.hpp"

using namespace projsurf;
using namespace projsurf::sim_test;
using namespace projsurf::node_test;

namespace {

/// Every ~result of one namespace's node, parsed.
struct Results {
    std::mutex mutex;
    std::vector<nlohmann::json> all;
    ros::Subscriber sub;

    void open(ros::NodeHandle &nh, const std::string &topic) {
        sub = nh.subscribe<std_msgs::String>(topic, 20, [this](const std_msgs::StringConstPtr &m) {
            std::lock_guard<std::mutex> lock(mutex);
            all.push_back(nlohmann::json::parse(m->data));
        });
    }
    /// The first result for which `wanted` holds, within `seconds`.
    bool wait(const std::function<bool(const nlohmann::json &)> &wanted, double seconds, nlohmann::json &out) {
        return waitFor(
            [&] {
                std::lock_guard<std::mutex> lock(mutex);
                for (const nlohmann::json &j : all)
                    if (wanted(j)) {
                        out = j;
                        return true;
                    }
                return false;
            },
            seconds);
    }
};

/// The answer explains itself: one candidate chosen, the answer's rectangle, every candidate
/// with a verdict, a reason in words and its distance.
void expectExplained(const nlohmann::json &result) {
    ASSERT_TRUE(result.value("found", false)) << result.dump();
    ASSERT_TRUE(result.contains("candidates") && result["candidates"].is_array()) << result.dump();
    const nlohmann::json &candidates = result["candidates"];
    ASSERT_GE(candidates.size(), 1u);
    int chosen = 0;
    for (const nlohmann::json &c : candidates) {
        ASSERT_TRUE(c.contains("verdict") && c["verdict"].is_string()) << c.dump();
        ASSERT_TRUE(c.contains("reason") && c["reason"].is_string()) << c.dump();
        EXPECT_GT(c["reason"].get<std::string>().size(), 10u) << c.dump();
        EXPECT_GT(c.value("distance_m", 0.0), 0.3) << c.dump();
        if (c["verdict"] == "chosen") {
            ++chosen;
            EXPECT_NEAR(c["rectangle"]["width_m"].get<double>(), result["rectangle"]["width_m"].get<double>(), 1e-6);
            EXPECT_EQ(c["reason"].get<std::string>().rfind("chosen: the largest free rectangle", 0), 0u) << c.dump();
            EXPECT_NEAR(c["distance_m"].get<double>(), 2.0, 0.05) << "the front wall, 2 m ahead";
        }
    }
    EXPECT_EQ(chosen, 1) << result.dump();
}

TEST_F(NodeTest, ExplainPutsEveryCandidateInTheResultOnDemand) {
    const std::string ns = env("PROJSURF_EXPLAIN_NS", "/explain");
    Results results;
    results.open(*nh_, ns + "/projsurf/result");
    std_srvs::Trigger call;
    ros::Publisher pub;
    publishRoomAndDetect(*nh_, ns, call, pub);
    if (HasFatalFailure()) return;
    nlohmann::json result;
    ASSERT_TRUE(results.wait([](const nlohmann::json &j) { return j.value("found", false); }, 20.0, result))
        << "no ~result with a surface after a successful ~detect";
    expectExplained(result);
}

TEST_F(NodeTest, ExplainPutsEveryCandidateInTheResultContinuously) {
    const std::string ns = env("PROJSURF_EXPLAIN_CONTINUOUS_NS", "/explain_continuous");
    Results results;
    results.open(*nh_, ns + "/projsurf/result");
    ros::Publisher pub = nh_->advertise<sensor_msgs::PointCloud2>(ns + "/points", 1, true);
    ASSERT_TRUE(waitFor([&] { return pub.getNumSubscribers() > 0; }, 60.0)) << "the node never subscribed to points";
    const ros::Time stamp = ros::Time::now();
    pub.publish(ros_node::toPointCloud2(renderScene(cameraPose(0, 0, 0), {}), header("camera_optical", stamp)));
    nlohmann::json result;
    ASSERT_TRUE(results.wait(
        [&](const nlohmann::json &j) {
            return j.contains("continuous") && std::abs(j["continuous"].value("stamp", 0.0) - stamp.toSec()) < 1e-3;
        },
        20.0, result))
        << "no ~result for the cloud";
    expectExplained(result);
}

}  // namespace
