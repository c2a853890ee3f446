#pragma once
// Judging a detection against the simulator's ground truth: is the rectangle valid (on a
// real surface, upright, of the asked aspect, lit by the projector, free), and is it as big
// as the best possible one (the paper's 0.05 m^2 criterion, section 4.1)?
#include <string>

#include "projsurf/detector/detector.hpp"
#include "projsurf/sim/ground_truth.hpp"

namespace projsurf::eval {

struct ScoreOptions {
    double area_tolerance = 0.05;     ///< m^2, success when area >= best - this (paper 4.1)
    double plane_tolerance = 0.03;    ///< m, corners at most this far from the true surface
    double upright_tolerance = 0.02;  ///< rad, left edge vs gravity
    double min_free_share = 0.97;     ///< share of the rectangle that must be truly free
    double pixel_tolerance = 2.0;     ///< px, corners inside the framebuffer by this margin
};

struct Score {
    bool found = false;
    bool valid = false;        ///< on a surface, upright, aspect, inside the framebuffer, free
    bool success = false;      ///< valid and within area_tolerance of the best area
    double area = 0.0;         ///< m^2
    double best_area = 0.0;    ///< m^2 (ground truth)
    double area_error = 0.0;   ///< best - area (m^2; 0 when not found: best)
    double plane_error = 0.0;  ///< m, worst corner distance to the surface it is on
    double free_share = 0.0;
    std::string why;  ///< the first failed condition
};

Score scoreDetection(const Detection &detection, const sim::GroundTruth &truth, const Projector &projector,
                     const Eigen::Vector3d &gravity, double aspect, const ScoreOptions &options = {});

}  // namespace projsurf::eval
