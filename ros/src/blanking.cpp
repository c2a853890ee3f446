#include "blanking.hpp"

#include <sensor_msgs/Image.h>
#include <std_msgs/Float32.h>

#include <cstring>

#include "projsurf/people/focus.hpp"

namespace projsurf::ros_node {
namespace {

sensor_msgs::Image toMono8(const cv::Mat &mask, const std_msgs::Header &header) {
    sensor_msgs::Image msg;
    msg.header = header;
    msg.height = static_cast<std::uint32_t>(mask.rows);
    msg.width = static_cast<std::uint32_t>(mask.cols);
    msg.encoding = "mono8";
    msg.is_bigendian = 0;
    msg.step = static_cast<std::uint32_t>(mask.cols);
    msg.data.resize(static_cast<std::size_t>(mask.rows) * mask.cols);
    for (int y = 0; y < mask.rows; ++y)
        std::memcpy(&msg.data[static_cast<std::size_t>(y) * mask.cols], mask.ptr(y), mask.cols);
    return msg;
}

}  // namespace

NodeBlanking::NodeBlanking(ros::NodeHandle &pnh, const Projector &projector, bool blank)
    : projector_(projector), blank_(blank), blanker_(projector) {
    if (blank_) blanked_pub_ = pnh.advertise<sensor_msgs::Image>("blanked", 1, true);
    focus_pub_ = pnh.advertise<std_msgs::Float32>("focus_distance", 1, true);
}

void NodeBlanking::publishFocus(const Rectangle &rectangle) {
    std_msgs::Float32 f;
    f.data = static_cast<float>(focusFor(projector_, rectangle).distance_m);
    focus_pub_.publish(f);
}

void NodeBlanking::apply(cv::Mat &framebuffer, const Cloud &cloud, const Rectangle *shown,
                         const std_msgs::Header &header) {
    blanked_ = 0;
    if (shown) publishFocus(*shown);
    if (!blank_) return;
    const ros::WallTime start = ros::WallTime::now();
    if (shown) {
        const auto &c = shown->corners;
        const Eigen::Vector3d normal = (c[1] - c[0]).cross(c[3] - c[0]).normalized();
        const cv::Mat &mask = blanker_.compute(cloud, makePlane(normal, -normal.dot(shown->center())));
        applyBlanking(framebuffer, mask);
        blanked_ = blanker_.blankedPixels();
        last_ms_ = (ros::WallTime::now() - start).toSec() * 1e3;
        blanked_pub_.publish(toMono8(mask, header));
    } else {
        last_ms_ = 0.0;
        blanked_pub_.publish(toMono8(cv::Mat::zeros(projector_.height, projector_.width, CV_8U), header));
    }
}

}  // namespace projsurf::ros_node
