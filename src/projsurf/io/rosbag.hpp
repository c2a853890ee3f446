#pragma once
// projsurf/io/rosbag: ROS 1 bags read and written without ROS: clouds and depth images of a topic,
// camera_info.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/io/rosbag/bag_writer.hpp"
#include "projsurf/io/rosbag/depth_image_bytes.hpp"
#include "projsurf/io/rosbag/pointcloud2.hpp"
#include "projsurf/io/rosbag/ros_messages.hpp"
#include "projsurf/io/rosbag/rosbag_clouds.hpp"
#include "projsurf/io/rosbag/rosbag_depth.hpp"
