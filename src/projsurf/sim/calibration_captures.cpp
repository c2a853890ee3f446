#include "projsurf/sim/calibration_captures.hpp"

#include <stdexcept>

#include "projsurf/sim/scenarios.hpp"

namespace projsurf::sim {

std::vector<RgbdFrame> renderCalibrationCaptures(const Projector &projector, const SensorModel &sensor, int count,
                                                 unsigned seed, double roll_deg, double pitch_deg) {
    if (count < 1) throw std::invalid_argument("calibration captures: count must be at least 1");
    const cv::Mat disc = calibrationPicture(projector.width, projector.height);
    const double angles[] = {0.0, 10.0, -10.0, 20.0, -20.0};  // deg, robot turned a little
    std::vector<RgbdFrame> frames;
    frames.reserve(count);
    for (int k = 0; k < count; ++k) {
        const double d = count > 1 ? 1.2 + 1.8 * k / (count - 1) : 1.2;  // m, 1.2-3.0 m
        Scenario wall = makeScenario("wall", d, angles[k % 5]);
        if (pitch_deg != 0.0) pitchCamera(wall, pitch_deg);
        if (roll_deg != 0.0) rollCamera(wall, roll_deg);
        frames.push_back(renderFrame(wall.scene, sensor, seed + 1000u + static_cast<unsigned>(k),
                                     Projection{projector, disc}));
    }
    return frames;
}

std::vector<CaptureImages> captureImages(const std::vector<RgbdFrame> &frames) {
    std::vector<CaptureImages> out;
    out.reserve(frames.size());
    for (const auto &f : frames) out.push_back(CaptureImages{f.rgb, f.depth});
    return out;
}

}  // namespace projsurf::sim
