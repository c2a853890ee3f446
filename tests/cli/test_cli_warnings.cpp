// Likely user mistakes that are still valid input get one warning line; calibrations in the
// wrong units are refused with one error line (exit 2).
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_run.hpp"

namespace fs = std::filesystem;
using namespace projsurf::test;

namespace {

/// The TUM office frame: a camera pitched about 30 deg down at a partition (depth in 0.2 mm);
/// it ships in the repository's data/.
const fs::path kFrame = fs::path(PROJSURF_SOURCE_DIR) / "data/tum_o3d_fr3_office_partition";
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

TEST(CliWarnings, DepthScaleFiveTimesOffEitherWayOrACloudInMillimetresIsNamed) {
    const fs::path dir = freshDir("warnings_range");
    // 5000 -> 1000: the median depth is 5 times too far (about 12 m).
    writeEdited(kFrame / "camera.yaml", dir / "camera.yaml", "depth_scale: *[0-9.]+", "depth_scale: 1000");
    auto r = cli(
        depthArgs(dir / "camera.yaml") + " --calib " + kCalib + " --gravity auto --json " + (dir / "a.json").string(),
        dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: " + (dir / "camera.yaml").string() + ": the median depth is"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("about 8 m"), std::string::npos) << r.err;
    // 5000 -> 40000: 8 times too near (about 0.3 m), below the minimum range.
    writeEdited(kFrame / "camera.yaml", dir / "near.yaml", "depth_scale: *[0-9.]+", "depth_scale: 40000");
    r = cli(depthArgs(dir / "near.yaml") + " --calib " + kCalib + " --gravity auto --json " + (dir / "b.json").string(),
            dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("minimum range"), std::string::npos) << r.err;
    // 5000 -> 25000: 5 times too near (median about 0.48 m), above the minimum range but a
    // close-up no projector robot works at: warned too, and the file named.
    writeEdited(kFrame / "camera.yaml", dir / "five.yaml", "depth_scale: *[0-9.]+", "depth_scale: 25000");
    r = cli(depthArgs(dir / "five.yaml") + " --calib " + kCalib + " --gravity auto --json " + (dir / "f.json").string(),
            dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: " + (dir / "five.yaml").string() + ": the median depth is 0.4"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("nearer than a projector robot works (under 0.75 m"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("check its depth_scale"), std::string::npos) << r.err;
    // The right scale: no range warning.
    r = cli(depthArgs() + " --calib " + kCalib + " --gravity auto --json " + (dir / "c.json").string(), dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("median depth"), std::string::npos) << r.err;
    // A cloud written in millimetres (an ASCII PCD, z about 2000).
    {
        std::ofstream pcd(dir / "mm.pcd");
        pcd << "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 400\nHEIGHT 1\nVIEWPOINT 0 0 0 1 "
               "0 0 "
               "0\nPOINTS 400\nDATA ascii\n";
        for (int i = 0; i < 400; ++i) pcd << (i % 20) * 50 - 500 << " " << (i / 20) * 50 - 500 << " 2000\n";
    }
    r = cli(
        "detect --cloud " + (dir / "mm.pcd").string() + " --calib " + kCalib + " --json " + (dir / "d.json").string(),
        dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: " + (dir / "mm.pcd").string() +
                         ": the median depth is 2000 m; the "
                         "cloud looks like millimetres"),
              std::string::npos)
        << r.err;
    fs::remove_all(dir);
}

TEST(CliWarnings, AnUpVectorOrAnOpticalAxisGivenAsGravityIsExplained) {
    const fs::path dir = freshDir("warnings_gravity");
    auto r = cli(depthArgs() + " --calib " + kCalib + " --gravity 0,-1,0 --json " + (dir / "a.json").string(), dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: --gravity 0,-1,0 puts the floor above the camera"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("give 0,1,0"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    r = cli(depthArgs() + " --calib " + kCalib + " --gravity 0,0,1 --json " + (dir / "b.json").string(), dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: --gravity 0,0,1 points along the camera's optical axis"),
              std::string::npos)
        << r.err;
    // Down given as down: no gravity warning.
    r = cli(depthArgs() + " --calib " + kCalib + " --gravity 0,1,0 --json " + (dir / "c.json").string(), dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("--gravity 0,1,0"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(CliWarnings, ColourThatIsNotEightBitBgrIsRefusedAsPythonDoes) {
    const fs::path dir = freshDir("warnings_rgb");
    cv::imwrite((dir / "grey.png").string(), cv::Mat(480, 640, CV_8UC1, cv::Scalar(128)));
    for (const auto &[file, what] : {std::pair<fs::path, std::string>{kFrame / "depth.png", "16-bit with 1 channel"},
                                     {dir / "grey.png", "8-bit with 1 channel"}}) {
        const auto r =
            cli(depthArgs() + " --calib " + kCalib + " --rgb " + file.string() + " --json " + (dir / "a.json").string(),
                dir);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("projsurf: error: " + file.string() + ": expected 8-bit 3-channel colour"),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "a.json"));
    }
    fs::remove_all(dir);
}

TEST(CliWarnings, SwappedFilesRosCameraInfoUnknownKeysAndImagesAsJsonAreNamed) {
    const fs::path dir = freshDir("warnings_files");
    const std::string camera = (kFrame / "camera.yaml").string();
    auto r = cli(depthArgs(kCalib) + " --calib " + camera + " --json " + (dir / "a.json").string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--camera and --calib swapped?"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    // A typo in camera.yaml: warned, the rest read.
    writeEdited(kFrame / "camera.yaml", dir / "typo.yaml", "depth_scale", "depth_scal");
    r = cli(depthArgs(dir / "typo.yaml") + " --calib " + kCalib + " --gravity auto --json " + (dir / "b.json").string(),
            dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("unknown key 'camera.depth_scal' is ignored"), std::string::npos) << r.err;
    // A typo under the calibration's projector: (its distortion would be lost): warned, once per key.
    std::ofstream(dir / "calib_typo.yaml") << slurp(kCalib) << "  distorsion: [0.1, 0, 0, 0, 0]\n";
    r = cli(depthArgs() + " --calib " + (dir / "calib_typo.yaml").string() + " --gravity auto --json " +
                (dir / "b2.json").string(),
            dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: " + (dir / "calib_typo.yaml").string() +
                         ": unknown key 'projector.distorsion' is ignored"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    // A ROS camera_info YAML: read (depth in mm, so the TUM frame is 5 times too far: warned);
    // with distortion: refused.
    const std::string info =
        "image_width: 640\nimage_height: 480\ncamera_name: depth\ncamera_matrix:\n  rows: 3\n  cols: 3\n  data: "
        "[535.4, 0, 320.1, 0, 539.2, 247.6, 0, 0, 1]\ndistortion_model: plumb_bob\ndistortion_coefficients:\n  rows: "
        "1\n  cols: 5\n  data: [";
    std::ofstream(dir / "info.yaml") << info << "0, 0, 0, 0, 0]\n";
    std::ofstream(dir / "distorted.yaml") << info << "0.1, 0, 0, 0, 0]\n";
    r = cli(depthArgs(dir / "info.yaml") + " --calib " + kCalib + " --gravity auto --json " + (dir / "c.json").string(),
            dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "c.json"));
    EXPECT_NE(r.err.find("the median depth is"), std::string::npos) << r.err;
    r = cli(depthArgs(dir / "distorted.yaml") + " --calib " + kCalib + " --json " + (dir / "d.json").string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("non-zero distortion_coefficients"), std::string::npos) << r.err;
    // The overlay PNG given as the detection.
    r = cli(depthArgs() + " --calib " + kCalib + " --gravity auto --json " + (dir / "e.json").string() + " --overlay " +
                (dir / "e.png").string(),
            dir);
    ASSERT_EQ(r.status, 0) << r.err;
    r = cli("correct --calib " + kCalib + " --detection " + (dir / "e.png").string() + " --image " +
                (kFrame / "rgb.png").string() + " --out " + (dir / "fb.png").string(),
            dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find((dir / "e.png").string() + ": is a PNG image, not a JSON file"), std::string::npos) << r.err;
    // The calibration given as the detection (the two swapped), and a text file that is no JSON.
    r = cli("correct --calib " + kCalib + " --detection " + kCalib + " --image " + (kFrame / "rgb.png").string() +
                " --out " + (dir / "fb.png").string(),
            dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(kCalib + ": is a YAML file"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--detection and --calib swapped?"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    std::ofstream(dir / "notes.txt") << "found: yes\n";
    r = cli("correct --calib " + kCalib + " --detection " + (dir / "notes.txt").string() + " --image " +
                (kFrame / "rgb.png").string() + " --out " + (dir / "fb.png").string(),
            dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("is not JSON (it does not begin with '{')"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "fb.png"));
    fs::remove_all(dir);
}

TEST(CliWarnings, VersionAndUsageMistakesCarryTheErrorPrefix) {
    const fs::path dir = freshDir("warnings_usage");
    auto r = cli("--version", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.rfind("projsurf ", 0), 0u) << r.out;
    r = cli("detect --no-such-option 1", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("projsurf: error: ", 0), 0u) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    // The unknown word is named, not the required option CLI11 checks first.
    EXPECT_NE(r.err.find("unknown option '--no-such-option' for projsurf detect"), std::string::npos) << r.err;
    r = cli("detcet --calib c.yaml", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("projsurf: error: unknown command 'detcet' (commands: detect,"), std::string::npos) << r.err;
    r = cli("", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("projsurf: error: a command is required (commands: detect,"), std::string::npos) << r.err;
    r = cli("detect", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "projsurf: error: --calib is required (see projsurf detect --help)\n");
    r = cli("detect --calib " + kCalib + " --cloud x.pcd stray", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("projsurf: error: unexpected argument 'stray' for projsurf detect"), std::string::npos)
        << r.err;
    fs::remove_all(dir);
}
