#pragma once
// Inputs for the example when it is given no files: what a depth camera sees of a wall, and a
// picture to show.
#include <algorithm>
#include <cstdint>

#include <opencv2/core.hpp>

#include "projsurf/types.hpp"

/// An organized cloud (camera frame, metres): a level 640x480 depth camera (525 px focal
/// length), 0.8 m above the floor, 2.5 m from a wall.
inline projsurf::Cloud makeWallAndFloor() {
    const projsurf::CameraIntrinsics camera;  // 640x480, fx = fy = 525 px, depth in mm
    cv::Mat depth(camera.height, camera.width, CV_16UC1);
    for (int v = 0; v < camera.height; ++v) {
        const double down = (v - camera.cy) / camera.fy;              // the pixel ray's y / z
        const double z = down > 0 ? std::min(2.5, 0.8 / down) : 2.5;  // floor or wall, m
        depth.row(v).setTo(static_cast<std::uint16_t>(z * camera.depth_scale));
    }
    return projsurf::depthToCloud(depth, camera);
}

/// A 16:9 picture of eight colour bars (B, G, R).
inline cv::Mat makePicture() {
    cv::Mat picture(360, 640, CV_8UC3);
    for (int x = 0; x < picture.cols; ++x) {
        const int bar = x * 8 / picture.cols;
        picture.col(x).setTo(cv::Scalar(bar & 1 ? 255 : 0, bar & 2 ? 255 : 0, bar & 4 ? 255 : 0));
    }
    return picture;
}
