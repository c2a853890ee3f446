#pragma once
// What a detection found (paper section 3.2's output), and what it looked at on the way.
#include <Eigen/Core>
#include <array>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/detection/candidate_outcome.hpp"
#include "projsurf/detection/surface_check.hpp"
#include "projsurf/detection/wall_height.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// Intermediate results of the plane shown, for overlays and diagnostics.
struct DetectionDebug {
    std::vector<int> inliers;                        ///< indices into the input cloud (sampled)
    std::vector<std::vector<Eigen::Vector3d>> hull;  ///< hull / free-space outlines on the plane
    std::array<Eigen::Vector3d, 4> workspace{};      ///< projector footprint on the plane
    bool has_workspace = false;
    std::vector<int> outliers;                              ///< indices into the input cloud
    std::vector<Plane> candidates;                          ///< vertical planes considered
    PlaneFrame frame;                                       ///< frame of the chosen plane
    cv::Mat free_space;                                     ///< CV_8U, 255 = free, rows go down from max v
    cv::Mat cell_state;                                     ///< CV_8U CellState per cell (default method), else empty
    WallShape wall_shape;                                   ///< how the wall departs from the plane (default method)
    DepthTolerance tolerance;                               ///< the band the wall's points were judged with
    Eigen::Vector2d grid_origin = Eigen::Vector2d::Zero();  ///< plane coords of the top-left cell corner
    double grid_cell = 0.0;
};

/// What the chosen rectangle lies on, by its colour (default method, when colour was used).
struct SuitabilityReport {
    bool used = false;              ///< the cloud had colour and the mode was not off
    std::string mode;               ///< "avoid" or "prefer"
    double mean_albedo = 0.0;       ///< mean luminance of the wall samples in it, share of 255 (uncalibrated albedo)
    double texture = 0.0;           ///< mean luminance contrast (std / mean over 5 cm windows) of its cells
    double unsuitable_share = 0.0;  ///< share of its cells unfit by their colour
    double wall_luminance = 0.0;    ///< median luminance of the wall's samples, share of 255
};

struct Detection {
    bool found = false;
    std::string reason;  ///< why not found (empty when found)
    Plane plane;
    double orientation_deg = 0.0;
    int inliers = 0;
    Rectangle rectangle;
    SurfaceCheckResult surface_check;
    SuitabilityReport suitability;
    Eigen::Vector3d gravity = Eigen::Vector3d::UnitY();  ///< the down direction used (camera frame, unit)
    std::map<std::string, double> timing_ms;             ///< "total" and per stage
    std::vector<CandidateOutcome> candidates;            ///< every plane considered and what became of it
    DetectionDebug debug;
};

}  // namespace projsurf
