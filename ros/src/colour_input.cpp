#include "colour_input.hpp"

#include <ros/console.h>

#include <cmath>
#include <limits>

#include "conversions.hpp"
#include "projsurf/io/files/errors.hpp"

namespace projsurf::ros_node {

sensor_msgs::ImageConstPtr ColourInput::exact(const ros::Time &stamp) const {
    const auto *found = images_.exact(stamp.toSec());
    return found != nullptr ? *found : nullptr;
}

sensor_msgs::ImageConstPtr ColourInput::near(const ros::Time &stamp, double &offset_s) const {
    double at = 0.0;
    const auto *found = images_.nearest(stamp.toSec(), at);
    offset_s = found != nullptr ? std::abs(at - stamp.toSec()) : std::numeric_limits<double>::infinity();
    return found != nullptr && offset_s <= kColourMaxOffsetS ? *found : nullptr;
}

std::string ColourInput::registration() const {
    if (!consulted_) return {};
    if (!verdict_.checked) return "cannot tell";
    return verdict_.registered ? "registered" : "not registered";
}

void ColourInput::warnOnce(const std::string &key, const std::string &text) {
    if (!warned_.insert(key).second) return;
    ROS_WARN("projsurf_node: %s", text.c_str());
}

std::string ColourInput::attach(Cloud &cloud, const sensor_msgs::Image &colour, const std::string &stream) {
    const std::string size = std::to_string(colour.width) + "x" + std::to_string(colour.height);
    const std::string key = stream + " | colour " + size + " " + colour.header.frame_id;
    consulted_ = false;
    if (!cloud.organized()) {
        const std::string why = "the cloud is not organized (colour needs a depth image or an organized cloud)";
        warnOnce(key + " unorganized", "colour on " + topic_ + " not used: " + why);
        return why;
    }
    if (colour.width != static_cast<unsigned>(cloud.width) || colour.height != static_cast<unsigned>(cloud.height)) {
        const std::string why = "the colour image is " + size + ", the depth " + std::to_string(cloud.width) + "x" +
                                std::to_string(cloud.height) + " (it must be registered to the depth, pixel by pixel)";
        warnOnce(key + " size", "colour on " + topic_ + " not used: " + why);
        return why;
    }
    if (colour.encoding == "mono8") {
        const std::string why = "its encoding is mono8; need bgr8 or rgb8";
        warnOnce(key + " encoding", "colour on " + topic_ + " not used: " + why);
        return why;
    }
    cv::Mat bgr;
    try {
        bgr = toBgr(colour);
    } catch (const InputError &e) {
        warnOnce(key + " encoding", "colour on " + topic_ + " not used: " + e.what());
        return e.what();
    }
    // Once per stream; again only while the check cannot tell (a flat wall has no depth edges).
    const ros::WallTime now = ros::WallTime::now();
    if (key != checked_stream_ || (!verdict_.checked && (now - last_check_).toSec() >= kRecheckPeriodS)) {
        verdict_ = checkColourRegistration(cloud, bgr);
        check_ms_ = (ros::WallTime::now() - now).toSec() * 1e3;
        checked_stream_ = key;
        last_check_ = now;
        ROS_DEBUG("projsurf_node: colour registration check: %s (%.1f ms)", verdict_.summary().c_str(), check_ms_);
    }
    consulted_ = true;
    if (verdict_.checked && !verdict_.registered) {
        const std::string why = "it is not registered to the depth (" + verdict_.summary() + ")";
        warnOnce(key + " unregistered", "colour on " + topic_ + " not used: " + why);
        return why;
    }
    if (!verdict_.checked)
        warnOnce(key + " unchecked", "cannot check that the colour on " + topic_ + " is registered to the depth (" +
                                         verdict_.summary() + "); used as given");
    if (!attachColour(cloud, bgr)) return "the colour does not fit the cloud";
    return {};
}

}  // namespace projsurf::ros_node
