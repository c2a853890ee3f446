#pragma once
// OpenCV's calibrations run to convergence, and how many Levenberg-Marquardt iterations that
// took. cv::calibrateCamera and cv::stereoCalibrate stop, without explicit criteria, after 30
// iterations (calibrateCamera) or at a relative step of 1e-6 (stereoCalibrate): on a projector
// seen on a few board poses that is an unconverged iterate (procam-calibration's sample_data:
// cy still moves 60 px between iterations 20 and 30). Here every call has explicit criteria
// (COUNT + EPS, a cap, eps = DBL_EPSILON: only a step too small to change a double stops it).
//
// OpenCV does not return the iterations it used. Its solver (CvLevMarq, 4.x) is deterministic
// and a run capped at k iterations returns its k-th iterate, so: the run at the full cap is the
// result; the smallest cap whose result is bit-identical to it (bisection, about log2(cap)
// more runs) is the number of iterations after which the parameters stopped changing; one run
// at one iteration fewer gives the last step. When that number is the cap, the fit stopped on
// its cap, still moving by the last step: the caller warns.
#include <cfloat>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace projsurf {

struct LmCriteria {
    int max_iterations = 1000;    ///< OpenCV caps its solver at 1000
    double epsilon = DBL_EPSILON;  ///< relative L2 step below which the solver stops
    /// Count the iterations (bisection, ~11 more runs); false: one more run at cap - 1 only
    /// tells whether the fit stopped on its cap (iterations then is the cap or 0 = "fewer").
    bool count = true;
    cv::TermCriteria term(int cap) const {
        return cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, cap, epsilon);
    }
};

/// How one iterative fit ended.
struct FitConvergence {
    std::string fit;         ///< what was fitted ("camera", "projector", "stereo", ...)
    int iterations = 0;      ///< after which the parameters no longer changed (0: not counted, fewer than the cap)
    int cap = 0;             ///< the iteration cap
    double last_step = 0;    ///< relative L2 change of the reported parameters in the last iteration
    double last_step_px = 0; ///< largest change of a focal length or principal point in it, px (stereo: 0)
    bool on_cap = false;     ///< stopped on its cap: the parameters were still changing
};

/// One line: "projector: 137 iterations (cap 1000), last step 1.2e-17" or the warning's words.
std::string describeConvergence(const FitConvergence &c);
/// "" when it converged, else a one-line warning (no prefix, no newline).
std::string convergenceWarning(const FitConvergence &c);

struct CameraCalibration {
    double rms_px = 0;
    cv::Mat camera_matrix, distortion;
    cv::Mat sigma;  ///< standard deviations of the intrinsics (OpenCV's order: fx fy cx cy k1 k2 p1 p2 k3 ...)
    std::vector<cv::Mat> rvecs, tvecs;
    FitConvergence convergence;
};

/// cv::calibrateCamera (no intrinsic guess) run to convergence.
CameraCalibration calibrateCameraConverged(const std::vector<std::vector<cv::Point3f>> &board,
                                           const std::vector<std::vector<cv::Point2f>> &image, cv::Size size,
                                           int flags, const LmCriteria &criteria, const std::string &name);

struct StereoCalibration {
    double rms_px = 0;
    cv::Mat rotation, translation;  ///< second device from first
    FitConvergence convergence;
};

/// cv::stereoCalibrate with the intrinsics as given (`flags` normally CALIB_FIX_INTRINSIC) run to
/// convergence; the matrices are not changed.
StereoCalibration stereoCalibrateConverged(const std::vector<std::vector<cv::Point3f>> &board,
                                           const std::vector<std::vector<cv::Point2f>> &first,
                                           const std::vector<std::vector<cv::Point2f>> &second,
                                           const cv::Mat &k1, const cv::Mat &d1, const cv::Mat &k2, const cv::Mat &d2,
                                           cv::Size size, int flags, const LmCriteria &criteria);

}  // namespace projsurf
