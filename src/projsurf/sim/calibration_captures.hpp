#pragma once
// Simulated calibration captures (paper 3.1.1): the calibration picture (black, one white disc)
// projected on a plain wall from several robot positions, as the RGB-D camera sees it.
#include <string>
#include <vector>

#include "projsurf/calibration/calibration.hpp"
#include "projsurf/types/projector.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/sensor_model.hpp"

namespace projsurf::sim {

/// `count` captures of the plain "wall" scenario with the disc projected by `projector`:
/// capture k is taken from 1.2 m (k = 0) to 3.0 m (k = count - 1), evenly spaced, turned by
/// 0, 10, -10, 20, -20 degrees (repeating), the camera pitched by `pitch_deg` then rolled by
/// `roll_deg` (pitchCamera, rollCamera); noise seed seed + 1000 + k. Throws
/// std::invalid_argument for count < 1.
std::vector<RgbdFrame> renderCalibrationCaptures(const Projector &projector, const SensorModel &sensor, int count,
                                                 unsigned seed, double roll_deg = 0.0, double pitch_deg = 0.0);

/// One robot position for structured-light captures: a scenario, pitched and rolled.
struct PatternPose {
    std::string scenario = "wall";
    double distance = 2.0, angle_deg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;
};
/// How the colour camera sees the patterns (on top of renderFrame's ambient light and albedo).
struct PatternCameraModel {
    double ambient = 0.25;       ///< room light, fraction of white
    double noise_sigma = 2.0;    ///< colour noise, grey levels (8-bit)
    double blur_sigma_px = 0.7;  ///< optics + projector defocus, camera px
};
/// What the user captures at one position: depth (registered) and one colour image per
/// pattern of grayPatterns(projector.width, projector.height), same order.
struct PatternCapture {
    cv::Mat depth;
    std::vector<cv::Mat> colour;
};
/// Renders the pattern captures of each pose (noise seed seed + 100 k + pattern index).
std::vector<PatternCapture> renderPatternCaptures(const Projector &projector, const SensorModel &sensor,
                                                  const std::vector<PatternPose> &poses, unsigned seed,
                                                  const PatternCameraModel &model = {});
/// The colour and depth images of rendered captures, as calibrateProjector takes them.
std::vector<CaptureImages> captureImages(const std::vector<RgbdFrame> &frames);

}  // namespace projsurf::sim
