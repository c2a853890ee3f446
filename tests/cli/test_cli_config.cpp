// `projsurf detect --config FILE` and `--print-config`: the settings file under the flags,
// printed back as YAML that reads to the same config; a bad file is one line, exit 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"

namespace fs = std::filesystem;
using namespace projsurf::test;

namespace {

const fs::path kFrame = fs::path(PROJSURF_SOURCE_DIR) / "data/tum_o3d_fr3_office_partition";
const std::string kCalib = std::string(PROJSURF_SOURCE_DIR) + "/examples/calib/example_calib.yaml";

std::string depthArgs() {
    return "detect --depth " + (kFrame / "depth.png").string() + " --camera " + (kFrame / "camera.yaml").string() +
           " --calib " + kCalib;
}

/// The config `yaml` (what --print-config wrote) describes.
projsurf::DetectorConfig readPrinted(const fs::path &dir, const std::string &yaml) {
    const fs::path path = dir / "printed.yaml";
    std::ofstream(path) << yaml;
    projsurf::DetectorConfig c;
    projsurf::frontend::readDetectorConfig(path.string(), c);
    return c;
}

}  // namespace

TEST(CliConfig, PrintConfigNeedsNoInputAndWritesTheDefaults) {
    const fs::path dir = freshDir("cli_print_config");
    const CliRun r = cli("detect --print-config", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, slurp(fs::path(PROJSURF_SOURCE_DIR) / "config/detector.yaml"));
    EXPECT_EQ(r.out, projsurf::frontend::detectorConfigYaml(projsurf::DetectorConfig{}));
    // Without --print-config, --calib stays required, as before.
    const CliRun missing =
        cli("detect --config " + (fs::path(PROJSURF_SOURCE_DIR) / "config/detector.yaml").string(), dir);
    EXPECT_EQ(missing.status, 2);
    EXPECT_EQ(missing.err, "projsurf: error: --calib is required (see projsurf detect --help)\n");
    fs::remove_all(dir);
}

TEST(CliConfig, FlagsOverrideTheFileWhichOverridesTheDefaults) {
    const fs::path dir = freshDir("cli_config_precedence");
    std::ofstream(dir / "detector.yaml") << "method: default\nseed: 5\nplanes:\n  max_planes: 3\n"
                                            "free_space.cell: 0.02\npaper: {hull: convex}\n";
    const CliRun r = cli("detect --print-config --config " + (dir / "detector.yaml").string() +
                             " --max-planes 7 --method paper --aspect 4:3",
                         dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const projsurf::DetectorConfig c = readPrinted(dir, r.out);
    EXPECT_EQ(c.planes.max_planes, 7);             // flag over file
    EXPECT_EQ(c.method, projsurf::Method::Paper);  // flag over file
    EXPECT_DOUBLE_EQ(c.aspect, 4.0 / 3.0);         // flag over default
    EXPECT_EQ(c.seed, 5u);                         // file over default
    EXPECT_EQ(c.free_space.cell, 0.02);            // file over default
    EXPECT_EQ(c.paper.hull, projsurf::HullKind::Convex);
    EXPECT_EQ(c.check.max_outlier_fraction, projsurf::DetectorConfig{}.check.max_outlier_fraction);
    fs::remove_all(dir);
}

TEST(CliConfig, TheFileReachesTheDetector) {
    const fs::path dir = freshDir("cli_config_detect");
    std::ofstream(dir / "paper.yaml") << "method: paper\n";
    CliRun r = cli(depthArgs() + " --gravity auto --config " + (dir / "paper.yaml").string(), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("method"), "paper");
    r = cli(depthArgs() + " --gravity auto --method default --config " + (dir / "paper.yaml").string(), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("method"), "default");
    fs::remove_all(dir);
}

TEST(CliConfig, ABadFileIsOneLineExitTwoAndNoOutput) {
    const fs::path dir = freshDir("cli_config_bad");
    const std::string file = (dir / "detector.yaml").string();
    std::ofstream(file) << "planes:\n  max_plane: 6\n";
    CliRun r = cli(depthArgs() + " --config " + file + " --json " + (dir / "out.json").string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err,
              "projsurf: error: " + file + ": unknown key 'planes.max_plane' (did you mean 'planes.max_planes'?)\n");
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    std::ofstream(file) << "free_space:\n  cell: 5\n";
    r = cli("detect --print-config --config " + file, dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err,
              "projsurf: error: " + file + ": key 'free_space.cell': must be a number from 0.002 to 0.5, got '5'\n");
    std::ofstream(file) << "seed: [1\n";
    r = cli("detect --print-config --config " + file, dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("projsurf: error: " + file + ": malformed YAML: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
    r = cli("plan --cloud x.pcd --calib " + kCalib + " --config " + file, dir);  // plan reads the same file
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("projsurf: error: " + file + ": malformed YAML: ", 0), 0u) << r.err;
    fs::remove_all(dir);
}
