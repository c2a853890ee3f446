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
#include "eval/paper/truth_json.hpp"
#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/formats/pattern_files.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/calibration_captures.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/projector_rigs.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/sim/scenes/scenarios_realistic.hpp"

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

/// The depth sensor a frame is rendered through.
struct SimulatedSensor {
    bool independent = false;                   ///< the paper experiments' independent-noise Kinect
    std::optional<sim::DepthSensor> realistic;  ///< none when independent or noise-free
    /// The independent model at the chosen sensor's camera and range (exact with --noise-free):
    /// the frame when there is no realistic sensor, the ground truth's limits, the captures.
    sim::SensorModel model;
};

/// What a scenario's frame is: the frame, its ground truth, and the picture seen by the audience.
struct SimulatedScene {
    sim::RgbdFrame frame;
    sim::GroundTruth truth;
    cv::Mat audience;  ///< empty without --picture
};

void createFolder(const fs::path &dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw InputError(dir.string(), "cannot create the directory: " + ec.message());
}

void listScenarios() {
    for (const auto &name : sim::scenarioNames())
        std::cout << name << "\t" << sim::makeScenario(name, 2.0, 0.0).description << "\n";
    for (const auto &name : sim::realisticScenarioNames())
        std::cout << name << "\t" << sim::makeRealisticScenario(name, 2.0, 0.0).description << "\n";
}

/// The options that are refused on their own, before any file is read.
void checkSimulateArguments(const SimulateOptions &o) {
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
}

/// --calib's projector (the contract's example without it), refused when --structured-light
/// would render framebuffers too big.
Projector simulatedProjector(const SimulateOptions &o) {
    const Projector projector = o.calib.empty() ? sim::exampleProjector() : readCalibrationWarned(o.calib);
    // Each pattern is rendered at the framebuffer's size, for three positions: 16384 x 2048
    // took 40-54 s. 4K UHD (3840 x 2160) fits the bound.
    if (o.structured_light &&
        static_cast<std::uint64_t>(projector.width) * projector.height > kMaxSimulatedPatternPixels)
        throw InputError(o.calib, "--structured-light renders framebuffers of at most " +
                                      std::to_string(kMaxSimulatedPatternPixels) + " pixels; this one is " +
                                      std::to_string(projector.width) + " x " + std::to_string(projector.height));
    return projector;
}

/// --picture scaled to the framebuffer (the projector scales its input); none without it.
std::optional<sim::Projection> projectedPicture(const std::string &path, const Projector &projector) {
    if (path.empty()) return std::nullopt;
    cv::Mat picture = readImage(path, cv::IMREAD_COLOR);
    if (picture.cols != projector.width || picture.rows != projector.height)
        cv::resize(picture, picture, cv::Size(projector.width, projector.height), 0, 0, cv::INTER_AREA);
    return sim::Projection{projector, picture};
}

SimulatedSensor simulatedSensor(const SimulateOptions &o) {
    SimulatedSensor s;
    s.independent = o.sensor == kIndependent;
    const auto kind = sim::parseSensorKind(o.sensor);
    if (!s.independent && !kind)
        throw InputError("--sensor", "expected kinect1, tof, d435 or kinect1-independent, got '" + o.sensor + "'");
    if (o.unit < 0 || o.unit > 1000000) throw InputError("--unit", "must be between 0 and 1000000");
    if (!(s.independent || o.noise_free)) s.realistic = sim::makeDepthSensor(*kind, o.unit);
    s.model = o.noise_free ? sim::SensorModel::ideal() : sim::SensorModel();
    if (!s.independent) {
        const sim::SensorModel limits = sim::makeDepthSensor(*kind, o.unit).truthModel();
        s.model.camera = limits.camera;
        s.model.min_depth = limits.min_depth;
        s.model.max_depth = limits.max_depth;
        s.model.grazing_max_deg = limits.grazing_max_deg;
    }
    return s;
}

/// Refuses an --out that is a file, and capture folders an earlier run left: they are read
/// whole (every pose_<k>, every capture_<k>), so its files would be read as this run's.
void checkOutputFolder(const SimulateOptions &o) {
    const fs::path out(o.out);
    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_directory(out, ec)) throw InputError(o.out, "exists and is not a directory");
    for (const auto &[wanted, name] : {std::pair<bool, const char *>{o.captures > 0, "captures"},
                                       std::pair<bool, const char *>{o.structured_light, "structured"}})
        if (wanted && fs::exists(out / name, ec) && !fs::is_empty(out / name, ec))
            throw InputError((out / name).string(),
                             "exists and is not empty: an earlier run's captures would stay beside the new ones "
                             "(remove it, or give another --out)");
}

/// The picture as someone facing the wall sees it, 2.5 m in front of where the projector's
/// axis meets the wall (or of the true rectangle's centre).
cv::Mat audienceView(const sim::Scenario &scenario, const sim::GroundTruth &truth, const Projector &projector,
                     const sim::Projection &projection, double distance) {
    const Plane &wall = truth.found ? truth.best.plane : scenario.wall;
    const auto axis_hit = intersectRay(wall, projector.origin, projector.direction.normalized());
    const Eigen::Vector3d target =
        truth.found ? truth.best.rectangle.center() : axis_hit.value_or(Eigen::Vector3d(0.0, 0.0, distance));
    return sim::renderView(scenario.scene, sim::facingView(wall, target, 2.5, scenario.gravity), projection);
}

SimulatedScene renderScene(const sim::Scenario &scenario, const SimulatedSensor &sensor, const Projector &projector,
                           const std::optional<sim::Projection> &projection, double aspect, const SimulateOptions &o) {
    SimulatedScene s;
    s.frame = sensor.realistic ? sim::renderSensorFrame(scenario.scene, *sensor.realistic, o.seed, projection)
                               : sim::renderFrame(scenario.scene, sensor.model, o.seed, projection);
    sim::TruthOptions topt;
    topt.aspect = aspect;
    s.truth = sim::computeGroundTruth(scenario.scene, sensor.model, projector, scenario.gravity, topt);
    if (projection) s.audience = audienceView(scenario, s.truth, projector, *projection, o.distance);
    return s;
}

void writeScene(const fs::path &out, const SimulatedScene &s, const sim::Scenario &scenario,
                const CameraIntrinsics &camera, const Projector &projector, const SimulateOptions &o) {
    writeFrame(out, "", s.frame, true);
    if (!s.audience.empty()) writeImageAtomic((out / "audience.png").string(), s.audience);
    writeCamera((out / "camera.yaml").string(), camera);
    writeCalibration((out / "calib.yaml").string(), projector);
    eval::writeTruthJson((out / "truth.json").string(), s.truth, scenario, o.seed, !o.noise_free);
}

void writeCalibrationCaptures(const fs::path &dir, const std::vector<sim::RgbdFrame> &captures,
                              const CameraIntrinsics &camera) {
    createFolder(dir);
    writeCamera((dir / "camera.yaml").string(), camera);
    for (std::size_t k = 0; k < captures.size(); ++k)
        writeFrame(dir, "capture_" + std::to_string(k) + "_", captures[k], false);
}

void writePatternCaptures(const fs::path &dir, const std::vector<sim::PatternCapture> &patterns,
                          const Projector &projector, const CameraIntrinsics &camera) {
    const PatternList list = writePatternSet(dir.string(), projector.width, projector.height);
    writeCamera((dir / "camera.yaml").string(), camera);
    for (std::size_t k = 0; k < patterns.size(); ++k) {
        const fs::path pose = dir / ("pose_" + std::to_string(k));
        createFolder(pose);
        writeImageAtomic((pose / "depth.png").string(), patterns[k].depth);
        for (std::size_t i = 0; i < list.names.size() && i < patterns[k].colour.size(); ++i)
            writeImageAtomic((pose / (list.names[i] + ".png")).string(), patterns[k].colour[i]);
    }
}

void printScene(const SimulateOptions &o, const SimulatedSensor &sensor, const sim::Scenario &scenario,
                const sim::GroundTruth &truth) {
    std::cout << "sensor " << (sensor.independent ? std::string(kIndependent) : o.sensor)
              << (sensor.realistic ? " unit " + std::to_string(o.unit) : std::string()) << " ("
              << sensor.model.camera.width << "x" << sensor.model.camera.height << "), ";
    std::cout << "scenario " << scenario.name << " at " << scenario.distance << " m, " << scenario.angle_deg
              << " deg: ";
    if (truth.found)
        std::cout << "true rectangle on the " << truth.best.label << ", " << truth.best.rectangle.width << " x "
                  << truth.best.rectangle.height << " m\n";
    else
        std::cout << "no free rectangle\n";
}

void printCaptureFolders(const fs::path &out, std::size_t captures, std::size_t pattern_positions) {
    if (captures != 0) std::cout << captures << " calibration captures in " << (out / "captures").string() << "\n";
    if (pattern_positions != 0)
        std::cout << pattern_positions << " positions of structured-light captures in " << (out / "structured").string()
                  << "; projsurf calibrate --captures " << (out / "structured").string()
                  << " --out calib.yaml fits the projector, to compare with " << (out / "calib.yaml").string() << "\n";
}

void run(const SimulateOptions &o) {
    if (o.list) {
        listScenarios();
        return;
    }
    // Arguments and inputs first; nothing is written until everything is rendered.
    checkSimulateArguments(o);
    const Projector projector = simulatedProjector(o);
    const double aspect = o.aspect.empty() ? projector.aspect() : frontend::parseAspect("--aspect", o.aspect);
    const std::optional<sim::Projection> projection = projectedPicture(o.picture, projector);
    const SimulatedSensor sensor = simulatedSensor(o);
    std::optional<sim::Scenario> scenario;
    if (!o.scenario.empty()) scenario = buildScenario(o.scenario, o.distance, o.angle_deg, o.roll_deg, o.pitch_deg);
    checkOutputFolder(o);

    // Render. Calibration captures: a plain wall from N robot positions, 1.2-3.0 m, turned a
    // little. Structured-light captures: the flat wall from three positions
    // (sim/projector_rigs.hpp), each pattern of `projsurf patterns` as the colour camera sees
    // it, and the depth.
    std::optional<SimulatedScene> shot;
    if (scenario) shot = renderScene(*scenario, sensor, projector, projection, aspect, o);
    std::vector<sim::RgbdFrame> captures;
    if (o.captures > 0)
        captures = sim::renderCalibrationCaptures(projector, sensor.model, o.captures, o.seed, o.roll_deg, o.pitch_deg);
    std::vector<sim::PatternCapture> patterns;
    if (o.structured_light)
        patterns = sim::renderPatternCaptures(projector, sensor.model, sim::flatWallPoses(), o.seed);

    // Write.
    const fs::path out(o.out);
    createFolder(out);
    if (scenario) writeScene(out, *shot, *scenario, sensor.model.camera, projector, o);
    if (!captures.empty()) writeCalibrationCaptures(out / "captures", captures, sensor.model.camera);
    if (!patterns.empty()) writePatternCaptures(out / "structured", patterns, projector, sensor.model.camera);
    if (!scenario && (!captures.empty() || !patterns.empty()))
        writeCalibration((out / "calib.yaml").string(), projector);  // the truth to compare with
    if (scenario) printScene(o, sensor, *scenario, shot->truth);
    printCaptureFolders(out, captures.size(), patterns.size());
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
