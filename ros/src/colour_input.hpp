#pragma once
// The node's registered colour: colour images kept by stamp, so that each cloud
// (depth image) gets the colour image of its own stamp (frontend/inputs/stamp_pairing.hpp, as depth
// gets its camera_info), put into the cloud by the front ends' one policy
// (frontend/inputs/registered_colour.hpp), whose registration check
// (detection/colour/colour_registration.hpp) runs once per stream here, not per frame. Colour the
// policy refuses (another size or encoding: an error in the CLI and Python) or does not use (not
// registered) leaves the frame to be detected without it, with a warning naming the topic
// (warning_throttle.hpp: not one per frame).
#include <ros/time.h>
#include <sensor_msgs/Image.h>

#include <string>

#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/frontend/inputs/stamp_pairing.hpp"
#include "projsurf/types/cloud.hpp"
#include "warning_throttle.hpp"

namespace projsurf::ros_node {

/// s: a colour image this near a depth image's stamp is taken for it when none has the same
/// stamp (half a frame period of a 30 Hz camera: nearer than any other frame).
constexpr double kColourMaxOffsetS = 0.5 / 30.0;
/// s: while the check cannot tell (too few depth edges in view), it is tried again this often.
constexpr double kRecheckPeriodS = 2.0;

class ColourInput {
public:
    /// `topic`: the colour topic's resolved name, for messages; `options`: the config's
    /// suitability.registration.
    ColourInput(std::string topic, const RegistrationOptions &options) : topic_(std::move(topic)), options_(options) {}

    void add(const sensor_msgs::ImageConstPtr &msg) { images_.add(msg->header.stamp.toSec(), msg); }
    /// The colour image of this stamp, else nullptr.
    sensor_msgs::ImageConstPtr exact(const ros::Time &stamp) const;
    /// The colour image nearest `stamp` when within kColourMaxOffsetS, else nullptr; `offset_s`
    /// is set to the nearest one's distance (infinity when there is none).
    sensor_msgs::ImageConstPtr near(const ros::Time &stamp, double &offset_s) const;

    /// Puts `colour` into `cloud` (organized, camera frame) when the policy allows it: the same
    /// size as the cloud, a colour encoding, and registered. `stream` names the depth stream's
    /// geometry (size, intrinsics, frame): the registration is checked again when it or the
    /// colour's size or frame changes. Returns "" when attached, else why not, the policy's
    /// sentence naming the topic; each warning is logged as warning_throttle.hpp says.
    std::string attach(Cloud &cloud, const sensor_msgs::Image &colour, const std::string &stream);

    /// The latest registration check (checked = false before any).
    const RegistrationResult &verdict() const { return verdict_; }
    /// The latest check in words: "registered", "not registered", "cannot tell" ("" before any).
    std::string registration() const;
    /// ms the latest registration check took.
    double lastCheckMs() const { return check_ms_; }

private:
    /// The policy's registration check for the stream `key`: the verdict kept for it, checked
    /// again for another stream, or while it cannot tell, every kRecheckPeriodS.
    RegistrationResult verdictFor(const std::string &key, const Cloud &cloud, const cv::Mat &bgr);

    std::string topic_;
    RegistrationOptions options_;
    /// The latest few (a sixth of a second at 30 Hz: colour and depth of one instant arrive
    /// within a frame or two of each other; full-size images are large).
    frontend::StampedBuffer<sensor_msgs::ImageConstPtr> images_{5};
    bool consulted_ = false;      ///< the latest attach() got as far as the registration
    std::string checked_stream_;  ///< the stream (depth geometry + colour size/frame) verdict_ is for
    RegistrationResult verdict_;
    ros::WallTime last_check_;
    double check_ms_ = 0.0;
    WarningThrottle warnings_;
};

}  // namespace projsurf::ros_node
