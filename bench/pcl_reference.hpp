#pragma once
// The paper's detection steps (section 3.2) built from stock PCL parts, as a timing and
// sanity reference for the benchmarks. Not used by the library or the CLI.
//
//   3.2.1  pcl::VoxelGrid (leaf 0.05 m)
//          pcl::SACSegmentation, SACMODEL_PARALLEL_PLANE, axis = gravity, eps 0.1 rad
//   3.2.2  pcl::ExtractIndices + pcl::ProjectInliers (inliers onto the plane)
//          pcl::ConcaveHull (alpha 0.1 m)   [pcl::ConvexHull timed as the alternative]
//          corner rays of the projector intersected with the plane (eq. 5-6),
//          both outlines rasterised (cv::fillPoly = Bresenham + row scan), M3 = M1 + M2,
//          biggest free rectangle of the aspect ratio (projsurf::largestAspectRect, the same
//          code the library uses: PCL has no such part)
//   3.2.3  pcl::transformPointCloud into the plane frame + pcl::CropBox (the rectangle),
//          outliers: (z - mean z)^2 > 0.05^2, reject above 5000 (paper 4.3)
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::bench {

using PclCloud = pcl::PointCloud<pcl::PointXYZ>;

struct StockConfig {
    double voxel_leaf = 0.05;                ///< m, paper 3.2.1
    double eps_angle = 0.1;                  ///< rad, normal off horizontal, paper 3.2.1
    double distance = 0.05;                  ///< m, RANSAC inlier band (paper gives none; = voxel side)
    int max_iterations = 1000;               ///< SACSegmentation's default
    double alpha = 0.1;                      ///< m, ConcaveHull alpha (2 voxels)
    double cell = 0.02;                      ///< m, raster cell of M1/M2
    double outlier_distance = 0.05;          ///< m, paper 3.2.3
    int max_outliers = 5000;                 ///< paper 4.3
    double aspect = 0.0;                     ///< width / height; 0 = the projector framebuffer's
    Eigen::Vector3d gravity{0.0, 1.0, 0.0};  ///< camera frame
    bool convex_too = true;                  ///< also time pcl::ConvexHull (not counted in "total")
};

/// Stage names in pipeline order; "convex_hull" is the paper's alternative hull and is
/// not part of "total".
const std::vector<std::string> &stockStageNames();

struct StockResult {
    bool found = false;
    std::string reason;
    Plane plane;
    int inliers = 0;
    Rectangle rectangle;
    int check_points = 0;
    int outliers = 0;
    bool accepted = false;
    /// (stage, ms) in pipeline order, then ("total", ms).
    std::vector<std::pair<std::string, double>> timing_ms;
};

/// Organized PCL copy of a projsurf cloud (NaNs kept, is_dense = false). Not timed.
PclCloud::Ptr toPcl(const Cloud &cloud);

// --- the stages, one call each (the Google Benchmark file times them one by one) --------
PclCloud::Ptr voxelGrid(const PclCloud::ConstPtr &cloud, double leaf);
/// Coefficients a, b, c, d (unit normal) and inlier indices; empty indices when none.
struct SacPlane {
    Eigen::Vector4d coefficients = Eigen::Vector4d::Zero();
    std::vector<int> inliers;
};
SacPlane segmentVerticalPlane(const PclCloud::ConstPtr &cloud, const StockConfig &config);
PclCloud::Ptr extractAndProject(const PclCloud::ConstPtr &cloud, const SacPlane &plane);
/// Outline loops of the plane's points (3-D, on the plane).
std::vector<std::vector<Eigen::Vector3d>> concaveHull(const PclCloud::ConstPtr &projected, double alpha);
std::vector<std::vector<Eigen::Vector3d>> convexHull(const PclCloud::ConstPtr &projected);

/// M3 of the paper: cells (CV_8U, 255 = free) inside both the hull and the projector
/// workspace. Rows go down from v_max.
struct FreeRaster {
    cv::Mat free;
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< plane (u_min, v_max) of cell (0,0)'s corner
    double cell = 0.0;
    Eigen::Vector2d prefer = Eigen::Vector2d::Zero();  ///< workspace centre, cell coordinates
    bool ok = false;
};
FreeRaster rasterFreeSpace(const PlaneFrame &frame, const std::vector<std::vector<Eigen::Vector3d>> &hull,
                           const Projector &projector, double cell);

struct CheckCounts {
    int points = 0;
    int outliers = 0;
};
/// Rotates the original cloud into the plane frame and crops it to the rectangle.
PclCloud::Ptr cropToRectangle(const PclCloud::ConstPtr &cloud, const PlaneFrame &frame, const Rectangle &rect);
CheckCounts countOutliers(const PclCloud &cropped, double outlier_distance);

class StockPipeline {
public:
    StockPipeline(const Projector &projector, const StockConfig &config);
    StockResult run(const PclCloud::ConstPtr &cloud) const;

private:
    Projector projector_;
    StockConfig config_;
};

}  // namespace projsurf::bench
