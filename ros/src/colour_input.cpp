#include "colour_input.hpp"

#include <ros/console.h>

#include <cmath>
#include <limits>

#include "conversions.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
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

RegistrationResult ColourInput::verdictFor(const std::string &key, const Cloud &cloud, const cv::Mat &bgr) {
    // Once per stream; again only while the check cannot tell (a flat wall has no depth edges).
    const ros::WallTime now = ros::WallTime::now();
    if (key != checked_stream_ || (!verdict_.checked && (now - last_check_).toSec() >= kRecheckPeriodS)) {
        verdict_ = checkColourRegistration(cloud, bgr, options_);
        check_ms_ = (ros::WallTime::now() - now).toSec() * 1e3;
        checked_stream_ = key;
        last_check_ = now;
        ROS_DEBUG("projsurf_node: colour registration check: %s (%.1f ms)", verdict_.summary().c_str(), check_ms_);
    }
    consulted_ = true;
    return verdict_;
}

std::string ColourInput::attach(Cloud &cloud, const sensor_msgs::Image &colour, const std::string &stream) {
    const std::string key = stream + " | colour " + std::to_string(colour.width) + "x" +
                            std::to_string(colour.height) + " " + colour.header.frame_id;
    consulted_ = false;
    try {
        const frontend::ColourAttachment attached = frontend::attachRegisteredColour(
            cloud, colourToBgr(colour, topic_), topic_,
            [&](const Cloud &c, const cv::Mat &bgr) { return verdictFor(key, c, bgr); });
        for (const std::string &w : attached.warnings) warnThrottled(warnings_, w);
        if (attached.used) return {};
        return attached.warnings.empty() ? topic_ + ": the colour does not fit the cloud" : attached.warnings.front();
    } catch (const InputError &e) {  // an error where the CLI and Python stop; here, this frame goes without
        warnThrottled(warnings_, std::string(e.what()) + "; not used, the frame is detected without colour");
        return e.what();
    }
}

}  // namespace projsurf::ros_node
