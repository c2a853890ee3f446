#include "projsurf/calibration/calibration.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/euler_rodrigues.hpp"
#include "projsurf/calibration/greyscale.hpp"

namespace projsurf {
namespace {

constexpr double kPi = 3.14159265358979323846;

cv::Mat toGrey8(const cv::Mat &image) {
    cv::Mat img = image;
    if (img.depth() == CV_16U)
        img.convertTo(img, CV_8U, 1.0 / 257.0);
    else if (img.depth() != CV_8U)
        img.convertTo(img, CV_8U);
    return greyscale(img);
}

/// Least-squares plane through points (smallest eigenvector of the covariance).
std::optional<Plane> planeThrough(const std::vector<Eigen::Vector3d> &pts, const std::vector<char> &use) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int n = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (use[i]) mean += pts[i], ++n;
    if (n < 3) return std::nullopt;
    mean /= n;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (use[i]) cov += (pts[i] - mean) * (pts[i] - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    if (es.info() != Eigen::Success) return std::nullopt;
    const Eigen::Vector3d ev = es.eigenvalues();
    if (!(ev(1) > 1e-12 * std::max(1.0, ev(2)))) return std::nullopt;  // collinear
    const Eigen::Vector3d normal = es.eigenvectors().col(0);
    return makePlane(normal, -normal.dot(mean));
}

/// The contour's moments place the centre to about 0.2 px (Canny puts the edge on the inner
/// pixel on some sides and the outer one on others). The intensity-weighted centroid of the
/// blob (grey level above the surrounding background, over the contour's interior grown by
/// 2 px so antialiased rim pixels count) is unbiased.
Eigen::Vector2d refineCentroid(const cv::Mat &grey, const std::vector<cv::Point> &contour,
                               const Eigen::Vector2d &fallback) {
    const int pad = 8;
    cv::Rect box = cv::boundingRect(contour);
    box = cv::Rect(box.x - pad, box.y - pad, box.width + 2 * pad, box.height + 2 * pad) &
          cv::Rect(0, 0, grey.cols, grey.rows);
    cv::Mat filled(box.size(), CV_8UC1, cv::Scalar(0));
    std::vector<std::vector<cv::Point>> one{contour};
    cv::drawContours(filled, one, 0, cv::Scalar(255), cv::FILLED, cv::LINE_8, cv::noArray(), 0,
                     cv::Point(-box.x, -box.y));
    cv::Mat inner, outer;
    const cv::Mat k3 = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
    cv::dilate(filled, inner, k3, cv::Point(-1, -1), 2);
    cv::dilate(filled, outer, k3, cv::Point(-1, -1), 5);
    const cv::Mat roi = grey(box);
    const cv::Mat ring = outer & ~inner;
    if (cv::countNonZero(ring) == 0) return fallback;
    const double background = cv::mean(roi, ring)[0];
    double sw = 0, sx = 0, sy = 0;
    for (int y = 0; y < roi.rows; ++y)
        for (int x = 0; x < roi.cols; ++x) {
            if (!inner.at<uchar>(y, x)) continue;
            const double w = std::max(0.0, roi.at<uchar>(y, x) - background);
            sw += w, sx += w * (x + box.x), sy += w * (y + box.y);
        }
    if (!(sw > 0)) return fallback;
    return Eigen::Vector2d(sx / sw, sy / sw);
}

}  // namespace

std::optional<DiscDetection> findDisc(const cv::Mat &image, const DiscConfig &config, int *cut_by_border) {
    if (cut_by_border) *cut_by_border = 0;
    if (image.empty()) return std::nullopt;
    const cv::Mat grey = toGrey8(image);
    cv::Mat binary;  // paper 3.1.1: binarise ...
    cv::threshold(grey, binary, config.threshold, 255, cv::THRESH_BINARY);
    if (config.opening_px > 1) {  // ... open to discard small bright regions ...
        const cv::Mat kernel =
            cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(config.opening_px, config.opening_px));
        cv::morphologyEx(binary, binary, cv::MORPH_OPEN, kernel);
    }
    // ... Canny for the contour (on a black margin, so that a blob cut by the image border
    // still has a closed contour and can be recognised as cut) ...
    cv::Mat padded, edges;
    cv::copyMakeBorder(binary, padded, 2, 2, 2, 2, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::Canny(padded, edges, config.canny_low, config.canny_high);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(edges, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE, cv::Point(-2, -2));

    std::optional<DiscDetection> best;
    int best_index = -1;
    int candidates = 0;
    for (const auto &c : contours) {
        const cv::Moments m = cv::moments(c);  // ... and moments (Green's theorem) for the centroid
        const double area = std::abs(m.m00);
        if (area < config.min_area_px) continue;
        ++candidates;
        const double perimeter = cv::arcLength(c, true);
        const double circularity = perimeter > 0 ? 4.0 * kPi * area / (perimeter * perimeter) : 0.0;
        if (circularity < config.min_circularity) continue;
        const cv::Rect box = cv::boundingRect(c);
        if (box.x < 1 || box.y < 1 || box.x + box.width > grey.cols - 1 || box.y + box.height > grey.rows - 1) {
            if (cut_by_border) ++*cut_by_border;
            continue;
        }
        if (best && best->area_px >= area) continue;
        best_index = static_cast<int>(&c - contours.data());
        DiscDetection d;
        d.centroid = Eigen::Vector2d(m.m10 / m.m00, m.m01 / m.m00);
        d.area_px = area;
        d.radius_px = std::sqrt(area / kPi);
        d.circularity = circularity;
        best = d;
    }
    if (!best) return best;
    best->candidates = candidates;
    best->centroid = refineCentroid(grey, contours[best_index], best->centroid);
    return best;
}

LiftedDisc liftToDepth(const cv::Mat &depth, const CameraIntrinsics &camera, const Eigen::Vector2d &pixel,
                       double radius_px, const LiftConfig &config) {
    LiftedDisc out;
    if (depth.empty() || depth.type() != CV_16UC1) return out;
    const double r = std::max(config.min_region_px, config.region_factor * radius_px);
    const int u0 = std::max(0, static_cast<int>(std::floor(pixel.x() - r)));
    const int u1 = std::min(depth.cols - 1, static_cast<int>(std::ceil(pixel.x() + r)));
    const int v0 = std::max(0, static_cast<int>(std::floor(pixel.y() - r)));
    const int v1 = std::min(depth.rows - 1, static_cast<int>(std::ceil(pixel.y() + r)));
    std::vector<Eigen::Vector3d> pts;
    for (int v = v0; v <= v1; ++v) {
        const auto *row = depth.ptr<std::uint16_t>(v);
        for (int u = u0; u <= u1; ++u) {
            if ((Eigen::Vector2d(u, v) - pixel).squaredNorm() > r * r) continue;
            ++out.region_points;
            if (row[u] == 0) continue;
            const double z = row[u] / camera.depth_scale;
            if (!(z > 0.0 && z < config.max_depth_m)) continue;
            pts.push_back(camera.backProject(u, v, z));
        }
    }
    out.valid_points = static_cast<int>(pts.size());
    if (out.valid_points < config.min_valid_points) return out;

    // Least squares with iterative rejection: keep readings within 3 robust sigmas.
    std::vector<char> use(pts.size(), 1);
    std::optional<Plane> plane;
    std::vector<double> abs_res(pts.size());
    for (int iter = 0; iter < 5; ++iter) {
        plane = planeThrough(pts, use);
        if (!plane) return out;
        for (std::size_t i = 0; i < pts.size(); ++i) abs_res[i] = std::abs(plane->signedDistance(pts[i]));
        std::vector<double> sorted = abs_res;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double sigma = 1.4826 * sorted[sorted.size() / 2];
        const double limit = std::max(3.0 * sigma, 1e-4);  // 0.1 mm floor for noise-free depth
        bool changed = false;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const char keep = abs_res[i] <= limit;
            changed |= keep != use[i];
            use[i] = keep;
        }
        if (!changed) break;
    }
    plane = planeThrough(pts, use);
    if (!plane) return out;
    double ss = 0.0;
    out.inliers = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (!use[i]) continue;
        ++out.inliers;
        ss += std::pow(plane->signedDistance(pts[i]), 2);
    }
    if (out.inliers < config.min_valid_points) return out;
    out.plane_rms_m = std::sqrt(ss / out.inliers);
    const Eigen::Vector3d ray = camera.backProject(pixel.x(), pixel.y(), 1.0).normalized();
    out.point = intersectRay(*plane, Eigen::Vector3d::Zero(), ray);
    return out;
}

std::optional<AxisFit> fitAxisLine(const std::vector<Eigen::Vector3d> &points) {
    if (points.size() < 2) return std::nullopt;
    AxisFit fit;
    for (const auto &p : points) fit.centroid += p;
    fit.centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto &p : points) cov += (p - fit.centroid) * (p - fit.centroid).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    if (es.info() != Eigen::Success) return std::nullopt;
    fit.direction = es.eigenvectors().col(2).normalized();  // largest eigenvalue
    if (fit.direction.z() < 0) fit.direction = -fit.direction;
    if (!(std::abs(fit.direction.z()) > 1e-6)) return std::nullopt;
    fit.origin = axisPointAtZeroZ(fit.centroid, fit.direction);
    double lo = 0.0, hi = 0.0, ss = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d q = points[i] - fit.centroid;
        const double along = q.dot(fit.direction);
        lo = i == 0 ? along : std::min(lo, along);
        hi = i == 0 ? along : std::max(hi, along);
        const double r = (q - along * fit.direction).norm();
        fit.residuals_m.push_back(r);
        ss += r * r;
        fit.max_m = std::max(fit.max_m, r);
    }
    fit.rms_m = std::sqrt(ss / points.size());
    fit.spread_m = hi - lo;
    return fit;
}

double angleBetweenDeg(const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
    const double c = std::abs(a.normalized().dot(b.normalized()));
    return std::acos(std::min(1.0, c)) * 180.0 / kPi;
}

Calibration calibrateProjector(const std::vector<CaptureImages> &captures, const CameraIntrinsics &camera,
                               const CalibrationConfig &config) {
    Calibration cal;
    auto fail = [&](CalibrationFailure f, int k, std::string msg) {
        cal.failure = f;
        cal.failed_capture = k;
        cal.message = std::move(msg);
        return cal;
    };
    const int n = static_cast<int>(captures.size());
    if (n < config.min_captures)
        return fail(CalibrationFailure::TooFewCaptures, -1,
                    "found " + std::to_string(n) + " capture(s), need at least " + std::to_string(config.min_captures) +
                        " taken at different distances from the wall");

    std::vector<Eigen::Vector3d> centroids;
    for (int k = 0; k < n; ++k) {
        const CaptureImages &c = captures[k];
        if (c.color.size() != c.depth.size() || c.depth.cols != camera.width || c.depth.rows != camera.height ||
            c.depth.type() != CV_16UC1)
            return fail(CalibrationFailure::SizeMismatch, k,
                        "colour and depth must both be " + std::to_string(camera.width) + "x" +
                            std::to_string(camera.height) + " (camera.yaml), depth 16-bit single-channel");
        CaptureResult r;
        int cut = 0;
        const auto disc = findDisc(c.color, config.disc, &cut);
        if (!disc && cut > 0)
            return fail(CalibrationFailure::NoDisc, k,
                        "the disc is cut by the image border: take the capture with the whole disc in view");
        if (!disc)
            return fail(CalibrationFailure::NoDisc, k,
                        "no projected disc found (threshold " + std::to_string(config.disc.threshold) +
                            "; a lower threshold finds a dimmer disc; check the calibration picture was projected)");
        r.disc = *disc;
        r.lifted = liftToDepth(c.depth, camera, disc->centroid, disc->radius_px, config.lift);
        if (!r.lifted.point)
            return fail(CalibrationFailure::NoDepth, k,
                        "depth missing at the disc (" + std::to_string(r.lifted.valid_points) + " valid readings of " +
                            std::to_string(r.lifted.region_points) + " pixels around (" +
                            std::to_string(static_cast<int>(std::lround(disc->centroid.x()))) + ", " +
                            std::to_string(static_cast<int>(std::lround(disc->centroid.y()))) + "), need " +
                            std::to_string(config.lift.min_valid_points) + ")");
        centroids.push_back(*r.lifted.point);
        cal.captures.push_back(r);
    }

    const auto fit = fitAxisLine(centroids);
    const std::string redo = "captures do not constrain a line: take them at different distances from the wall";
    if (!fit) return fail(CalibrationFailure::Degenerate, -1, redo);
    if (fit->spread_m < config.min_spread_m) {
        char buf[160];
        std::snprintf(buf, sizeof buf, " (the disc centres span %.3f m along the fitted axis, need %.2f m)",
                      fit->spread_m, config.min_spread_m);
        return fail(CalibrationFailure::Degenerate, -1, redo + buf);
    }
    const double tilt = angleBetweenDeg(fit->direction, Eigen::Vector3d::UnitZ());
    if (tilt > 60.0) {  // a projector on a robot looks forward, not sideways
        char buf[160];
        std::snprintf(buf, sizeof buf, " (the fitted axis is %.1f deg from the camera's z axis)", tilt);
        return fail(CalibrationFailure::Degenerate, -1, redo + buf);
    }
    cal.axis = *fit;
    for (int k = 0; k < n; ++k) cal.captures[k].residual_m = fit->residuals_m[k];

    cal.projector.width = config.width;
    cal.projector.height = config.height;
    cal.projector.fov_h = config.fov_h;
    cal.projector.fov_v = config.fov_v;
    cal.projector.origin = fit->origin;  // (A.1)
    cal.projector.direction = fit->direction;
    if (!isValidProjector(cal.projector))
        return fail(CalibrationFailure::Degenerate, -1, "the fitted axis is (nearly) vertical: " + redo);
    cal.paper_rays = paperCornerRays(fit->direction, config.fov_h, config.fov_v);  // Appendix steps 1-4
    cal.pinhole_rays = cal.projector.cornerRays();
    return cal;
}

}  // namespace projsurf
