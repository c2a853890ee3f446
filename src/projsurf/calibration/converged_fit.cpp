#include "projsurf/calibration/converged_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <opencv2/calib3d.hpp>

namespace projsurf {

namespace {

void append(std::vector<double> &out, const cv::Mat &m) {
    cv::Mat d;
    m.convertTo(d, CV_64F);
    d = d.reshape(1, 1);
    for (int i = 0; i < d.cols; ++i) out.push_back(d.at<double>(0, i));
}

double relativeL2(const std::vector<double> &a, const std::vector<double> &b) {
    double num = 0, den = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        num += (a[i] - b[i]) * (a[i] - b[i]);
        den += b[i] * b[i];
    }
    return den > 0 ? std::sqrt(num / den) : std::sqrt(num);
}

/// `run(cap)` -> the reported parameters (the first `intrinsics` of them focal lengths and
/// principal points, px). Fills `c` from the runs and returns the result at the full cap.
template <typename Result>
Result converge(const std::function<Result(int)> &run, const std::function<std::vector<double>(const Result &)> &params,
                int intrinsics, const LmCriteria &criteria, FitConvergence &c) {
    const int cap = std::clamp(criteria.max_iterations, 1, 1000);
    c.cap = cap;
    Result final = run(cap);
    if (cap == 1) {
        c.iterations = 1;
        c.on_cap = true;
        return final;
    }
    const std::vector<double> p = params(final);
    std::vector<double> before;
    if (criteria.count) {
        int lo = 1, hi = cap;  // run(hi) == final
        while (lo < hi) {
            const int mid = lo + (hi - lo) / 2;
            if (params(run(mid)) == p)
                hi = mid;
            else
                lo = mid + 1;
        }
        c.iterations = hi;
        if (hi > 1) before = params(run(hi - 1));
    } else {
        before = params(run(cap - 1));
        c.iterations = before == p ? 0 : cap;
    }
    c.on_cap = c.iterations >= cap;
    if (!before.empty()) {
        c.last_step = relativeL2(p, before);
        for (int i = 0; i < intrinsics && i < static_cast<int>(p.size()); ++i)
            c.last_step_px = std::max(c.last_step_px, std::abs(p[i] - before[i]));
    }
    return final;
}

}  // namespace

std::string describeConvergence(const FitConvergence &c) {
    char buf[240];
    if (c.iterations > 0)
        std::snprintf(buf, sizeof buf, "%s: %d iterations (cap %d), last step %.1e relative, %.2g px%s", c.fit.c_str(),
                      c.iterations, c.cap, c.last_step, c.last_step_px, c.on_cap ? ", STOPPED ON ITS CAP" : "");
    else
        std::snprintf(buf, sizeof buf, "%s: converged in fewer than %d iterations", c.fit.c_str(), c.cap);
    return buf;
}

std::string convergenceWarning(const FitConvergence &c) {
    if (!c.on_cap) return "";
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "the %s fit stopped on its iteration cap (%d) still moving (last step %.1e relative, %.2g px): its "
                  "result is not converged; capture more board poses at different angles",
                  c.fit.c_str(), c.cap, c.last_step, c.last_step_px);
    return buf;
}

CameraCalibration calibrateCameraConverged(const std::vector<std::vector<cv::Point3f>> &board,
                                           const std::vector<std::vector<cv::Point2f>> &image, cv::Size size,
                                           int flags, const LmCriteria &criteria, const std::string &name) {
    const std::function<CameraCalibration(int)> run = [&](int cap) {
        CameraCalibration r;
        cv::Mat extrinsic_sigma, per_view;
        r.rms_px = cv::calibrateCamera(board, image, size, r.camera_matrix, r.distortion, r.rvecs, r.tvecs, r.sigma,
                                       extrinsic_sigma, per_view, flags, criteria.term(cap));
        return r;
    };
    const std::function<std::vector<double>(const CameraCalibration &)> params = [](const CameraCalibration &r) {
        const cv::Mat k = r.camera_matrix;
        std::vector<double> p{k.at<double>(0, 0), k.at<double>(1, 1), k.at<double>(0, 2), k.at<double>(1, 2)};
        append(p, r.distortion);
        for (const auto &v : r.rvecs) append(p, v);
        for (const auto &v : r.tvecs) append(p, v);
        return p;
    };
    FitConvergence c;
    c.fit = name;
    CameraCalibration out = converge(run, params, 4, criteria, c);
    out.convergence = c;
    return out;
}

StereoCalibration stereoCalibrateConverged(const std::vector<std::vector<cv::Point3f>> &board,
                                           const std::vector<std::vector<cv::Point2f>> &first,
                                           const std::vector<std::vector<cv::Point2f>> &second,
                                           const cv::Mat &k1, const cv::Mat &d1, const cv::Mat &k2, const cv::Mat &d2,
                                           cv::Size size, int flags, const LmCriteria &criteria) {
    const std::function<StereoCalibration(int)> run = [&](int cap) {
        StereoCalibration r;
        cv::Mat a = k1.clone(), da = d1.clone(), b = k2.clone(), db = d2.clone(), e, f;
        r.rms_px = cv::stereoCalibrate(board, first, second, a, da, b, db, size, r.rotation, r.translation, e, f,
                                       flags, criteria.term(cap));
        return r;
    };
    const std::function<std::vector<double>(const StereoCalibration &)> params = [](const StereoCalibration &r) {
        cv::Mat rv;
        cv::Rodrigues(r.rotation, rv);
        std::vector<double> p;
        append(p, rv);
        append(p, r.translation);
        return p;
    };
    FitConvergence c;
    c.fit = "stereo";
    StereoCalibration out = converge(run, params, 0, criteria, c);
    out.convergence = c;
    return out;
}

}  // namespace projsurf
