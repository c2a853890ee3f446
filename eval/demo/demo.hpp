#pragma once
// The demo, end to end and from nothing (no files): a simulated robot calibrates its projector
// from simulated captures (paper 3.1), looks at a scene, detects where to project (3.2),
// corrects a picture (3.3), and shows it on the wall; and what an audience facing the wall
// sees with and without the correction (the paper's Fig 1). The CLI writes the files.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "eval/paper/experiments.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

struct DemoOptions {
    std::string scenario = "wall";
    double distance = 2.0;     ///< m
    double angle_deg = 17.19;  ///< one of the paper's angles (4.1)
    unsigned seed = 1;
    int captures = 5;                  ///< calibration captures (paper 3.1.1: 5 positions)
    cv::Mat picture;                   ///< BGR; empty = the test card at the projector's resolution
    DetectorConfig config;             ///< default method; the seed is set from the scene
    cv::Size audience_size{960, 600};  ///< px of each audience view
    double audience_hfov_deg = 50.0;   ///< horizontal field of view of the audience view
};

struct DemoResult {
    sim::Scenario scenario;
    Projector true_projector;    ///< the simulated robot's real projector
    CalibrationRun calibration;  ///< the projector as calibrated from simulated captures
    sim::RgbdFrame frame;        ///< what the RGB-D camera saw
    sim::GroundTruth truth;
    DetectorConfig config;
    Detection detection;  ///< with the calibrated projector
    Score score;          ///< against ground truth
    cv::Mat picture;
    std::optional<Keystone> keystone;
    std::string keystone_problem;
    cv::Mat framebuffer;              ///< the corrected framebuffer (black when nothing was found)
    WallPicture corrected_on_wall;    ///< the corrected picture's corners on the real wall (eq. 8)
    WallPicture uncorrected_on_wall;  ///< the whole framebuffer's corners on the real wall (eq. 8)
    cv::Mat audience_uncorrected;     ///< the picture projected as is (keystoned)
    cv::Mat audience_corrected;       ///< the corrected framebuffer projected
    sim::PinholeView audience_view;   ///< where the audience views are seen from
    sim::Lighting audience_light;
    std::vector<std::pair<std::string, double>> stage_ms;  ///< in order
};

/// Runs the demo; throws std::invalid_argument for an unknown scenario or impossible pose.
DemoResult runDemo(const DemoOptions &options);

}  // namespace projsurf::eval
