#pragma once
// Fits the full projector model (intrinsics, distortion, rotation, origin) to 3-D points in the
// camera frame and the framebuffer pixels that lit them (structured light lifted through the
// registered depth). Linear start (DLT, RQ decomposition), then Levenberg-Marquardt on the
// reprojection error with Huber weights (IRLS) and a final trimming of gross outliers.
// Distortion is fitted only as far as the data's coverage of the framebuffer constrains it.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "projsurf/types/projector.hpp"

namespace projsurf {

struct ProjectorCorrespondence {
    Eigen::Vector3d point;  ///< camera frame, m
    Eigen::Vector2d pixel;  ///< framebuffer px (centres at integers)
};

struct ProjectorFitConfig {
    int width = 1280, height = 800;  ///< framebuffer, px
    std::size_t min_points = 2000;   ///< fewer decoded pixels cannot be trusted
    std::size_t max_points = 40000;  ///< subsampled (evenly) beyond this, for speed
    double huber_px = 1.5;           ///< Huber threshold, px (decoding quantises to ~1-2 px)
    double trim_px = 6.0;            ///< after the robust fit, points beyond this are dropped and the fit repeated
    double min_relief_m = 0.02;      ///< RMS distance of the points from their best plane below this: flat
    double coverage_k1 = 0.35;       ///< share of the framebuffer (16 x 10 cells) with points to fit k1
    double coverage_k2 = 0.65;       ///< ... to fit k2 as well
};

struct ProjectorFit {
    bool ok = false;
    std::string problem;            ///< why not (what to capture instead)
    Projector projector;            ///< the full model
    double rms_px = 0, max_px = 0;  ///< reprojection residuals of the inliers, framebuffer px
    std::size_t points = 0, inliers = 0;
    double coverage = 0;       ///< share of framebuffer cells with points
    double relief_m = 0;       ///< RMS distance of the points from their best plane
    int distortion_terms = 0;  ///< 0, 1 (k1) or 2 (k1, k2)
};

ProjectorFit fitProjector(const std::vector<ProjectorCorrespondence> &pairs, const ProjectorFitConfig &config = {});

}  // namespace projsurf
