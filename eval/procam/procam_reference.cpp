#include "eval/procam/procam_reference.hpp"

#include <cmath>
#include <optional>

#include <opencv2/calib3d.hpp>
#ifdef PROJSURF_HAVE_STRUCTURED_LIGHT
#include <opencv2/structured_light.hpp>
#else
#include "projsurf/calibration/gray_code.hpp"
#endif

#include "projsurf/io/files/errors.hpp"

namespace projsurf::eval {
namespace {

/// One pose as the script keeps it: every camera corner (the camera's calibration), and the
/// corners carried into the projector with their camera corners (the projector's and the pair's).
struct ReferencePose {
    std::vector<cv::Point3f> board_all;
    std::vector<cv::Point2f> camera_all;
    StereoView carried;
    cv::Size camera;  ///< px
};

/// The decoded projector pixel of camera pixel (x, y), as getProjPixel gives it.
class Decoder {
public:
    Decoder(const std::vector<cv::Mat> &captures, int width, int height, int white_threshold) {
        patterns_.assign(captures.begin(), captures.end() - 2);
#ifdef PROJSURF_HAVE_STRUCTURED_LIGHT
        cv::structured_light::GrayCodePattern::Params p;
        p.width = width;
        p.height = height;
        code_ = cv::structured_light::GrayCodePattern::create(p);
        code_->setWhiteThreshold(static_cast<size_t>(white_threshold));
#else
        (void)white_threshold;
        decoding_ = decodeGray(captures, openCvGrayPatterns(width, height), width, height);
#endif
    }
    bool at(int x, int y, cv::Point2d &projector) const {
#ifdef PROJSURF_HAVE_STRUCTURED_LIGHT
        cv::Point p;
        if (code_->getProjPixel(patterns_, x, y, p)) return false;  // true: an error
        projector = cv::Point2d(p.x, p.y);
        return true;
#else
        const double u = decoding_.column.at<double>(y, x), v = decoding_.row.at<double>(y, x);
        if (std::isnan(u) || std::isnan(v)) return false;
        projector = cv::Point2d(u, v);
        return true;
#endif
    }

private:
    std::vector<cv::Mat> patterns_;
#ifdef PROJSURF_HAVE_STRUCTURED_LIGHT
    cv::Ptr<cv::structured_light::GrayCodePattern> code_;
#else
    GrayDecoding decoding_;
#endif
};

ReferencePose referencePose(const ProcamPose &pose, int width, int height, int camera_width, int camera_height,
                            const PublishedMethodConfig &cfg) {
    const std::vector<cv::Mat> captures = readProcamPose(pose, camera_width, camera_height);
    const cv::Mat &white = captures[captures.size() - 2], &black = captures.back();
    std::vector<cv::Point2f> corners;
    if (!cv::findChessboardCorners(white, cfg.board, corners))
        throw InputError(pose.files[captures.size() - 2], "the published method finds no " +
                                                              std::to_string(cfg.board.width) + "x" +
                                                              std::to_string(cfg.board.height) + " chessboard");
    ReferencePose r;
    for (int j = 0; j < cfg.board.height; ++j)
        for (int i = 0; i < cfg.board.width; ++i)
            r.board_all.emplace_back(static_cast<float>(i * cfg.square_m), static_cast<float>(j * cfg.square_m), 0.f);
    r.camera_all = corners;
    r.camera = white.size();
    const Decoder decoder(captures, width, height, cfg.white_threshold);
    const int half = static_cast<int>(std::ceil(white.cols / 180.0));
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const int cx = static_cast<int>(std::lround(corners[k].x)), cy = static_cast<int>(std::lround(corners[k].y));
        std::vector<cv::Point2d> src, dst;
        for (int dx = -half; dx <= half; ++dx)
            for (int dy = -half; dy <= half; ++dy) {
                const int x = cx + dx, y = cy + dy;
                if (x < 0 || y < 0 || x >= white.cols || y >= white.rows) continue;
                if (int(white.at<uchar>(y, x)) - int(black.at<uchar>(y, x)) <= cfg.black_threshold) continue;
                cv::Point2d p;
                if (decoder.at(x, y, p)) {
                    src.emplace_back(x, y);
                    dst.push_back(p);
                }
            }
        if (static_cast<int>(src.size()) < half * half) continue;
        const cv::Mat h = cv::findHomography(src, dst);
        if (h.empty()) continue;
        const cv::Vec3d q = cv::Matx33d(h) * cv::Vec3d(corners[k].x, corners[k].y, 1.0);
        r.carried.board.push_back(r.board_all[k]);
        r.carried.camera.push_back(corners[k]);
        r.carried.projector.emplace_back(static_cast<float>(q[0] / q[2]), static_cast<float>(q[1] / q[2]));
    }
    if (r.carried.board.size() < 3)
        throw InputError(pose.dir, "the published method carries fewer than 3 corners into the projector");
    return r;
}

DeviceIntrinsics intrinsicsOf(const CameraCalibration &c) {
    DeviceIntrinsics d;
    const cv::Mat &k = c.camera_matrix;
    d.fx = k.at<double>(0, 0);
    d.fy = k.at<double>(1, 1);
    d.cx = k.at<double>(0, 2);
    d.cy = k.at<double>(1, 2);
    for (int i = 0; i < 5 && i < static_cast<int>(c.distortion.total()); ++i) d.distortion[i] = c.distortion.at<double>(i);
    for (int i = 0; i < 4 && i < static_cast<int>(c.sigma.total()); ++i) d.sigma[i] = c.sigma.at<double>(i);
    d.rms_px = c.rms_px;
    return d;
}

/// The script's three fits on these poses, with explicit criteria.
StereoFit referenceFit(const std::vector<ReferencePose> &poses, cv::Size camera, cv::Size projector,
                       const LmCriteria &criteria, const LmCriteria &stereo_criteria) {
    std::vector<std::vector<cv::Point3f>> board_all, board;
    std::vector<std::vector<cv::Point2f>> cam_all, cam, proj;
    StereoFit fit;
    for (const auto &p : poses) {
        board_all.push_back(p.board_all);
        cam_all.push_back(p.camera_all);
        board.push_back(p.carried.board);
        cam.push_back(p.carried.camera);
        proj.push_back(p.carried.projector);
        fit.points += p.carried.board.size();
    }
    fit.views = poses.size();
    const CameraCalibration c = calibrateCameraConverged(board_all, cam_all, camera, 0, criteria, "camera");
    const CameraCalibration p = calibrateCameraConverged(board, proj, projector, 0, criteria, "projector");
    const StereoCalibration s = stereoCalibrateConverged(board, cam, proj, c.camera_matrix, c.distortion,
                                                         p.camera_matrix, p.distortion, camera,
                                                         cv::CALIB_FIX_INTRINSIC, stereo_criteria);
    fit.camera = intrinsicsOf(c);
    fit.projector = intrinsicsOf(p);
    fit.rms_px = s.rms_px;
    fit.rotation = cv::Matx33d(s.rotation);
    fit.translation = cv::Vec3d(s.translation.at<double>(0), s.translation.at<double>(1), s.translation.at<double>(2));
    fit.convergence = {c.convergence, p.convergence, s.convergence};
    fit.ok = true;
    return fit;
}

/// The work of runPublishedMethod; OpenCV's exceptions pass through.
PublishedMethodRun runPublishedMethodOrThrow(const ProcamFolder &folder, const PublishedMethodConfig &cfg) {
    PublishedMethodRun run;
#ifdef PROJSURF_HAVE_STRUCTURED_LIGHT
    run.opencv_decoder = true;
#endif
    std::vector<ReferencePose> poses;
    cv::Size camera;
    for (const auto &pose : folder.poses) {
        poses.push_back(referencePose(pose, folder.width, folder.height, folder.camera_width, folder.camera_height, cfg));
        run.carried.push_back(static_cast<int>(poses.back().carried.board.size()));
        if (camera.area() == 0) camera = poses.back().camera;
    }
    run.corners = cfg.board.area();
    // The script's sizes are numpy shapes, (rows, cols), which OpenCV reads as (width, height).
    const cv::Size cam_size = cfg.numpy_sizes ? cv::Size(camera.height, camera.width) : camera;
    const cv::Size proj_size = cfg.numpy_sizes ? cv::Size(folder.height, folder.width) : cv::Size(folder.width, folder.height);
    const LmCriteria stereo = cfg.stereo_criteria.value_or(cfg.criteria);
    run.fit = referenceFit(poses, cam_size, proj_size, cfg.criteria, stereo);
    run.opencv_defaults = referenceFit(poses, cam_size, proj_size, LmCriteria{30, DBL_EPSILON, true},
                                       LmCriteria{30, 1e-6, true});
    if (!cfg.jackknife || poses.size() < 3) return run;
    LmCriteria quick = cfg.criteria, quick_stereo = stereo;
    quick.count = quick_stereo.count = false;
    std::vector<std::optional<ProjectorEstimate>> loo;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        std::vector<ReferencePose> rest;
        for (std::size_t j = 0; j < poses.size(); ++j)
            if (j != i) rest.push_back(poses[j]);
        const StereoFit f = referenceFit(rest, cam_size, proj_size, quick, quick_stereo);
        loo.emplace_back(projectorEstimate(stereoProjector(f, folder.width, folder.height)));
        for (const auto &c : f.convergence) run.fit.spread.on_cap += c.on_cap ? 1 : 0;
    }
    const int on_cap = run.fit.spread.on_cap;
    run.fit.spread = poseSpread(projectorEstimate(stereoProjector(run.fit, folder.width, folder.height)), loo);
    run.fit.spread.on_cap = on_cap;
    return run;
}

}  // namespace

PublishedMethodRun runPublishedMethod(const ProcamFolder &folder, const PublishedMethodConfig &cfg) {
    try {
        return runPublishedMethodOrThrow(folder, cfg);
    } catch (const cv::Exception &e) {
        throw InputError(folder.poses.empty() ? std::string(".") : folder.poses.front().dir,
                         std::string("the published method (eval --procam's reference) fails on these captures: ") +
                             e.what());
    }
}

}  // namespace projsurf::eval
