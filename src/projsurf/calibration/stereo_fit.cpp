#include "projsurf/calibration/stereo_fit.hpp"

#include <cmath>
#include <optional>

#include <opencv2/calib3d.hpp>

namespace projsurf {

namespace {

DeviceIntrinsics fromCv(const cv::Mat &k, const cv::Mat &dist, const cv::Mat &sigma, double rms) {
    DeviceIntrinsics d;
    for (int i = 0; i < 4 && i < static_cast<int>(sigma.total()); ++i) d.sigma[i] = sigma.at<double>(i);
    d.fx = k.at<double>(0, 0);
    d.fy = k.at<double>(1, 1);
    d.cx = k.at<double>(0, 2);
    d.cy = k.at<double>(1, 2);
    for (int i = 0; i < 5 && i < static_cast<int>(dist.total()); ++i) d.distortion[i] = dist.at<double>(i);
    d.rms_px = rms;
    return d;
}

}  // namespace

Projector stereoProjector(const StereoFit &fit, int width, int height) {
    Eigen::Matrix3d r;
    Eigen::Vector3d t;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r(i, j) = fit.rotation(i, j);
        t[i] = fit.translation[i];
    }
    Projector p;
    p.width = width;
    p.height = height;
    p.intrinsics = ProjectorIntrinsics{fit.projector.fx, fit.projector.fy, fit.projector.cx, fit.projector.cy};
    p.distortion = fit.projector.distortion;
    p.setRotation(r.transpose());
    p.origin = -r.transpose() * t;
    p.fov_h = 2 * std::atan(0.5 * width / fit.projector.fx);
    p.fov_v = 2 * std::atan(0.5 * height / fit.projector.fy);
    return p;
}

namespace {

/// One fit on these views, every step to convergence.
StereoFit fitOnce(const std::vector<StereoView> &views, cv::Size camera_size, cv::Size projector_size,
                  const StereoFitConfig &cfg) {
    StereoFit fit;
    fit.views = views.size();
    if (views.size() < 2) {
        fit.problem = "found the board in " + std::to_string(views.size()) +
                      " pose(s); capture 3 or more poses of the board at different angles";
        return fit;
    }
    std::vector<std::vector<cv::Point3f>> board;
    std::vector<std::vector<cv::Point2f>> cam, proj;
    for (const auto &v : views) {
        if (v.board.size() < 6 || v.board.size() != v.camera.size() || v.board.size() != v.projector.size()) {
            fit.problem = "a pose with fewer than 6 board corners seen by both camera and projector";
            return fit;
        }
        board.push_back(v.board);
        cam.push_back(v.camera);
        proj.push_back(v.projector);
        fit.points += v.board.size();
    }
    try {
        const CameraCalibration c = calibrateCameraConverged(board, cam, camera_size, cfg.flags, cfg.criteria, "camera");
        const CameraCalibration p =
            calibrateCameraConverged(board, proj, projector_size, cfg.flags, cfg.criteria, "projector");
        const StereoCalibration s =
            stereoCalibrateConverged(board, cam, proj, c.camera_matrix, c.distortion, p.camera_matrix, p.distortion,
                                     camera_size, cv::CALIB_FIX_INTRINSIC, cfg.criteria);
        fit.rms_px = s.rms_px;
        fit.camera = fromCv(c.camera_matrix, c.distortion, c.sigma, c.rms_px);
        fit.projector = fromCv(p.camera_matrix, p.distortion, p.sigma, p.rms_px);
        fit.rotation = cv::Matx33d(s.rotation);
        fit.translation = cv::Vec3d(s.translation.at<double>(0), s.translation.at<double>(1), s.translation.at<double>(2));
        fit.convergence = {c.convergence, p.convergence, s.convergence};
        fit.ok = true;
    } catch (const cv::Exception &ex) {
        fit.problem = std::string("the calibration did not converge: ") + ex.what();
    }
    return fit;
}

}  // namespace

StereoFit fitStereo(const std::vector<StereoView> &views, cv::Size camera_size, cv::Size projector_size,
                    const StereoFitConfig &cfg) {
    StereoFit fit = fitOnce(views, camera_size, projector_size, cfg);
    if (!fit.ok || !cfg.jackknife || views.size() < 3) return fit;
    // Leave each pose out once; these fits only tell whether they stopped on their cap.
    StereoFitConfig quick = cfg;
    quick.criteria.count = false;
    const int w = projector_size.width, h = projector_size.height;
    std::vector<std::optional<ProjectorEstimate>> loo;
    for (std::size_t i = 0; i < views.size(); ++i) {
        std::vector<StereoView> rest;
        for (std::size_t j = 0; j < views.size(); ++j)
            if (j != i) rest.push_back(views[j]);
        const StereoFit f = fitOnce(rest, camera_size, projector_size, quick);
        if (!f.ok) {
            loo.emplace_back();
            continue;
        }
        loo.emplace_back(projectorEstimate(stereoProjector(f, w, h)));
        for (const auto &c : f.convergence) fit.spread.on_cap += c.on_cap ? 1 : 0;
    }
    const int on_cap = fit.spread.on_cap;
    fit.spread = poseSpread(projectorEstimate(stereoProjector(fit, w, h)), loo);
    fit.spread.on_cap = on_cap;
    return fit;
}

std::vector<std::string> stereoWarnings(const StereoFit &fit, const SpreadLimits &limits) {
    std::vector<std::string> out;
    for (const auto &c : fit.convergence) {
        const std::string w = convergenceWarning(c);
        if (!w.empty()) out.push_back(w);
    }
    if (fit.spread.on_cap > 0)
        out.push_back(std::to_string(fit.spread.on_cap) +
                      " step(s) of the leave-one-pose-out fits stopped on their iteration cap: the spread is "
                      "uncertain");
    const std::string s = spreadWarning(fit.spread, limits);
    if (!s.empty()) out.push_back(s);
    return out;
}

}  // namespace projsurf
