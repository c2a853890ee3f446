// Hostile input, end to end through the CLI: every finding is a case here, built
// from a simulated frame in the test (no committed binaries). A refused input must give exit
// 2, exactly one stderr line "projsurf: error: <file>: ...", and no output file (nor a
// temporary) left behind; a valid but odd input (all-NaN cloud, far points) exit 0.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <random>
#include <sstream>

#include "bag_writer.hpp"
#include "cli_run.hpp"
#include "hostile_fixture.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/rosbag/rosbag_clouds.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {

/// A simulated frame (cloud, depth, camera, calibration, captures) shared by the cases.
class Hostile : public HostileCli {};

std::string pngHeader(std::uint32_t w, std::uint32_t h) {
    // Signature and IHDR only: the size is read from the header and refused before decoding.
    std::string s("\x89PNG\r\n\x1a\n", 8);
    auto be = [&](std::uint32_t v) {
        for (int i = 3; i >= 0; --i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
    };
    be(13);
    s += "IHDR";
    be(w);
    be(h);
    s += std::string("\x10\x00\x00\x00\x00", 5);  // 16-bit grey
    be(0);                                        // CRC (not checked: never decoded)
    return s + std::string(1000, '\0');
}

std::string pcdAscii(const std::vector<std::array<float, 3>> &pts) {
    std::ostringstream s;
    s.precision(9);
    s << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH " << pts.size() << "\nHEIGHT 1\nPOINTS "
      << pts.size() << "\nDATA ascii\n";
    for (const auto &p : pts) s << p[0] << " " << p[1] << " " << p[2] << "\n";
    return s.str();
}

}  // namespace

// --- High: a corrupt bag must not reach a parser that trusts its lengths -----------------

TEST_F(Hostile, BagsAreCheckedRecordByRecord) {
    const Cloud cloud = readCloud(sim("cloud.pcd"));
    const std::string good = bagtest::bagWithClouds({cloud, cloud}, "/points");
    writeBytes(at("good.bag"), good);
    const CliRun ok = cli("detect --calib " + sim("calib.yaml") + " --bag " + at("good.bag") +
                              " --topic /points --json " + at("good.jsonl"),
                          dir_);
    ASSERT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(ok.err, "");
    EXPECT_EQ(std::count(std::istreambuf_iterator<char>(std::ifstream(at("good.jsonl")).rdbuf()), {}, '\n'), 2);

    // The finding: a header field length far beyond its header (rosbag read past the buffer).
    std::string bad = good;
    const std::size_t chunk = bad.find("compression=none") - 4;  // the first field of the chunk's header
    bad.replace(chunk, 4, std::string("\x00\x00\x01\x00", 4));   // 65536 bytes, in a header of ~40
    writeBytes(at("field.bag"), bad);
    refused("detect --calib " + sim("calib.yaml") + " --bag " + at("field.bag") + " --topic /points --json " +
                at("o.jsonl"),
            at("field.bag"), "corrupt ROS bag", {at("o.jsonl")});
    // A record announcing more data than the file has; a chunk announcing 4 GB.
    std::string cut = good.substr(0, good.size() - 100);
    writeBytes(at("cut.bag"), cut);
    refused("detect --calib " + sim("calib.yaml") + " --bag " + at("cut.bag") + " --topic /points", at("cut.bag"),
            "ROS bag");
    std::string big = good;
    const std::size_t size_field = big.find("size=") + 5;
    big.replace(size_field, 4, std::string("\xff\xff\xff\xff", 4));
    writeBytes(at("big.bag"), big);
    refused("detect --calib " + sim("calib.yaml") + " --bag " + at("big.bag") + " --topic /points", at("big.bag"),
            "exceeds the limit");

    // Random mutations of a small bag: an InputError naming the file, or a clean read.
    Cloud small;
    small.points.assign(50, Point(0.1f, 0.2f, 1.5f));
    small.width = 50;
    const std::string seed = bagtest::bagWithClouds({small}, "/points");
    std::mt19937 rng(16);
    int errors = 0;
    for (int k = 0; k < 1000; ++k) {
        std::string m = seed;
        const int flips = 1 + static_cast<int>(rng() % 4);
        for (int f = 0; f < flips; ++f) m[rng() % m.size()] = static_cast<char>(rng());
        writeBytes(at("m.bag"), m);
        try {
            forEachBagCloud(at("m.bag"), "/points", [](const Cloud &, const BagCloudInfo &) {});
        } catch (const InputError &e) {
            ++errors;
            ASSERT_NE(std::string(e.what()).find(at("m.bag")), std::string::npos) << e.what();
        }
    }
    EXPECT_GT(errors, 50);
}

// --- Undefined float -> int conversions: far points, NaN, inf, a tiny depth_scale --------

TEST_F(Hostile, FarAndNonFinitePointsAreAFrameNotACrash) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<std::array<float, 3>> pts;
    for (int i = 0; i < 400; ++i) {
        const float u = static_cast<float>(i % 20) / 10.0f - 1.0f, v = static_cast<float>(i / 20) / 10.0f - 1.0f;
        pts.push_back({u, v, 2.0f});                   // a wall
        pts.push_back({u * 1e12f, v * 1e12f, 1e12f});  // very far
        pts.push_back({u * 3e38f, 1e30f, 3e38f});      // near the float range
    }
    pts.push_back({nan, 0, 1});
    pts.push_back({inf, -inf, inf});
    writeBytes(at("far.pcd"), pcdAscii(pts));
    for (const char *method : {"default", "paper"}) {
        const CliRun r = cli(detectArgs(at("far.pcd")) + " --method " + method, dir_);
        EXPECT_EQ(r.status, 0) << method << ": " << r.err;
        // At most the one line that says most points are beyond any sensor's range.
        EXPECT_TRUE(r.err.empty() ||
                    (r.err.rfind("projsurf: warning: ", 0) == 0 && r.err.find('\n') == r.err.size() - 1 &&
                     r.err.find("farther than an RGB-D camera reads") != std::string::npos))
            << method << ": " << r.err;
        EXPECT_TRUE(nlohmann::json::accept(r.out)) << r.out;
    }
    // A depth_scale that turns every reading into kilometres and beyond.
    writeBytes(at("camera.yaml"),
               "camera: {width: 640, height: 480, fx: 525, fy: 525, cx: 319.5, cy: 239.5, depth_scale: 1e-9}\n");
    const CliRun r = cli("detect --calib " + sim("calib.yaml") + " --depth " + sim("depth.png") + " --camera " +
                             at("camera.yaml") + " --overlay " + at("far.png"),
                         dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(at("far.png")));
}

// --- The contract: NaN points are allowed, so an all-NaN cloud is a frame with no surface --

TEST_F(Hostile, AllNanCloudIsFoundFalseWithAReason) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    writeBytes(at("nan.pcd"), pcdAscii(std::vector<std::array<float, 3>>(100, {nan, nan, nan})));
    const CliRun r = cli(detectArgs(at("nan.pcd")) + " --json " + at("nan.json"), dir_);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const auto j = nlohmann::json::parse(slurp(at("nan.json")));
    EXPECT_EQ(j["found"], false);
    ASSERT_TRUE(j["reason"].is_string());
    EXPECT_FALSE(j["reason"].get<std::string>().empty());
}

// --- Memory bombs: valid-looking files refused from their headers -------------------------

TEST_F(Hostile, CompressedPcdBeyondTheLimitsIsRefusedBeforeDecompressing) {
    // 2^24 points of 48 bytes = 768 MiB once decompressed (> 512 MiB), in a few bytes.
    std::string pcd =
        "VERSION 0.7\nFIELDS x y z pad\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 9\nWIDTH 4096\nHEIGHT 4096\n"
        "POINTS 16777216\nDATA binary_compressed\n";
    bagtest::putU32(pcd, 10000000);
    bagtest::putU32(pcd, 48u << 24);
    pcd += std::string(10000000, '\0');
    writeBytes(at("bomb.pcd"), pcd);
    refused(detectArgs(at("bomb.pcd")) + " --json " + at("o.json"), at("bomb.pcd"), "exceeds the limit",
            {at("o.json")});
    // More points than the limit.
    writeBytes(at("many.pcd"),
               "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 5000\nHEIGHT 5000\n"
               "POINTS 25000000\nDATA binary_compressed\n" +
                   std::string(16, '\0'));
    refused(detectArgs(at("many.pcd")), at("many.pcd"), "exceeds the limit of 16777216 points");
}

TEST_F(Hostile, HugeImagesAreRefusedFromTheirHeader) {
    writeBytes(at("huge_depth.png"), pngHeader(16384, 16384));
    refused("detect --calib " + sim("calib.yaml") + " --depth " + at("huge_depth.png") + " --camera " +
                sim("camera.yaml") + " --json " + at("o.json"),
            at("huge_depth.png"), "exceeds the limit", {at("o.json")});
    writeBytes(at("huge_picture.png"), pngHeader(30000, 30000));
    const CliRun det =
        cli("detect --calib " + sim("calib.yaml") + " --cloud " + sim("cloud.pcd") + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " +
                at("huge_picture.png") + " --out " + at("fb.png") + " --json " + at("k.json"),
            at("huge_picture.png"), "exceeds the limit", {at("fb.png"), at("k.json")});
    // A framebuffer of 16384 x 16384 (1.2 GB per frame).
    writeBytes(at("calib.yaml"),
               "projector:\n  resolution: [16384, 16384]\n  fov_deg: [40, 25]\n  axis:\n"
               "    origin: [0, 0.12, 0]\n    direction: [0, 0, 1]\n");
    refused("detect --calib " + at("calib.yaml") + " --cloud " + sim("cloud.pcd"), at("calib.yaml"),
            "exceeds the limit");
    // Not an image format projsurf reads; a truncated PNG (libpng would print its own lines).
    writeBytes(at("junk.png"), "GIF89a" + std::string(100, 'x'));
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " + at("junk.png") +
                " --out " + at("fb.png"),
            at("junk.png"), "not a readable image", {at("fb.png")});
    const std::string rgb = slurp(sim("rgb.png"));
    writeBytes(at("cut.png"), rgb.substr(0, rgb.size() / 2));
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " + at("cut.png") +
                " --out " + at("fb.png"),
            at("cut.png"), "not a readable image", {at("fb.png")});
}

TEST_F(Hostile, ThinDepthFrameGivesASmallOverlay) {
    // 1 x 2000: the overlay was scaled by its width alone (960 x 1920000 pixels).
    writeBytes(at("camera.yaml"), "camera: {width: 1, height: 2000, fx: 525, fy: 525, cx: 0, cy: 1000}\n");
    cv::Mat depth(2000, 1, CV_16UC1, cv::Scalar(2000));
    ASSERT_TRUE(cv::imwrite(at("thin.png"), depth));
    const CliRun r = cli("detect --calib " + sim("calib.yaml") + " --depth " + at("thin.png") + " --camera " +
                             at("camera.yaml") + " --overlay " + at("thin_overlay.png") + " --json " + at("thin.json"),
                         dir_);
    ASSERT_EQ(r.status, 0) << r.err;
    const cv::Mat overlay = cv::imread(at("thin_overlay.png"));
    ASSERT_FALSE(overlay.empty());
    EXPECT_LT(overlay.total(), 8u << 20) << overlay.cols << " x " << overlay.rows;
}

// --- Partial output: every output of one command, or none ----------------------------------

TEST_F(Hostile, NoPartialOutputWhenALaterOutputFails) {
    // detect: --json fine, --overlay with an extension no encoder has, or a directory.
    refused(detectArgs(sim("cloud.pcd")) + " --json " + at("d.json") + " --overlay " + at("d.xyz"), at("d.xyz"),
            "extension", {at("d.json"), at("d.xyz")});
    fs::create_directories(at("adir.png"));
    refused(detectArgs(sim("cloud.pcd")) + " --json " + at("d.json") + " --overlay " + at("adir.png"), at("adir.png"),
            "directory", {at("d.json")});
    // correct: framebuffer fine, --json a directory.
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    fs::create_directories(at("k.json"));
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " + sim("rgb.png") +
                " --out " + at("fb.png") + " --json " + at("k.json"),
            at("k.json"), "directory", {at("fb.png")});
}

// --- Silent truncation: an unreadable frame in the middle of a sequence --------------------

TEST_F(Hostile, UnreadableMiddleFrameIsAnErrorNamingIt) {
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    fs::create_directories(at("frames"));
    const cv::Mat pic(120, 160, CV_8UC3, cv::Scalar(40, 200, 90));
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(cv::imwrite(at("frames/f_000" + std::to_string(k) + ".png"), pic));
    writeBytes(at("frames/f_0001.png"), "\x89PNG\r\n\x1a\n but then nothing");
    const std::string base = "correct --calib " + sim("calib.yaml") + " --detection " + at("det.json");
    refused(base + " --image " + at("frames/f_%04d.png") + " --out " + at("out.avi") + " --json " + at("k.json"),
            at("frames/f_0001.png"), "not a readable image", {at("out.avi"), at("k.json")});
    refused(base + " --image " + at("frames/f_%04d.png") + " --out " + at("out_%04d.png"), at("frames/f_0001.png"),
            "not a readable image", {at("out_0000.png")});
    // An unreadable video file.
    writeBytes(at("junk.mp4"), std::string(5000, 'j'));
    refused(base + " --image " + at("junk.mp4") + " --out " + at("out.avi"), at("junk.mp4"), "video", {at("out.avi")});
}

// --- One stderr line: a capture number out of range ----------------------------------------

TEST_F(Hostile, CaptureNumberOutOfRangeIsOneLineNamingIt) {
    fs::copy(sim_ / "captures", dir_ / "captures");
    fs::copy_file(sim_ / "captures" / "capture_0_rgb.png", dir_ / "captures" / "capture_99999999999_rgb.png");
    refused("calibrate --captures " + at("captures") + " --out " + at("calib.yaml"), "capture_99999999999_rgb.png",
            "out of range", {at("calib.yaml")});
}

// --- Text files: size and nesting ----------------------------------------------------------

TEST_F(Hostile, DeepOrHugeYamlAndJsonAreRefused) {
    writeBytes(at("deep.yaml"), "projector: " + std::string(1000, '[') + "\n");
    refused("detect --calib " + at("deep.yaml") + " --cloud " + sim("cloud.pcd"), at("deep.yaml"), "YAML");
    writeBytes(at("big.yaml"), "camera:\n" + std::string(1 << 20, '#') + "\n");
    refused("detect --calib " + sim("calib.yaml") + " --depth " + sim("depth.png") + " --camera " + at("big.yaml"),
            at("big.yaml"), "exceeds the limit");
    writeBytes(at("deep.json"), std::string(100000, '[') + std::string(100000, ']'));
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("deep.json") + " --image " + sim("rgb.png") +
                " --out " + at("fb.png"),
            at("deep.json"), "JSON", {at("fb.png")});
}

// --- Structured light: one pose decoded at a time, its limit in bytes ---------------------

namespace {

/// DIR/patterns.yaml for a 1280 x 800 framebuffer (as projsurf patterns writes it).
void writePatternList(const fs::path &dir) {
    std::string yaml = "patterns:\n  resolution: [1280, 800]\n  coding: gray_code_inverse\n  order:\n";
    for (const auto &p : grayPatterns(1280, 800)) yaml += "    - " + p.name + "\n";
    writeBytes(dir / "patterns.yaml", yaml);
}

/// camera.yaml of w x h (a plausible focal length) beside patterns.yaml, and pose_0/ with an
/// all-black capture of every pattern and a depth image without readings.
void writeDarkPose(const fs::path &dir, int w, int h) {
    fs::create_directories(dir / "pose_0");
    writePatternList(dir);
    CameraIntrinsics cam;
    cam.width = w;
    cam.height = h;
    cam.fx = cam.fy = 0.8 * w;
    cam.cx = 0.5 * (w - 1);
    cam.cy = 0.5 * (h - 1);
    writeCamera((dir / "camera.yaml").string(), cam);
    ASSERT_TRUE(cv::imwrite((dir / "pose_0" / "depth.png").string(), cv::Mat(h, w, CV_16UC1, cv::Scalar(0))));
    const fs::path first = dir / "pose_0" / "white.png";
    ASSERT_TRUE(cv::imwrite(first.string(), cv::Mat(h, w, CV_8UC1, cv::Scalar(0))));
    for (const auto &p : grayPatterns(1280, 800))
        if (p.name != "white") fs::copy_file(first, dir / "pose_0" / (p.name + ".png"));
}

}  // namespace

TEST_F(Hostile, StructuredLightDecodesOnePoseAtATime) {
    // 44 all-black 3490 x 3490 captures (the 2 MB folder): decoded, nothing lit.
    // TearDown checks the run stayed under 2 GiB (it took 2.8 GiB when every capture was
    // converted to float at once).
    writeDarkPose(dir_ / "sl", 3490, 3490);
    refused("calibrate --captures " + at("sl") + " --out " + at("c.yaml"), at("sl"), "only 0 decoded", {at("c.yaml")});
    // 39 poses (38 links to the first): refused from the listing, before any image is read.
    for (int k = 1; k < 39; ++k) fs::create_directory_symlink("pose_0", dir_ / "sl" / ("pose_" + std::to_string(k)));
    refused("calibrate --captures " + at("sl") + " --out " + at("c.yaml"), at("sl"), "MiB to decode", {at("c.yaml")});
}

TEST_F(Hostile, StructuredLightFolderProblemsSayWhatIsWrong) {
    // patterns.yaml but no pose_0/: structured light's message, not the disc mode's.
    const fs::path sl = dir_ / "sl";
    fs::create_directories(sl);
    writePatternList(sl);
    fs::copy_file(sim_ / "camera.yaml", sl / "camera.yaml");
    refused("calibrate --captures " + sl.string() + " --out " + at("c.yaml"), (sl / "pose_0").string(), "missing",
            {at("c.yaml")});
    // A depth image of another size than camera.yaml's: both sizes, not a size limit.
    fs::create_directories(sl / "pose_0");
    ASSERT_TRUE(cv::imwrite((sl / "pose_0" / "depth.png").string(), cv::Mat(240, 320, CV_16UC1, cv::Scalar(0))));
    refused("calibrate --captures " + sl.string() + " --out " + at("c.yaml"), "depth.png",
            "is 320x240, camera.yaml says 640x480", {at("c.yaml")});
    // patterns.yaml a link to itself.
    fs::remove(sl / "patterns.yaml");
    fs::create_symlink("patterns.yaml", sl / "patterns.yaml");
    refused("calibrate --captures " + sl.string() + " --out " + at("c.yaml"), "patterns.yaml", "loop", {at("c.yaml")});
    // A framebuffer no calibration could hold.
    fs::remove(sl / "patterns.yaml");
    writeBytes(sl / "patterns.yaml",
               "patterns:\n  resolution: [16384, 16384]\n  coding: gray_code_inverse\n  order: [white]\n");
    refused("calibrate --captures " + sl.string() + " --out " + at("c.yaml"), "patterns.yaml", "framebuffer limit",
            {at("c.yaml")});
}

// --- Regular files only: a FIFO is refused, never waited on --------------------------------

TEST_F(Hostile, FifosAreRefusedNotWaitedOn) {
    for (const char *name : {"fifo.yaml", "fifo.pcd", "fifo.png"}) ASSERT_EQ(::mkfifo(at(name).c_str(), 0600), 0);
    const std::string calib = sim("calib.yaml"), cam = sim("camera.yaml");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"detect --calib " + at("fifo.yaml") + " --cloud " + sim("cloud.pcd"), at("fifo.yaml")},
        {"detect --calib " + calib + " --cloud " + at("fifo.pcd"), at("fifo.pcd")},
        {"detect --calib " + calib + " --depth " + at("fifo.png") + " --camera " + cam, at("fifo.png")},
        {"detect --calib " + calib + " --depth " + sim("depth.png") + " --camera " + at("fifo.yaml"), at("fifo.yaml")},
        {"plan --calib " + at("fifo.yaml") + " --cloud " + sim("cloud.pcd"), at("fifo.yaml")},
    };
    for (const auto &[args, file] : cases) refused(args, file, "FIFO");
    fs::create_directories(dir_ / "sl");
    fs::copy_file(sim_ / "camera.yaml", dir_ / "sl" / "camera.yaml");
    fs::create_symlink(at("fifo.yaml"), dir_ / "sl" / "patterns.yaml");
    refused("calibrate --captures " + at("sl") + " --out " + at("c.yaml"), "patterns.yaml", "FIFO", {at("c.yaml")});
}

// --- Degenerate lens models: refused by the one check every reader shares -----------------

TEST_F(Hostile, DegenerateLensModelsAreRefusedByEveryCommand) {
    const std::string calib = test::slurp(sim("calib.yaml"));
    const std::string res = "  resolution: [1280, 800]\n";
    ASSERT_NE(calib.find(res), std::string::npos);
    auto withIntrinsics = [&](const std::string &name, const std::string &fx) {
        std::string c = calib;
        c.replace(c.find(res), res.size(),
                  res + "  intrinsics:\n    fx: " + fx + "\n    fy: " + fx + "\n    cx: 639.5\n    cy: 399.5\n");
        writeBytes(at(name), c);
        return at(name);
    };
    for (const char *fx : {"1e-300", "0.001"}) {
        const std::string c = withIntrinsics("tiny.yaml", fx);
        refused("detect --calib " + c + " --cloud " + sim("cloud.pcd"), c, "projector.intrinsics.fx");
        refused("plan --calib " + c + " --cloud " + sim("cloud.pcd"), c, "projector.intrinsics.fx");
    }
    // fov_deg 39.3 x 24 but intrinsics of a 120 deg lens.
    const std::string wide = withIntrinsics("wide.yaml", "369.5");
    refused("detect --calib " + wide + " --cloud " + sim("cloud.pcd"), wide, "fov_deg");

    // camera.yaml: a focal length, a depth scale, a principal point no camera has; in detect
    // and in verify (which printed "0.0 mm: passed" and NaN corners in its JSON).
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    const CliRun fb = cli("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " +
                              sim("rgb.png") + " --out " + at("fb.png"),
                          dir_);
    ASSERT_EQ(fb.status, 0) << fb.err;
    fs::create_directories(dir_ / "caps");
    fs::copy_file(sim_ / "rgb.png", dir_ / "caps" / "rgb.png");
    fs::copy_file(sim_ / "depth.png", dir_ / "caps" / "depth.png");
    const std::string camera = test::slurp(sim("camera.yaml"));
    for (const auto &[key, value] : std::vector<std::pair<std::string, std::string>>{
             {"fx", "1e-300"}, {"fx", "1e300"}, {"depth_scale", "1e-300"}, {"cx", "1e300"}}) {
        std::string c = camera;
        const std::size_t at_key = c.find("  " + key + ": ");
        ASSERT_NE(at_key, std::string::npos) << key;
        c.replace(at_key, c.find('\n', at_key) - at_key, "  " + key + ": " + value);
        writeBytes(dir_ / "caps" / "camera.yaml", c);
        const std::string cam = (dir_ / "caps" / "camera.yaml").string();
        refused("detect --calib " + sim("calib.yaml") + " --depth " + sim("depth.png") + " --camera " + cam, cam,
                "camera." + key);
        refused("verify --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --framebuffer " +
                    at("fb.png") + " --captures " + at("caps") + " --json " + at("v.json"),
                cam, "camera." + key, {at("v.json")});
    }
}

// --- Bounded searches: plan on walls far beyond the range ---------------------------------

TEST_F(Hostile, PlanOnFarWallsEndsWithAnAnswer) {
    // A wall at 10 m, 20 m and 65.535 m (all 65535: a wrong depth_scale is enough): plan
    // answers (exit 0, valid JSON) within the CLI's guard; docs/limits.md gives the times.
    for (const int raw : {10000, 20000, 65535}) {
        const std::string depth = at("far_" + std::to_string(raw) + ".png");
        ASSERT_TRUE(cv::imwrite(depth, cv::Mat(480, 640, CV_16UC1, cv::Scalar(raw))));
        const CliRun r = cli("plan --calib " + sim("calib.yaml") + " --depth " + depth + " --camera " +
                                 sim("camera.yaml") + " --json " + at("plan.json"),
                             dir_, 60);
        ASSERT_EQ(r.status, 0) << raw << ": " << r.err;
        const auto j = nlohmann::json::parse(test::slurp(at("plan.json")));
        EXPECT_TRUE(j.contains("found")) << j.dump();
    }
    // One point at x = -1e20 (a float-to-int overflow in the floor grid before it was clamped).
    writeBytes(at("far.pcd"), pcdAscii({{-1e20f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}}));
    const CliRun far = cli("plan --calib " + sim("calib.yaml") + " --cloud " + at("far.pcd"), dir_, 60);
    EXPECT_EQ(far.status, 0) << far.err;
    EXPECT_TRUE(nlohmann::json::accept(far.out)) << far.out;
}

// --- Framebuffers beyond what a calibration may hold ---------------------------------------

TEST_F(Hostile, FramebuffersBeyondTheCalibrationLimitAreRefused) {
    const std::string big = " --resolution 16384,16384";
    refused("patterns --out " + at("p") + big, "--resolution", "framebuffer limit", {at("p")});
    refused("verify --write-card " + at("card.png") + big, "--resolution", "framebuffer limit", {at("card.png")});
    refused("calibrate --write-picture " + at("pic.png") + big, "--resolution", "framebuffer limit", {at("pic.png")});
    // patterns that cannot be written leave no patterns/ folder behind.
    fs::create_directories(dir_ / "q" / "patterns.yaml");
    const CliRun r = cli("patterns --out " + at("q") + " --resolution 64,32", dir_);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "q" / "patterns"));
}

// --- Text that goes into JSON: a bag's frame_id -------------------------------------------

TEST_F(Hostile, BagFrameIdThatIsNotUtf8IsNamed) {
    const Cloud cloud = readCloud(sim("cloud.pcd"));
    std::string bag = bagtest::bagWithClouds({cloud}, "/points");
    const std::size_t id = bag.find("camera_optical");
    ASSERT_NE(id, std::string::npos);
    bag.replace(id, 2, "\xff\xfe");  // the same length: only the text is wrong
    writeBytes(at("id.bag"), bag);
    refused(
        "detect --calib " + sim("calib.yaml") + " --bag " + at("id.bag") + " --topic /points --json " + at("o.jsonl"),
        at("id.bag"), "header.frame_id is not UTF-8", {at("o.jsonl")});
}

// --- A video that ends before its header says ----------------------------------------------

TEST_F(Hostile, TruncatedVideoWarns) {
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    {
        cv::VideoWriter w(at("in.avi"), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25,
                          cv::Size(160, 120));
        ASSERT_TRUE(w.isOpened());
        for (int k = 0; k < 20; ++k) w.write(cv::Mat(120, 160, CV_8UC3, cv::Scalar(10 * k, 100, 200 - 5 * k)));
    }
    const std::string whole = test::slurp(at("in.avi"));
    writeBytes(at("cut.avi"), whole.substr(0, whole.size() / 3));
    const CliRun r = cli("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " +
                             at("cut.avi") + " --out " + at("out.avi"),
                         dir_);
    if (r.status == 2) {  // refused (nothing readable) is an answer too: one line, no output
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(at("out.avi")));
        return;
    }
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("projsurf: warning: " + at("cut.avi") + ": ended after"), std::string::npos) << r.err;
}

// --- Numbers and text from the command line and from files --------------------------------

TEST_F(Hostile, NonFiniteOptionValuesAreRefusedByEveryCommand) {
    // CLI11's ranges let NaN through (every comparison with it is false); 1e400 reads as infinity.
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    for (const char *v : {"nan", "inf", "-inf", "1e400"}) {
        const std::string value(v);
        refused(detectArgs(sim("cloud.pcd")) + " --min-width " + value + " --json " + at("d.json"), "--min-width",
                value, {at("d.json")});
        refused(detectArgs(sim("cloud.pcd")) + " --method paper --voxel-leaf " + value, "--voxel-leaf", value);
        refused("plan --calib " + sim("calib.yaml") + " --cloud " + sim("cloud.pcd") + " --max-move " + value,
                "--max-move", value);
        refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --video " +
                    sim("rgb.png") + " --out " + at("v.avi") + " --fps " + value,
                "--fps", value, {at("v.avi")});
        refused("simulate --out " + at("s") + " --distance " + value, "--distance", value, {at("s")});
    }
    refused(detectArgs(sim("cloud.pcd")) + " --max-tilt nan", "--max-tilt", "'nan' is not a finite number");
    // Two numbers in one word: each one.
    refused("calibrate --captures " + sim("captures") + " --out " + at("c.yaml") + " --fov-deg 39.3,nan", "--fov-deg",
            "expected two numbers", {at("c.yaml")});
}

TEST_F(Hostile, ErrorLinesAreUtf8WhateverTheFileHeld) {
    // A settings file's word quoted in the message: its bytes that are not UTF-8 come out as \xNN.
    writeBytes(at("bad.yaml"), "method: \xff\xfe\n");
    const CliRun r = cli(detectArgs(sim("cloud.pcd")) + " --config " + at("bad.yaml"), dir_);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(isUtf8(r.err)) << r.err;
    EXPECT_NE(r.err.find("\\xFF\\xFE"), std::string::npos) << r.err;
}

TEST_F(Hostile, DetectionCornersFarOffOrBehindTheCameraAreRefused) {
    // Corners of 1e300 m are finite, but the rectangle's sides overflow to infinity; verify
    // compared them, correct refused them only as "behind the projector".
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    nlohmann::json j = nlohmann::json::parse(test::slurp(at("det.json")));
    for (auto &c : j["rectangle"]["corners"])
        for (auto &x : c) x = x.get<double>() * 1000.0;  // millimetres
    writeBytes(at("mm.json"), j.dump());
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("mm.json") + " --image " + sim("rgb.png") +
                " --out " + at("fb.png"),
            at("mm.json"), "more than 1000 m", {at("fb.png")});
    for (auto &c : j["rectangle"]["corners"])
        for (auto &x : c) x = x.get<double>() * 1e297;
    writeBytes(at("far.json"), j.dump());
    fs::create_directories(dir_ / "caps");
    for (const char *f : {"rgb.png", "depth.png", "camera.yaml"}) fs::copy_file(sim_ / f, dir_ / "caps" / f);
    refused("verify --calib " + sim("calib.yaml") + " --detection " + at("far.json") + " --framebuffer " +
                sim("rgb.png") + " --captures " + at("caps") + " --json " + at("v.json"),
            at("far.json"), "more than 1000 m", {at("v.json")});
    // Behind the camera: correct refused it as behind the projector, verify compared it.
    for (auto &c : j["rectangle"]["corners"]) {
        for (auto &x : c) x = x.get<double>() / 1e300;  // metres again
        c[2] = -c[2].get<double>();
    }
    writeBytes(at("behind.json"), j.dump());
    refused("verify --calib " + sim("calib.yaml") + " --detection " + at("behind.json") + " --framebuffer " +
                sim("rgb.png") + " --captures " + at("caps") + " --json " + at("v.json"),
            at("behind.json"), "behind the camera", {at("v.json")});
    // Made with another projector: this one, turned 60 deg to the left, cannot light it.
    ASSERT_EQ(cli("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --image " +
                      sim("rgb.png") + " --out " + at("fb.png"),
                  dir_)
                  .status,
              0);
    writeBytes(at("turned.yaml"),
               "projector:\n  resolution: [1280, 800]\n  fov_deg: [39.3, 24.0]\n  axis:\n"
               "    origin: [0.0, 0.12, 0.0]\n    direction: [-0.866, 0.0, 0.5]\n");
    refused("verify --calib " + at("turned.yaml") + " --detection " + at("det.json") + " --framebuffer " +
                at("fb.png") + " --captures " + at("caps") + " --json " + at("v.json"),
            at("det.json"), "does not fit this calibration", {at("v.json")});
}

TEST_F(Hostile, DeeplyNestedProcamXmlIsRefusedBeforeOpenCvParsesIt) {
    // 50,000 nested elements crashed OpenCV's recursive XML parser (SIGSEGV).
    fs::create_directories(dir_ / "procam");
    std::string xml = "<?xml version=\"1.0\"?>\n<opencv_storage>";
    for (int i = 0; i < 50000; ++i) xml += "<a>";
    for (int i = 0; i < 50000; ++i) xml += "</a>";
    writeBytes(dir_ / "procam" / "calibration_result.xml", xml + "</opencv_storage>\n");
    const std::string path = (dir_ / "procam" / "calibration_result.xml").string();
    refused("eval --no-progress --procam " + at("procam") + " --out " + at("e"), path, "nested deeper than 64");
}

TEST_F(Hostile, ProcamXmlMatrixOfAHugeDeclaredSizeIsRefusedBeforeItIsAllocated) {
    // A flipped bit in a matrix's rows asked OpenCV for 48 GB (found by fuzz_procam_xml).
    fs::create_directories(dir_ / "procam");
    writeBytes(dir_ / "procam" / "calibration_result.xml",
               "<?xml version=\"1.0\"?>\n<opencv_storage>\n<cam_int type_id=\"opencv-matrix\">\n"
               "<rows>1073741827</rows><cols>3</cols><dt>d</dt><data>1 0 0 0 1 0 0 0 1</data></cam_int>\n"
               "</opencv_storage>\n");
    const std::string path = (dir_ / "procam" / "calibration_result.xml").string();
    refused("eval --no-progress --procam " + at("procam") + " --out " + at("e"), path, "matrix 'cam_int'");
}

TEST_F(Hostile, ProcamXmlCutShortOrWithoutItsStorageElementIsRefusedBeforeOpenCvReadsIt) {
    // OpenCV's XML reader read through a null pointer on a header cut short (found by
    // fuzz_procam_xml): only a whole document reaches it.
    fs::create_directories(dir_ / "procam");
    const std::string path = (dir_ / "procam" / "calibration_result.xml").string();
    writeBytes(dir_ / "procam" / "calibration_result.xml", "<?xml versi=");
    refused("eval --no-progress --procam " + at("procam") + " --out " + at("e"), path, "<?xml ...?> header");
    writeBytes(dir_ / "procam" / "calibration_result.xml",
               "<?xml version=\"1.0\"?>\n<opencv_storage>\n<cam_int type_id=\"opencv-matrix\">\n");
    refused("eval --no-progress --procam " + at("procam") + " --out " + at("e"), path, "<opencv_storage> element");
}

TEST_F(Hostile, SequenceFramesAndBagFramesThatAreNoFilesAreNamed) {
    // A FIFO where a frame belongs ended the sequence there (a 1-frame video, exit 0) or was
    // skipped by bag; a missing number still ends a sequence.
    const CliRun det = cli(detectArgs(sim("cloud.pcd")) + " --json " + at("det.json"), dir_);
    ASSERT_EQ(det.status, 0) << det.err;
    fs::create_directories(dir_ / "seq");
    fs::copy_file(sim_ / "rgb.png", dir_ / "seq" / "f_000.png");
    ASSERT_EQ(::mkfifo((dir_ / "seq" / "f_001.png").c_str(), 0600), 0);
    fs::copy_file(sim_ / "rgb.png", dir_ / "seq" / "f_002.png");
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --video " +
                at("seq/f_%03d.png") + " --out " + at("v.avi"),
            (dir_ / "seq" / "f_001.png").string(), "FIFO", {at("v.avi")});
    fs::create_directories(dir_ / "depths");
    fs::copy_file(sim_ / "depth.png", dir_ / "depths" / "d0.png");
    fs::create_directories(dir_ / "depths" / "d1.png");
    refused("bag --depth-dir " + at("depths") + " --camera " + sim("camera.yaml") + " --out " + at("o.bag"),
            (dir_ / "depths" / "d1.png").string(), "is a directory", {at("o.bag")});
    // Strings bag writes into the bag are UTF-8, as every reader of it needs.
    fs::remove(dir_ / "depths" / "d1.png");
    refused("bag --depth-dir " + at("depths") + " --camera " + sim("camera.yaml") + " --out " + at("o.bag") +
                " --frame-id \"$(printf '\\377')\"",
            "--frame-id", "UTF-8", {at("o.bag")});
    // A frame rate no video writer takes: named as the option, not as the output.
    refused("correct --calib " + sim("calib.yaml") + " --detection " + at("det.json") + " --video " +
                at("seq/f_%03d.png") + " --out " + at("v.avi") + " --fps 1e-300",
            "--fps", "0.01-1000 Hz", {at("v.avi")});
}

TEST_F(Hostile, CalibrateFovInRadiansIsRefusedBeforeWriting) {
    // Accepted before, it wrote a calibration every reader refuses.
    refused("calibrate --captures " + sim("captures") + " --out " + at("c.yaml") + " --fov-deg 0.6,0.4", "--fov-deg",
            "looks like radians", {at("c.yaml")});
}

TEST_F(Hostile, LabelFramesArePlainNamesAndPolygonsNearTheImage) {
    const std::string label =
        test::slurp(std::string(PROJSURF_SOURCE_DIR) + "/labels/real/check/chimso_classroom_whiteboard.yaml");
    const std::string frame = "frame: chimso_classroom_whiteboard";
    ASSERT_NE(label.find(frame), std::string::npos);
    fs::create_directories(dir_ / "labels");
    const std::string path = (dir_ / "labels" / "chimso_classroom_whiteboard.yaml").string();
    std::string bad = label;
    bad.replace(bad.find(frame), frame.size(), "frame: ../../../../etc");
    writeBytes(path, bad);
    fs::create_directories(dir_ / "real");  // the label is refused before any frame is looked for (no ../shared)
    const std::string eval = "eval --no-progress --labelled-only --labels " + at("labels") + " --real-dir " +
                             at("real") + " --out " + at("e");
    refused(eval, path, "not a path");
    bad = label;
    const std::size_t poly = bad.find("polygon: [[0, 0]");
    ASSERT_NE(poly, std::string::npos);
    bad.replace(poly, std::string("polygon: [[0, 0]").size(), "polygon: [[1e300, 0]");
    writeBytes(path, bad);
    refused(eval, path, "100000 px");
}
