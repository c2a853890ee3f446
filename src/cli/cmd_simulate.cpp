// projsurf simulate: render an RGB-D frame of a test scene (paper section 4, the realistic
// scenes, more) through a realistic sensor model (--sensor kinect1 | tof | d435, --unit N) or
// the paper experiments' independent-noise Kinect (--sensor kinect1-independent), optionally
// with a picture projected on it, and write the contract's files plus the ground truth; or the
// calibration captures of the white disc (paper 3.1.1); or the structured-light captures that
// `projsurf patterns` asks a user to take (calibrate --captures reads them).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "cli/calibration_input.hpp"
#include "cli/commands.hpp"
#include "eval/truth_json.hpp"
#include "projsurf/frontend/aspect.hpp"
#include "projsurf/io/cloud_io.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/pattern_files.hpp"
#include "projsurf/io/yaml_files.hpp"
#include "projsurf/sim/calibration_captures.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenarios.hpp"
#include "projsurf/sim/scenarios_realistic.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

/// Framebuffer pixels `simulate --structured-light` renders at most (docs/limits.md).
constexpr std::uint64_t kMaxSimulatedPatternPixels = std::uint64_t{1} << 23;

struct SimulateOptions {
    bool list = false;
    std::string scenario;
    double distance = 2.0;   // m, camera to wall along the optical axis
    double angle_deg = 0.0;  // wall orientation (paper: 27.5, 17.19, -12.06, -26.01, -16.62)
    double roll_deg = 0.0;   // extra camera roll
    double pitch_deg = 0.0;  // camera pitch, positive looking down
    unsigned seed = 0;
    std::string calib;   // default: the contract's example projector
    std::string aspect;  // default: the framebuffer's
    std::string picture;
    bool noise_free = false;
    int captures = 0;
    bool structured_light = false;
    std::string sensor = "kinect1";  // kinect1 | tof | d435 | kinect1-independent
    int unit = 0;                    // sensor unit: its fixed systematic errors
    std::string out;
};

constexpr const char *kIndependent = "kinect1-independent";

sim::Scenario buildScenario(const std::string &name, double distance, double angle_deg, double roll_deg,
                            double pitch_deg) {
    try {
        sim::Scenario s = sim::isRealisticScenario(name) ? sim::makeRealisticScenario(name, distance, angle_deg)
                                                         : sim::makeScenario(name, distance, angle_deg);
        if (pitch_deg != 0.0) sim::pitchCamera(s, pitch_deg);
        if (roll_deg != 0.0) sim::rollCamera(s, roll_deg);
        return s;
    } catch (const std::invalid_argument &e) {
        throw InputError("--scenario", e.what());
    }
}

void writeFrame(const fs::path &dir, const std::string &stem, const sim::RgbdFrame &frame, bool with_cloud) {
    writeImageAtomic((dir / (stem + "depth.png")).string(), frame.depth);
    writeImageAtomic((dir / (stem + "rgb.png")).string(), frame.rgb);
    if (with_cloud) writeCloudPcd((dir / (stem + "cloud.pcd")).string(), frame.cloud);
}

void run(const SimulateOptions &o) {
    if (o.list) {
        for (const auto &name : sim::scenarioNames())
            std::cout << name << "\t" << sim::makeScenario(name, 2.0, 0.0).description << "\n";
        for (const auto &name : sim::realisticScenarioNames())
            std::cout << name << "\t" << sim::makeRealisticScenario(name, 2.0, 0.0).description << "\n";
        return;
    }
    // Arguments and inputs first; nothing is written until everything is rendered.
    if (o.out.empty()) throw InputError("--out", "an output directory is required");
    if (o.scenario.empty() && o.captures == 0 && !o.structured_light)
        throw InputError("--scenario", "required (see --list)");
    if (o.captures != 0 && (o.captures < 3 || o.captures > 50))
        throw InputError("--captures", "must be between 3 and 50 (the contract needs N >= 3)");
    if (!(o.distance >= 0.5 && o.distance <= 10.0)) throw InputError("--distance", "must be between 0.5 and 10 m");
    if (!(std::abs(o.angle_deg) < 75.0)) throw InputError("--angle-deg", "must be within +-75 degrees");
    if (!std::isfinite(o.roll_deg) || std::abs(o.roll_deg) > 45.0)
        throw InputError("--roll-deg", "must be within +-45 degrees");
    if (!std::isfinite(o.pitch_deg) || std::abs(o.pitch_deg) > 30.0)
        throw InputError("--pitch-deg", "must be within +-30 degrees");
    const Projector projector = o.calib.empty() ? sim::exampleProjector() : readCalibrationWarned(o.calib);
    // Each pattern is rendered at the framebuffer's size, for three positions: 16384 x 2048
    // took 40-54 s. 4K UHD (3840 x 2160) fits the bound.
    if (o.structured_light &&
        static_cast<std::uint64_t>(projector.width) * projector.height > kMaxSimulatedPatternPixels)
        throw InputError(o.calib, "--structured-light renders framebuffers of at most " +
                                      std::to_string(kMaxSimulatedPatternPixels) + " pixels; this one is " +
                                      std::to_string(projector.width) + " x " + std::to_string(projector.height));
    const double aspect = o.aspect.empty() ? projector.aspect() : frontend::parseAspect("--aspect", o.aspect);
    std::optional<sim::Projection> projection;
    if (!o.picture.empty()) {
        cv::Mat picture = readImage(o.picture, cv::IMREAD_COLOR);
        if (picture.cols != projector.width || picture.rows != projector.height)  // the projector scales its input
            cv::resize(picture, picture, cv::Size(projector.width, projector.height), 0, 0, cv::INTER_AREA);
        projection = sim::Projection{projector, picture};
    }
    const bool independent = o.sensor == kIndependent;
    const auto kind = sim::parseSensorKind(o.sensor);
    if (!independent && !kind)
        throw InputError("--sensor", "expected kinect1, tof, d435 or kinect1-independent, got '" + o.sensor + "'");
    if (o.unit < 0 || o.unit > 1000000) throw InputError("--unit", "must be between 0 and 1000000");
    const std::optional<sim::DepthSensor> realistic =
        independent || o.noise_free ? std::nullopt
                                    : std::optional<sim::DepthSensor>(sim::makeDepthSensor(*kind, o.unit));
    // The independent model at the chosen sensor's camera and range (exact with --noise-free):
    // the frame when there is no realistic sensor, the ground truth's limits, the captures.
    sim::SensorModel sensor = o.noise_free ? sim::SensorModel::ideal() : sim::SensorModel();
    if (!independent) {
        const sim::SensorModel limits = sim::makeDepthSensor(*kind, o.unit).truthModel();
        sensor.camera = limits.camera;
        sensor.min_depth = limits.min_depth;
        sensor.max_depth = limits.max_depth;
        sensor.grazing_max_deg = limits.grazing_max_deg;
    }
    std::optional<sim::Scenario> scenario;
    if (!o.scenario.empty()) scenario = buildScenario(o.scenario, o.distance, o.angle_deg, o.roll_deg, o.pitch_deg);
    const fs::path out(o.out);
    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_directory(out, ec)) throw InputError(o.out, "exists and is not a directory");
    // The capture folders are read whole (every pose_<k>, every capture_<k>): an earlier run's
    // files left beside the new ones would be read as this run's.
    for (const auto &[wanted, name] : {std::pair<bool, const char *>{o.captures > 0, "captures"},
                                       std::pair<bool, const char *>{o.structured_light, "structured"}})
        if (wanted && fs::exists(out / name, ec) && !fs::is_empty(out / name, ec))
            throw InputError((out / name).string(),
                             "exists and is not empty: an earlier run's captures would stay beside the new ones "
                             "(remove it, or give another --out)");

    // Render.
    std::optional<sim::RgbdFrame> frame;
    sim::GroundTruth truth;
    cv::Mat audience;
    if (scenario) {
        frame = realistic ? sim::renderSensorFrame(scenario->scene, *realistic, o.seed, projection)
                          : sim::renderFrame(scenario->scene, sensor, o.seed, projection);
        sim::TruthOptions topt;
        topt.aspect = aspect;
        truth = sim::computeGroundTruth(scenario->scene, sensor, projector, scenario->gravity, topt);
        if (projection) {
            // The picture as someone facing the wall sees it, 2.5 m in front of where the
            // projector's axis meets the wall (or of the true rectangle's centre).
            const Plane &wall = truth.found ? truth.best.plane : scenario->wall;
            const auto axis_hit = intersectRay(wall, projector.origin, projector.direction.normalized());
            const Eigen::Vector3d target =
                truth.found ? truth.best.rectangle.center() : axis_hit.value_or(Eigen::Vector3d(0.0, 0.0, o.distance));
            audience =
                sim::renderView(scenario->scene, sim::facingView(wall, target, 2.5, scenario->gravity), projection);
        }
    }
    // Calibration captures: a plain wall from N robot positions, 1.2-3.0 m, turned a little.
    std::vector<sim::RgbdFrame> captures;
    if (o.captures > 0)
        captures = sim::renderCalibrationCaptures(projector, sensor, o.captures, o.seed, o.roll_deg, o.pitch_deg);

    // Structured-light captures: the flat wall from three positions (sim/projector_rigs.hpp),
    // each pattern of `projsurf patterns` as the colour camera sees it, and the depth.
    std::vector<sim::PatternCapture> patterns;
    if (o.structured_light) patterns = sim::renderPatternCaptures(projector, sensor, sim::flatWallPoses(), o.seed);

    // Write.
    fs::create_directories(out, ec);
    if (ec) throw InputError(o.out, "cannot create the directory: " + ec.message());
    if (scenario) {
        writeFrame(out, "", *frame, true);
        if (!audience.empty()) writeImageAtomic((out / "audience.png").string(), audience);
        writeCamera((out / "camera.yaml").string(), sensor.camera);
        writeCalibration((out / "calib.yaml").string(), projector);
        eval::writeTruthJson((out / "truth.json").string(), truth, *scenario, o.seed, !o.noise_free);
    }
    if (!captures.empty()) {
        const fs::path dir = out / "captures";
        fs::create_directories(dir, ec);
        if (ec) throw InputError(dir.string(), "cannot create the directory: " + ec.message());
        writeCamera((dir / "camera.yaml").string(), sensor.camera);
        for (std::size_t k = 0; k < captures.size(); ++k)
            writeFrame(dir, "capture_" + std::to_string(k) + "_", captures[k], false);
    }
    if (!patterns.empty()) {
        const fs::path dir = out / "structured";
        const PatternList list = writePatternSet(dir.string(), projector.width, projector.height);
        writeCamera((dir / "camera.yaml").string(), sensor.camera);
        for (std::size_t k = 0; k < patterns.size(); ++k) {
            const fs::path pose = dir / ("pose_" + std::to_string(k));
            fs::create_directories(pose, ec);
            if (ec) throw InputError(pose.string(), "cannot create the directory: " + ec.message());
            writeImageAtomic((pose / "depth.png").string(), patterns[k].depth);
            for (std::size_t i = 0; i < list.names.size() && i < patterns[k].colour.size(); ++i)
                writeImageAtomic((pose / (list.names[i] + ".png")).string(), patterns[k].colour[i]);
        }
    }
    if (!scenario && (!captures.empty() || !patterns.empty()))
        writeCalibration((out / "calib.yaml").string(), projector);  // the truth to compare with
    if (scenario) {
        std::cout << "sensor " << (independent ? std::string(kIndependent) : o.sensor)
                  << (realistic ? " unit " + std::to_string(o.unit) : std::string()) << " (" << sensor.camera.width
                  << "x" << sensor.camera.height << "), ";
        std::cout << "scenario " << scenario->name << " at " << scenario->distance << " m, " << scenario->angle_deg
                  << " deg: ";
        if (truth.found)
            std::cout << "true rectangle on the " << truth.best.label << ", " << truth.best.rectangle.width << " x "
                      << truth.best.rectangle.height << " m\n";
        else
            std::cout << "no free rectangle\n";
    }
    if (!captures.empty())
        std::cout << captures.size() << " calibration captures in " << (out / "captures").string() << "\n";
    if (!patterns.empty())
        std::cout << patterns.size() << " positions of structured-light captures in " << (out / "structured").string()
                  << "; projsurf calibrate --captures " << (out / "structured").string()
                  << " --out calib.yaml fits the projector, to compare with " << (out / "calib.yaml").string() << "\n";
}

}  // namespace

void addSimulateCommand(CLI::App &app) {
    auto opts = std::make_shared<SimulateOptions>();
    auto *sub = app.add_subcommand("simulate", "Render a simulated RGB-D frame of a test scene, with ground truth");
    sub->add_flag("--list", opts->list, "Print the scenario names and exit");
    sub->add_option("--scenario", opts->scenario, "Scene name (see --list)");
    sub->add_option("--distance", opts->distance, "Camera to wall along the optical axis, m (default 2.0)");
    sub->add_option("--angle-deg", opts->angle_deg, "Wall normal vs camera z about the vertical, deg (default 0)");
    sub->add_option("--roll-deg", opts->roll_deg, "Extra camera roll about its optical axis, deg (default 0)");
    sub->add_option("--pitch-deg", opts->pitch_deg, "Camera pitch, positive looking down, deg (default 0)");
    sub->add_option("--seed", opts->seed, "Noise seed (default 0)");
    sub->add_option("--calib", opts->calib, "Projector calibration YAML (default: the contract's example)");
    sub->add_option("--aspect", opts->aspect, "Aspect ratio W:H of the true rectangle (default: the framebuffer's)");
    sub->add_option("--picture", opts->picture,
                    "Image to project (scaled to the framebuffer), shown in rgb.png and audience.png (a frontal view)");
    sub->add_flag("--noise-free", opts->noise_free,
                  "Exact depth at the sensor's camera: no noise, quantisation or random dropouts");
    sub->add_option("--sensor", opts->sensor,
                    "Depth sensor model: kinect1 (default), tof (Kinect v2 class), d435 (RealSense), or "
                    "kinect1-independent (the paper experiments' independent-noise Kinect)");
    sub->add_option("--unit", opts->unit, "Sensor unit: its fixed distortions (default 0)");
    sub->add_option("--captures", opts->captures, "Also write N calibration captures to OUT/captures");
    sub->add_flag("--structured-light", opts->structured_light,
                  "Also write the structured-light captures of --calib's projector (three positions at a plain wall) "
                  "to OUT/structured, for calibrate --captures");
    sub->add_option("--out", opts->out, "Output directory (created if missing)");
    sub->callback([opts] { run(*opts); });
}

}  // namespace projsurf::cli
