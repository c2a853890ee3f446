#pragma once
// projsurf_node: ROS 1 front end of the library (contract, "ROS node"). Subscribes to the
// clouds (or depth + camera_info) and the picture; the ~detect service runs one detection
// (the paper's start signal, section 5); continuous mode detects on every cloud and keeps the
// picture steady on the wall while the robot moves.
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

#include "blanking.hpp"
#include "colour_input.hpp"
#include "params.hpp"
#include "plan_service.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/inputs/stamp_pairing.hpp"
#include "warning_throttle.hpp"

namespace projsurf::ros_node {

/// Clouds in a row without their colour image after which a cloud no longer waits for it (the
/// colour stream stopped): a waiting cloud is detected one cloud late in continuous mode.
constexpr int kColourlessToStopWaiting = 3;

class ProjsurfNode {
public:
    /// `nh` resolves the input topics, `pnh` (private, "~") the outputs and the service.
    ProjsurfNode(ros::NodeHandle nh, ros::NodeHandle pnh, NodeParams params);

private:
    struct Outcome {
        bool success = false;
        std::string message;
    };

    void onCloud(const sensor_msgs::PointCloud2ConstPtr &msg);
    void onDepth(const sensor_msgs::ImageConstPtr &msg);
    void onCameraInfo(const sensor_msgs::CameraInfoConstPtr &msg);
    void onImage(const sensor_msgs::ImageConstPtr &msg);
    void onColour(const sensor_msgs::ImageConstPtr &msg);  ///< ~use_colour: the registered colour
    bool onDetect(std_srvs::Trigger::Request &req, std_srvs::Trigger::Response &res);
    bool onPlan(std_srvs::Trigger::Request &req, std_srvs::Trigger::Response &res);  ///< ~plan (plan_service.hpp)

    /// `stream`: the depth stream's geometry (colour_input.hpp's `stream`); `topic`: where it came from.
    void takeCloud(Cloud cloud, const std_msgs::Header &header, const std::string &stream, const std::string &topic);
    /// The depth image with this camera_info as a cloud (or rejected).
    void takeDepth(const sensor_msgs::Image &depth, const sensor_msgs::CameraInfo &info);
    /// ~use_colour: the colour image of the latest cloud's stamp into cloud_ (when it fits);
    /// colour_note_ says why not.
    void useColour(const sensor_msgs::Image &colour);
    /// The latest cloud waits for its colour image: it takes the nearest one within
    /// kColourMaxOffsetS, or goes without colour (a warning says so).
    void settleColourWait();
    /// A cloud (or depth image) that cannot be used: kept out, and remembered for ~detect.
    void rejectCloud(const std::string &what, const std::string &problem, const std_msgs::Header &header);
    /// ~detect's answer; it says when the latest cloud was rejected (and answers from the last valid one).
    Outcome detectOnce();
    Outcome detectOnValidCloud();
    /// ~detect's words on the colour: the chosen rectangle's suitability, or why colour was not used.
    std::string colourSummary(const Detection &det) const;
    void runContinuous();
    /// The latest cloud detected as every front end detects one (frontend::detectWithGravity),
    /// with the CLI's warnings about its gravity and depth range (warning_throttle.hpp; the
    /// floor is searched to check the gravity on the first cloud only). Throws as detectWithGravity.
    frontend::GravityDetection detectLatest();
    /// How to find gravity for this cloud (frontend::detectWithGravity resolves it): from tf2
    /// when ~gravity_frame is set, from the floor with ~gravity auto when tf gives none, else ~gravity.
    frontend::GravityChoice gravityChoiceFor(const std_msgs::Header &header, std::string &problem);
    bool lookup(const std::string &target, const std::string &source, const ros::Time &stamp, Eigen::Isometry3d &pose,
                std::string &problem);
    /// Warps the picture into `rect` (camera frame) and publishes it; empty string on success.
    std::string publishFramebuffer(const Rectangle &rect, const std_msgs::Header &header);
    void publishBlack(const std_msgs::Header &header);
    void writeFramebufferFile(const cv::Mat &image);

    NodeParams params_;
    ros::NodeHandle nh_, pnh_;
    ros::Subscriber cloud_sub_, depth_sub_, info_sub_, image_sub_, colour_sub_;
    ros::Publisher result_pub_, rectangle_pub_, framebuffer_pub_, markers_pub_;
    ros::ServiceServer detect_srv_, plan_srv_;
    std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
    std::unique_ptr<tf2_ros::TransformListener> tf_listener_;

    cv::Mat picture_;  ///< BGR picture to show
    bool picture_from_topic_ = false;
    Cloud cloud_;  ///< latest cloud
    std_msgs::Header cloud_header_;
    bool have_cloud_ = false;
    std::string rejected_;        ///< why the latest cloud was rejected; empty when it was used
    std::string cloud_topic_;     ///< the topic of the latest cloud (or depth image), named in warnings about it
    bool floor_checked_ = false;  ///< the gravity was checked against the floor (once: the mount does not change)
    bool range_checked_ =
        false;                  ///< the depth range of cloud_topic_ was checked (once a topic: its units do not change)
    WarningThrottle warnings_;  ///< the warnings about the clouds' gravity and depth range
    /// camera_info by stamp: each depth image is paired with the one of its own stamp.
    frontend::StampedBuffer<sensor_msgs::CameraInfoConstPtr> camera_infos_;
    sensor_msgs::ImageConstPtr pending_depth_;       ///< a depth image whose camera_info has not come yet
    std::unique_ptr<ColourInput> colour_;            ///< ~use_colour (null without)
    bool colour_wait_ = false;                       ///< the latest cloud waits for the colour image of its stamp
    std::string colour_note_;                        ///< why the latest cloud has no colour ("" when it has)
    double colour_ms_ = 0.0;                         ///< ms spent putting the colour into the latest cloud
    std::string depth_stream_;                       ///< the depth stream's geometry (colour_input.hpp's `stream`)
    int colourless_ = 0;                             ///< clouds in a row whose colour image never came
    SurfaceDetector detector_;                       ///< one for the stream: its buffers are reused frame to frame
    std::unique_ptr<ContinuousTracker> continuous_;  ///< ~continuous (null without)
    std::unique_ptr<NodeBlanking> blanking_;         ///< ~blanked, ~focus_distance
    std::unique_ptr<NodePlanner> planner_;           ///< ~plan
    ros::WallTime last_file_write_;
    double rate_hz_ = 0.0;  ///< running estimate of the continuous-mode frame rate
    ros::WallTime last_frame_;
};

}  // namespace projsurf::ros_node
