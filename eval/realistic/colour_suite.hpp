#pragma once
// The colour suite: walls that are free by depth but carry things a picture must
// not land on (flat framed pictures, a calendar, a busy poster, a flat TV, a bright window
// pane, a dark panel; all 5 mm proud, so free by the depth truth), and plain walls of room
// paints. Depth through the realistic Kinect v1 model, registered colour rendered at the same
// intrinsics under room light with camera noise. Scored per round: the share of the detected
// rectangle on unfit things, its area against the largest rectangle on fit wall (the depth
// cells of the detector with suitability off, without the unfit things), and on plain walls its area against
// --suitability off. Knows nothing of files.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "projsurf/detector/detector.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace projsurf::eval {

struct ColourCase {
    std::string scene;      ///< colourSceneNames()
    double distance = 2.5;  ///< m
    double angle_deg = 0.0;
};
/// The scene names: pictures, calendar_poster, tv_flat, window_pane, dark_panel, mixed,
/// and plain_<paint> for white, beige, pale_blue, sage, terracotta, grey.
const std::vector<std::string> &colourSceneNames();
const std::vector<ColourCase> &colourSuiteCases();

/// A colour scene: the scenario and where the unfit things are on its main wall (s0, s1, h0,
/// h1 in the WallFrame's coordinates: m along the wall from the axis point, m above the floor).
struct ColourScene {
    sim::Scenario scenario;
    std::vector<std::array<double, 4>> unfit;
    bool plain = false;  ///< a plain painted wall (nothing unfit)
};
/// Throws std::invalid_argument for an unknown name.
ColourScene makeColourScene(const std::string &name, double distance, double angle_deg);

struct ColourSuiteOptions {
    int rounds = 10;  ///< per scene (every round)
    unsigned seed = 1;
    double truth_cell = 0.01;  ///< m, as the eval
    double ambient =
        0.8;  ///< room light, fraction of white (a lit room; the sim's default 0.15 is the calibration's dim room)
    double rgb_noise = 2.0;  ///< colour noise, 8-bit levels (sigma)
    std::vector<ColourCase> cases = colourSuiteCases();
};
ColourSuiteOptions quickColourSuite();  ///< 2 rounds

struct ColourRow {
    ColourCase scene;
    bool plain = false;
    int rounds = 0, found = 0;
    double max_unfit_pct = 0.0;  ///< worst round: % of the rectangle on unfit things
    double depth_best = 0.0;     ///< m^2, the depth ground truth's best rectangle (unfit things count as free)
    double suitable_best = 0.0;  ///< m^2, mean over rounds: the largest rectangle on the detector's free cells (off)
                                 ///< without the unfit things
    double min_area_pct = 0.0;   ///< worst round: area / suitable_best, %
    double mean_area = 0.0;      ///< m^2, with suitability (avoid)
    double mean_area_off = 0.0;  ///< m^2, --suitability off
    double max_off_unfit_pct = 0.0;  ///< worst round with suitability off: % on unfit things
    double worst_plain_pct = 0.0;    ///< plain walls: largest |area / area off - 1|, %
    double suitability_ms = 0.0;     ///< median of the detector's "suitability" stage
    bool ok() const;                 ///< the issue's targets hold for this scene
};

struct ColourSuiteResult {
    std::vector<ColourRow> rows;
    int rounds = 0;
    double seconds = 0.0;
};

/// Runs the suite: each round detects with `config` (mode avoid, unless it says prefer) and
/// with suitability off.
ColourSuiteResult runColourSuite(const ColourSuiteOptions &options, const DetectorConfig &config = {},
                                 const std::function<void(int, int, const std::string &)> &progress = nullptr);

std::string colourSuiteMarkdown(const ColourSuiteResult &result);
std::string colourSuiteSummary(const ColourSuiteResult &result);  ///< one line

}  // namespace projsurf::eval
