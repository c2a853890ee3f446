#pragma once
// A published projector-camera calibration in cv::FileStorage XML as procam-calibration
// writes it: cam_int, cam_dist, proj_int, proj_dist, rotation (spelt "roration" in older
// files), translation (P_proj = R P_cam + t, the board's units), rms.
#include <array>
#include <string>

#include <Eigen/Core>

namespace projsurf {

struct PublishedProcam {
    double cam_fx = 0, cam_fy = 0, cam_cx = 0, cam_cy = 0;
    std::array<double, 5> cam_distortion{{0, 0, 0, 0, 0}};
    double proj_fx = 0, proj_fy = 0, proj_cx = 0, proj_cy = 0;
    std::array<double, 5> proj_distortion{{0, 0, 0, 0, 0}};
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    double rms = 0;
};

/// InputError when the file is missing, unreadable or lacks a key.
PublishedProcam readProcamXml(const std::string &path);

}  // namespace projsurf
