#pragma once
// ROS messages <-> the library's types. Nothing here decides anything.
#include <geometry_msgs/PolygonStamped.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/MarkerArray.h>

#include <opencv2/core.hpp>
#include <string>

#include "projsurf/detector/detector.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::ros_node {

/// x, y, z of a PointCloud2 (camera optical frame); throws InputError on a layout it cannot read.
Cloud toCloud(const sensor_msgs::PointCloud2 &msg);
/// Organized cloud from a depth image (16UC1 in mm, or 32FC1 in m) and its camera_info
/// (K only; the depth is taken as rectified). Throws InputError on other encodings or sizes.
Cloud toCloud(const sensor_msgs::Image &depth, const sensor_msgs::CameraInfo &info);

/// A picture to show: bgr8, rgb8, bgra8, rgba8 or mono8 -> a BGR cv::Mat (copied). Throws
/// InputError(what, problem) for another encoding or data shorter than the size.
cv::Mat toBgr(const sensor_msgs::Image &msg, const std::string &what = "image");
/// Colour for the surface suitability: as toBgr, but a grey image (mono8) is refused too (it
/// cannot tell colours apart); `topic` names it in the error.
cv::Mat colourToBgr(const sensor_msgs::Image &msg, const std::string &topic);
/// A BGR (CV_8UC3) image -> bgr8 message.
sensor_msgs::Image toImageMsg(const cv::Mat &bgr, const std_msgs::Header &header);
/// An organized cloud as a PointCloud2 (x, y, z float32), for tests and tools.
sensor_msgs::PointCloud2 toPointCloud2(const Cloud &cloud, const std_msgs::Header &header);

/// The rectangle's corners (top-left, top-right, bottom-right, bottom-left) as a polygon.
geometry_msgs::PolygonStamped toPolygon(const Rectangle &rect, const std_msgs::Header &header);

/// RViz markers: the plane (a translucent patch), the projector workspace on it, the
/// rectangle (outline and fill); on failure a text with the reason. Starts with DELETEALL so
/// stale markers disappear.
visualization_msgs::MarkerArray toMarkers(const Detection &det, const Rectangle *shown, const std_msgs::Header &header,
                                          const std::string &ns);

}  // namespace projsurf::ros_node
