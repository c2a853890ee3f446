// Likely user mistakes that are still valid input get one warning line; calibrations in the
// wrong units are refused with one error line (exit 2).
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "cli_run.hpp"

namespace fs = std::filesystem;
using namespace projsurf::test;

namespace {

/// The TUM office frame: a camera pitched about 30 deg down at a partition (depth in 0.2 mm).
const fs::path kFrame = fs::path(PROJSURF_SHARED_DIR) / "data/real/tum_o3d_fr3_office_partition";
const std::string kCalib = std::string(PROJSURF_SOURCE_DIR) + "/examples/calib/example_calib.yaml";

std::string depthArgs(const fs::path &camera = kFrame / "camera.yaml") {
    return "detect --depth " + (kFrame / "depth.png").string() + " --camera " + camera.string();
}

int lines(const std::string &text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

/// `text` with the first match of `from` replaced, written to `path`.
void writeEdited(const fs::path &from, const fs::path &path, const std::string &pattern, const std::string &with) {
    std::ofstream(path) << std::regex_replace(slurp(from), std::regex(pattern), with,
                                              std::regex_constants::format_first_only);
}

}  // namespace

TEST(CliWarnings, TiltedCameraWithoutGravityIsToldToGiveIt) {
    if (!fs::exists(kFrame / "depth.png")) GTEST_SKIP() << "no real frames at " << kFrame;
    const fs::path dir = freshDir("warnings_tilt");
    const auto level = cli(depthArgs() + " --calib " + kCalib + " --json " + (dir / "a.json").string(), dir);
    EXPECT_EQ(level.status, 0) << level.err;
    EXPECT_NE(level.err.find("projsurf: warning: the floor says the camera is tilted"), std::string::npos) << level.err;
    EXPECT_NE(level.err.find("--gravity auto"), std::string::npos) << level.err;
    EXPECT_EQ(lines(level.err), 1) << level.err;
    // Given gravity (or auto): no warning.
    const auto given =
        cli(depthArgs() + " --calib " + kCalib + " --gravity auto --json " + (dir / "b.json").string(), dir);
    EXPECT_EQ(given.status, 0) << given.err;
    EXPECT_EQ(given.err.find("tilted"), std::string::npos) << given.err;
    fs::remove_all(dir);
}

TEST(CliWarnings, WrongDepthScaleAndIgnoredOptionsAreWarnedAbout) {
    if (!fs::exists(kFrame / "depth.png")) GTEST_SKIP() << "no real frames at " << kFrame;
    const fs::path dir = freshDir("warnings_scale");
    writeEdited(kFrame / "camera.yaml", dir / "camera.yaml", "depth_scale: *[0-9.]+", "depth_scale: 500");
    const auto r = cli(depthArgs(dir / "camera.yaml") + " --calib " + kCalib + " --gravity auto --hull convex --json " +
                           (dir / "d.json").string(),
                       dir);
    EXPECT_EQ(r.status, 0) << r.err;  // valid input: warned, not refused
    EXPECT_NE(r.err.find("the median depth is"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("depth_scale"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: --hull is ignored by the default method"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(CliWarnings, CalibrationInRadiansOrMillimetresIsRefused) {
    const fs::path dir = freshDir("warnings_units");
    writeEdited(kCalib, dir / "rad.yaml", "fov_deg: \\[[^\\]]*\\]", "fov_deg: [0.686, 0.419]");
    writeEdited(kCalib, dir / "mm.yaml", "origin: \\[[^\\]]*\\]", "origin: [0, 120, 0]");
    for (const auto &[file, word] :
         {std::pair<std::string, std::string>{"rad.yaml", "radians"}, {"mm.yaml", "metres"}}) {
        const auto r = cli("detect --cloud /nonexistent.pcd --calib " + (dir / file).string(), dir);
        EXPECT_EQ(r.status, 2) << file;
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_NE(r.err.find((dir / file).string()), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(word), std::string::npos) << r.err;
    }
    fs::remove_all(dir);
}
