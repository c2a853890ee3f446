// The node's translation of the front ends' shared outcomes (no master): colour the policy
// refuses is not used, with the CLI's sentence naming the topic, and the frame goes on without
// it; a warning is repeated at most every kWarningRepeatS, not once per frame.
#include <gtest/gtest.h>

#include <boost/make_shared.hpp>
#include <opencv2/imgproc.hpp>

#include "colour_input.hpp"
#include "conversions.hpp"
#include "node_test_support.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/io/files/errors.hpp"
#include "sim_wall.hpp"
#include "warning_throttle.hpp"

using namespace projsurf;
using namespace projsurf::sim_test;
using namespace projsurf::node_test;

namespace {

TEST(NodeWarnings, AWarningIsRepeatedAtMostEveryPeriodWhileItLasts) {
    ros_node::WarningThrottle t;
    EXPECT_TRUE(ros_node::warningDue(t, "a", 100.0));
    EXPECT_FALSE(ros_node::warningDue(t, "a", 101.0)) << "not once per frame";
    EXPECT_TRUE(ros_node::warningDue(t, "b", 101.0)) << "another problem is said at once";
    EXPECT_FALSE(ros_node::warningDue(t, "a", 100.0 + ros_node::kWarningRepeatS - 0.1));
    EXPECT_TRUE(ros_node::warningDue(t, "a", 100.0 + ros_node::kWarningRepeatS)) << "again while it lasts";
    EXPECT_TRUE(ros_node::warningDue(t, "c", 1000.0));
    EXPECT_EQ(t.last_s.size(), 1u) << "texts said long ago are forgotten";
}

TEST(NodeWarnings, ColourOfAnotherSizeIsTheClisErrorAsAWarningAndTheFrameGoesOnWithout) {
    const Eigen::Isometry3d pose = cameraPose(0.0, 0.0, 0.0);
    SceneOptions scene;
    scene.picture = true;
    const Cloud cloud = renderScene(pose, scene);
    cv::Mat big;
    cv::resize(renderColour(pose, scene), big, cv::Size(640, 480), 0, 0, cv::INTER_NEAREST);
    // What `detect --rgb` and Python's colour= stop on (exit 2, InputError) ...
    std::string cli;
    try {
        Cloud c = cloud;
        frontend::attachRegisteredColour(c, big, "/cam/rgb/image_rect_color", RegistrationOptions{});
    } catch (const InputError &e) {
        cli = e.what();
    }
    EXPECT_EQ(cli, "/cam/rgb/image_rect_color: colour image is 640x480, the cloud is " + std::to_string(cloud.width) +
                       "x" + std::to_string(cloud.height));
    // ... the node says in the same words, and detects the frame without colour.
    ros_node::ColourInput in("/cam/rgb/image_rect_color", RegistrationOptions{});
    Cloud c = cloud;
    const auto msg = boost::make_shared<sensor_msgs::Image>(ros_node::toImageMsg(big, header("rgb", ros::Time(1.0))));
    EXPECT_EQ(in.attach(c, *msg, "depth A"), cli);
    EXPECT_FALSE(c.hasColour());
    EXPECT_EQ(c.points.size(), cloud.points.size());
}

}  // namespace
