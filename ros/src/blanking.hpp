#pragma once
// The node's side of blanking and focus (contract "Blanking", "Focus"): every continuous-mode
// frame, the framebuffer is blacked out where something stands between the lens and the
// shown rectangle's plane (~blank, default true), the mask is published as ~blanked (mono8,
// framebuffer size, 255 = blanked) and the shown rectangle's focus distance as ~focus_distance
// (std_msgs/Float32, m along the projector axis).
#include <ros/ros.h>

#include <opencv2/core.hpp>

#include "projsurf/people/beam_blanking.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf::ros_node {

class NodeBlanking {
public:
    NodeBlanking(ros::NodeHandle &pnh, const Projector &projector, bool blank);

    /// Blanks `framebuffer` (BGR, framebuffer size) for `cloud` when `shown` is set, and
    /// publishes ~blanked (when blanking) and ~focus_distance (when shown).
    void apply(cv::Mat &framebuffer, const Cloud &cloud, const Rectangle *shown, const std_msgs::Header &header);
    /// Publishes ~focus_distance for a rectangle (on-demand detections).
    void publishFocus(const Rectangle &rectangle);

    bool enabled() const { return blank_; }
    int blankedPixels() const { return blanked_; }
    double lastMs() const { return last_ms_; }  ///< time of the last mask, ms

private:
    Projector projector_;
    bool blank_;
    BeamBlanker blanker_;
    ros::Publisher blanked_pub_, focus_pub_;
    int blanked_ = 0;
    double last_ms_ = 0.0;
};

}  // namespace projsurf::ros_node
