#pragma once
// Projector calibration as in the paper (section 3.1 and Appendix): find the projected disc in
// each colour capture, lift its centroid to 3-D with the registered depth, fit the projector's
// central axis through the centroids, and derive the lens origin (A.1) and corner rays.
// Knows nothing of files: the front end names the files when a capture is refused.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct DiscConfig {
    int threshold = 50;       ///< grey level (0-255) of the binarisation; paper 3.1.1
    int opening_px = 5;       ///< side of the elliptic opening kernel, px (removes specks)
    double canny_low = 50.0;  ///< Canny hysteresis thresholds on the binary image
    double canny_high = 150.0;
    double min_area_px = 30.0;     ///< smallest disc accepted, px^2 (a 3 px radius)
    double min_circularity = 0.5;  ///< 4 pi A / P^2; an ellipse of axis ratio 0.3 still passes
};

/// The projected disc found in one colour image.
struct DiscDetection {
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  ///< image pixel (centres at integers)
    double area_px = 0.0;                                ///< area enclosed by the disc's contour, px^2
    double radius_px = 0.0;                              ///< sqrt(area / pi)
    double circularity = 0.0;                            ///< 4 pi A / P^2, 1 for a perfect circle
    int candidates = 0;                                  ///< bright blobs seen (1 for a clean capture)
};

/// Paper 3.1.1: binary threshold, morphological opening, Canny, contours, moments. Picks the
/// largest sufficiently round blob; its centre is the intensity-weighted centroid of the grey
/// image over the blob (the paper's "weighted average of the pixel intensities"), which is
/// sub-pixel accurate where the contour's moments are biased by ~0.2 px. nullopt when there is
/// no disc. Accepts 8-bit (or 16-bit) grey, BGR or BGRA images.
/// Blobs that touch the image border are skipped (their centroid would be off the disc's
/// centre); `cut_by_border`, when given, receives how many round enough blobs that were.
std::optional<DiscDetection> findDisc(const cv::Mat &image, const DiscConfig &config = {},
                                      int *cut_by_border = nullptr);

struct LiftConfig {
    double region_factor = 2.0;  ///< depth is sampled within this many disc radii of the centroid
    double min_region_px = 8.0;  ///< ... but at least this radius, px
    int min_valid_points = 30;   ///< fewer valid depth readings there: refuse
    double max_depth_m = 10.0;   ///< readings beyond this are ignored (sensor garbage)
};

/// The disc centroid in 3-D.
struct LiftedDisc {
    std::optional<Eigen::Vector3d> point;  ///< camera frame, m; nullopt when depth is missing
    int valid_points = 0;                  ///< valid depth readings in the sampled region
    int region_points = 0;                 ///< pixels in the sampled region
    int inliers = 0;                       ///< readings kept by the robust local plane fit
    double plane_rms_m = 0.0;              ///< rms distance of the inliers to that plane
};

/// Lifts an image point to 3-D with a registered 16-bit depth image (units per metre in
/// `camera.depth_scale`, 0 = no reading): fits a plane to the valid readings around it by least
/// squares with iterative outlier rejection and intersects the camera ray through the pixel
/// with it. Robust to holes and noise inside the disc and to oblique walls.
LiftedDisc liftToDepth(const cv::Mat &depth, const CameraIntrinsics &camera, const Eigen::Vector2d &pixel,
                       double radius_px, const LiftConfig &config = {});

/// A 3-D least-squares line (principal axis of the points) and how well it fits.
struct AxisFit {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();    ///< mean of the points
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit, oriented towards +z
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();      ///< the line's point with z = 0 (A.1)
    std::vector<double> residuals_m;                       ///< distance of each point to the line
    double rms_m = 0.0;
    double max_m = 0.0;
    double spread_m = 0.0;  ///< extent of the points along the line
};

/// Least-squares line through the points (smallest orthogonal distances: PCA). nullopt for
/// fewer than 2 points or when the line has no point with z = 0 (direction parallel to it).
std::optional<AxisFit> fitAxisLine(const std::vector<Eigen::Vector3d> &points);

struct CalibrationConfig {
    DiscConfig disc;
    LiftConfig lift;
    int min_captures = 3;       ///< contract: N >= 3
    double min_spread_m = 0.3;  ///< centroids must span at least this along the axis
    int width = 1280;           ///< framebuffer, px (Aaxa P300, the paper's projector)
    int height = 800;
    double fov_h = 39.3 * 3.14159265358979323846 / 180.0;  ///< rad, paper 3.1.2
    double fov_v = 24.0 * 3.14159265358979323846 / 180.0;  ///< rad, paper 3.1.2
};

/// One capture: colour image and registered depth image.
struct CaptureImages {
    cv::Mat color;  ///< 8-bit grey/BGR
    cv::Mat depth;  ///< CV_16UC1, same size
};

/// What the calibration found for one capture.
struct CaptureResult {
    DiscDetection disc;
    LiftedDisc lifted;
    double residual_m = 0.0;  ///< distance of the 3-D centroid to the fitted axis
};

enum class CalibrationFailure {
    None,
    TooFewCaptures,  ///< fewer than config.min_captures
    SizeMismatch,    ///< colour/depth/camera sizes differ (capture)
    NoDisc,          ///< no disc in the colour image (capture)
    NoDepth,         ///< too few depth readings at the disc (capture)
    Degenerate,      ///< the centroids do not constrain a line (all at one distance)
};

struct Calibration {
    CalibrationFailure failure = CalibrationFailure::None;
    int failed_capture = -1;  ///< index of the capture refused, or -1
    std::string message;      ///< what went wrong, for the user (empty on success)
    std::vector<CaptureResult> captures;
    AxisFit axis;
    Projector projector;                          ///< origin = axis.origin, direction = axis.direction
    std::array<Eigen::Vector3d, 4> paper_rays;    ///< Appendix steps 1-4 (Euler-Rodrigues), unit
    std::array<Eigen::Vector3d, 4> pinhole_rays;  ///< through the framebuffer's outer corners, unit
    bool ok() const { return failure == CalibrationFailure::None; }
};

/// The whole calibration (section 3.1): disc per capture, lift, axis fit, lens origin (A.1),
/// corner rays (Appendix). Stops at the first capture that cannot be used.
Calibration calibrateProjector(const std::vector<CaptureImages> &captures, const CameraIntrinsics &camera,
                               const CalibrationConfig &config = {});

/// Angle between two directions, degrees (sign of the directions ignored).
double angleBetweenDeg(const Eigen::Vector3d &a, const Eigen::Vector3d &b);

}  // namespace projsurf
