#pragma once
// Projection surface detection (paper section 3.2): from a cloud to the biggest upright
// rectangle of a given aspect ratio that the projector can light on a vertical surface.
#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/core/cloud.hpp"
#include "projsurf/core/plane.hpp"
#include "projsurf/core/plane_frame.hpp"
#include "projsurf/core/projector.hpp"
#include "projsurf/core/surface_check.hpp"

namespace projsurf {

enum class Method {
    Default,  ///< every vertical plane, observed free space, gravity-upright, relative check
    Paper,    ///< the paper's steps, one by one (for reproduction)
};
enum class HullKind { Concave, Convex };

struct DetectorConfig {
    Method method = Method::Default;
    HullKind hull = HullKind::Concave;  ///< paper mode: hull of the inliers (paper 4.1 keeps concave)
    double aspect = 0.0;                ///< picture width / height; 0 = the projector framebuffer's
    Eigen::Vector3d gravity{0.0, 1.0, 0.0};  ///< camera frame (contract: level camera)
    double max_tilt = 0.1;              ///< rad, normal vs horizontal (paper 3.2.1)
    unsigned seed = 42;                 ///< RANSAC random seed (runs are deterministic)

    // --- paper mode (section 3.2) ---
    double voxel_leaf = 0.05;           ///< m, voxel-grid side (paper 3.2.1)
    double ransac_distance = 0.05;      ///< m, inlier band; not given in the paper, = voxel side
    int ransac_iterations = 1000;       ///< PCL SACSegmentation's default max iterations
    double concave_alpha = 0.1;         ///< m, alpha of the concave hull (2 voxels)
    double paper_cell = 0.02;           ///< m, raster cell of the free-space matrices
    double outlier_distance = 0.05;     ///< m, |z - mean z| above this is an outlier (paper 3.2.3)
    int max_outliers = 5000;            ///< more outliers reject the surface (paper 4.3)

    // --- default mode ---
    int target_samples = 12000;         ///< points kept for plane search (stride / voxel), measured
    int max_planes = 4;                 ///< vertical planes tried, biggest first
    int min_plane_points = 150;         ///< sampled inliers for a plane to count
    double plane_noise = 1.425e-3;      ///< 1/m, sigma_z = k z^2 (Khoshelham & Oude Elberink 2012)
    double plane_sigmas = 3.0;          ///< inlier band in sigmas of the depth noise
    double min_band = 0.01;             ///< m, inlier band floor (flat posters stay inliers)
    double max_band = 0.06;             ///< m, inlier band ceiling
    double obstacle_bands = 2.0;        ///< off the plane by more than this many inlier bands = obstacle or hole
    double min_obstacle = 0.03;         ///< m, ... and by at least this much (paper 3.2.3 uses 0.05)
    double cell = 0.01;                 ///< m, free-space raster cell (area error < 0.05 m^2 at 3 m, measured)
    int support_stride = 2;             ///< pixel step of the free-space pass on organized clouds (3 lost 7% of the area behind a person)
    double max_outlier_fraction = 0.03; ///< share of checked points off the plane that rejects a rectangle

    DepthTolerance tolerance() const {
        return {plane_noise, plane_sigmas, min_band, max_band, obstacle_bands, min_obstacle};
    }
};

/// Per-candidate and intermediate results, for overlays and diagnostics.
struct DetectionDebug {
    std::vector<int> inliers;                        ///< indices into the input cloud (sampled)
    std::vector<std::vector<Eigen::Vector3d>> hull;  ///< hull / free-space outlines on the plane
    std::array<Eigen::Vector3d, 4> workspace{};      ///< projector footprint on the plane
    bool has_workspace = false;
    std::vector<int> outliers;                       ///< indices into the input cloud
    std::vector<Plane> candidates;                   ///< vertical planes considered
    PlaneFrame frame;                                ///< frame of the chosen plane
    cv::Mat free_space;                              ///< CV_8U, 255 = free, rows go down from max v
    Eigen::Vector2d grid_origin = Eigen::Vector2d::Zero();  ///< plane coords of the top-left cell corner
    double grid_cell = 0.0;
};

struct Detection {
    bool found = false;
    std::string reason;           ///< why not found (empty when found)
    Plane plane;
    double orientation_deg = 0.0;
    int inliers = 0;
    Rectangle rectangle;
    SurfaceCheckResult surface_check;
    std::map<std::string, double> timing_ms;  ///< "total" and per stage
    DetectionDebug debug;
};

struct DetectorScratch;

/// Runs detection with a fixed projector and configuration over a stream of frames, keeping
/// the largest working buffers (the point grid, the per-plane counts) from one frame to the
/// next.
class SurfaceDetector {
public:
    SurfaceDetector(const Projector &projector, const DetectorConfig &config);
    ~SurfaceDetector();
    SurfaceDetector(SurfaceDetector &&) noexcept;
    SurfaceDetector &operator=(SurfaceDetector &&) noexcept;
    Detection detect(const Cloud &cloud);
    const DetectorConfig &config() const { return config_; }
    const Projector &projector() const { return projector_; }

private:
    Projector projector_;
    DetectorConfig config_;
    std::unique_ptr<DetectorScratch> scratch_;
};

/// One-shot convenience.
Detection detectSurface(const Cloud &cloud, const Projector &projector, const DetectorConfig &config);

}  // namespace projsurf
