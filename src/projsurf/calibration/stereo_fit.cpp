#include "projsurf/calibration/stereo_fit.hpp"

#include <cmath>

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

StereoFit fitStereo(const std::vector<StereoView> &views, cv::Size camera_size, cv::Size projector_size) {
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
        cv::Mat kc, dc, kp, dp, r, t, e, f;
        std::vector<cv::Mat> rv, tv;
        cv::Mat sc, sp, extrinsic_sigma, per_view;
        // Tangential distortion held at zero: over a few board poses seen through narrow lenses
        // it trades against the principal point and the pose instead of measuring the lens.
        const int flags = cv::CALIB_ZERO_TANGENT_DIST;
        const double rms_c =
            cv::calibrateCamera(board, cam, camera_size, kc, dc, rv, tv, sc, extrinsic_sigma, per_view, flags);
        const double rms_p =
            cv::calibrateCamera(board, proj, projector_size, kp, dp, rv, tv, sp, extrinsic_sigma, per_view, flags);
        fit.rms_px = cv::stereoCalibrate(board, cam, proj, kc, dc, kp, dp, camera_size, r, t, e, f,
                                         cv::CALIB_FIX_INTRINSIC);
        fit.camera = fromCv(kc, dc, sc, rms_c);
        fit.projector = fromCv(kp, dp, sp, rms_p);
        fit.rotation = cv::Matx33d(r);
        fit.translation = cv::Vec3d(t.at<double>(0), t.at<double>(1), t.at<double>(2));
        fit.ok = true;
    } catch (const cv::Exception &ex) {
        fit.problem = std::string("the calibration did not converge: ") + ex.what();
    }
    return fit;
}

}  // namespace projsurf
