// The calibrate, correct and show commands end to end: synthetic captures -> calibration YAML,
// detection JSON + picture/video -> framebuffer, framebuffer -> full screen under Xvfb.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <random>
#include <sstream>
#include <thread>

#include "cli_fixtures.hpp"
#include "cli_run.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "synthetic_rig.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {

cv::Mat quadrantPicture(int w, int h) {
    cv::Mat pic(h, w, CV_8UC3);
    pic(cv::Rect(0, 0, w / 2, h / 2)).setTo(cv::Scalar(255, 0, 0));
    pic(cv::Rect(w / 2, 0, w - w / 2, h / 2)).setTo(cv::Scalar(0, 255, 0));
    pic(cv::Rect(w / 2, h / 2, w - w / 2, h - h / 2)).setTo(cv::Scalar(0, 0, 255));
    pic(cv::Rect(0, h / 2, w / 2, h - h / 2)).setTo(cv::Scalar(255, 255, 255));
    return pic;
}

/// Files left in `dir` whose name contains ".tmp" (a partial output).
int leftovers(const fs::path &dir) {
    int n = 0;
    for (const auto &e : fs::recursive_directory_iterator(dir))
        if (e.path().filename().string().find(".tmp") != std::string::npos) ++n;
    return n;
}

}  // namespace

namespace {

/// `calibrate` refuses, with one line naming the problem and no output file: a capture without
/// a disc, depth missing at the disc, too few captures, all at one distance, missing files, bad
/// flags. `caps` are the good captures of the synthetic walls, in `good`.
void checkCalibrateRefusals(const fs::path &dir, const fs::path &good, const std::vector<CaptureImages> &caps,
                            std::mt19937 &rng) {
    const Projector truth = rig::trueProjector();
    const CameraIntrinsics cam;
    const auto walls = rig::calibrationWalls();
    auto refuse = [&](const std::string &args, const std::string &needle) {
        const std::string target = (dir / "refused.yaml").string();
        const CliRun rr = cli("calibrate " + args + " --out " + target, dir);
        EXPECT_EQ(rr.status, 2) << args << "\n" << rr.err;
        EXPECT_NE(rr.err.find(needle), std::string::npos) << "expected '" << needle << "' in: " << rr.err;
        EXPECT_EQ(std::count(rr.err.begin(), rr.err.end(), '\n'), 1) << rr.err;
        EXPECT_FALSE(fs::exists(target));
    };
    // A capture without a disc: named.
    const fs::path nodisc = dir / "nodisc";
    fs::create_directories(nodisc);
    auto bad = caps;
    rig::CaptureOptions none;
    none.no_disc = true;
    bad[3] = rig::renderCapture(truth, walls[3], cam, rng, none);
    writeCaptures(nodisc, bad);
    refuse("--captures " + nodisc.string(), "capture_3_rgb.png: no projected disc found");
    // Depth missing at the disc: the depth file is named.
    const fs::path nodepth = dir / "nodepth";
    fs::create_directories(nodepth);
    bad = caps;
    rig::CaptureOptions holes;
    holes.drop_disc_depth = true;
    bad[1] = rig::renderCapture(truth, walls[1], cam, rng, holes);
    writeCaptures(nodepth, bad);
    refuse("--captures " + nodepth.string(), "capture_1_depth.png: depth missing at the disc");
    // Too few captures.
    const fs::path few = dir / "few";
    fs::create_directories(few);
    writeCaptures(few, std::vector<CaptureImages>(caps.begin(), caps.begin() + 2));
    refuse("--captures " + few.string(), "need at least 3");
    // All at one distance.
    const fs::path flat = dir / "flat";
    fs::create_directories(flat);
    std::vector<CaptureImages> same;
    for (double a : {0.0, 4.0, -4.0}) same.push_back(rig::renderCapture(truth, rig::wall(2.0, a), cam, rng));
    writeCaptures(flat, same);
    refuse("--captures " + flat.string(), "take them at different distances");
    // Missing camera.yaml, a missing depth file, a gap in the numbering, bad flags.
    fs::remove(few / "camera.yaml");
    refuse("--captures " + few.string(), "camera.yaml: no such file");
    const fs::path gap = dir / "gap";
    fs::create_directories(gap);
    writeCaptures(gap, caps);
    fs::remove(gap / "capture_2_depth.png");
    refuse("--captures " + gap.string(), "capture_2_depth.png: no such file");
    fs::remove(gap / "capture_2_rgb.png");
    refuse("--captures " + gap.string(), "capture_2_rgb.png: missing");
    refuse("--captures " + (dir / "nowhere").string(), "not a directory");
    refuse("--captures " + good.string() + " --fov-deg 39.3", "--fov-deg");
    refuse("--captures " + good.string() + " --resolution 12.5,800", "--resolution");
    cv::imwrite((nodisc / "capture_0_depth.png").string(), cv::Mat(480, 640, CV_8UC1, cv::Scalar(9)));
    refuse("--captures " + nodisc.string(), "capture_0_depth.png: expected a 16-bit");
}

}  // namespace

TEST(CliCalibrate, SyntheticCapturesToYamlAndRefusals) {
    const fs::path dir = freshDir("calibrate");
    const Projector truth = rig::trueProjector();
    const CameraIntrinsics cam;
    std::mt19937 rng(31);
    const auto walls = rig::calibrationWalls();
    std::vector<CaptureImages> caps;
    for (const Plane &w : walls) caps.push_back(rig::renderCapture(truth, w, cam, rng));
    const fs::path good = dir / "good";
    fs::create_directories(good);
    writeCaptures(good, caps);

    const std::string out = (dir / "calib.yaml").string();
    CliRun r = cli("calibrate --captures " + good.string() + " --out " + out, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("residual"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("capture_4_rgb.png"), std::string::npos) << r.out;
    const Projector p = readCalibration(out);  // the contract's reader accepts it
    EXPECT_LT(angleBetweenDeg(p.direction, truth.direction), 0.5);
    EXPECT_LT((p.origin - truth.origin).norm(), 0.03);
    EXPECT_EQ(p.width, 1280);
    EXPECT_NEAR(p.fov_h * 180 / M_PI, 39.3, 1e-9);
    const YAML::Node y = YAML::LoadFile(out);
    ASSERT_TRUE(y["calibration"]["captures"].IsSequence());
    EXPECT_EQ(y["calibration"]["captures"].size(), 5u);
    EXPECT_TRUE(y["calibration"]["captures"][0]["residual_m"]);
    EXPECT_TRUE(y["calibration"]["fit"]["rms_residual_m"]);
    EXPECT_EQ(y["calibration"]["fit"]["verdict"].as<std::string>(), "good");
    EXPECT_EQ(y["calibration"]["threshold"].as<int>(), 50);
    EXPECT_EQ(y["projector"]["corner_rays"]["pinhole"].size(), 4u);
    EXPECT_EQ(y["projector"]["corner_rays"]["paper"].size(), 4u);

    // Flags: field of view, resolution, threshold.
    const std::string out2 = (dir / "calib2.yaml").string();
    r = cli("calibrate --captures " + good.string() + " --out " + out2 +
                " --fov-deg 40,25 --resolution 1920,1080 --threshold 60",
            dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const Projector p2 = readCalibration(out2);
    EXPECT_EQ(p2.width, 1920);
    EXPECT_NEAR(p2.fov_v * 180 / M_PI, 25.0, 1e-9);

    // A second, smaller bright blob (a lamp): the disc is still used, with a warning.
    const fs::path lamp = dir / "lamp";
    fs::create_directories(lamp);
    auto with_lamp = caps;
    with_lamp[2].color = caps[2].color.clone();
    cv::circle(with_lamp[2].color, cv::Point(40, 40), 8, cv::Scalar(255, 255, 255), -1);
    writeCaptures(lamp, with_lamp);
    r = cli("calibrate --captures " + lamp.string() + " --out " + (dir / "calib3.yaml").string(), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("capture_2_rgb.png: 2 bright blobs"), std::string::npos) << r.err;
    EXPECT_LT(angleBetweenDeg(readCalibration((dir / "calib3.yaml").string()).direction, truth.direction), 0.5);

    checkCalibrateRefusals(dir, good, caps, rng);
    if (!HasFailure()) fs::remove_all(dir);
}

TEST(CliCorrect, PictureToFramebufferJsonAndBadInputs) {
    const fs::path dir = freshDir("correct");
    const Projector truth = rig::trueProjector();
    writeCalibration((dir / "calib.yaml").string(), truth);
    const Plane wall = rig::wall(2.0, 17.19);
    const Rectangle rect = rig::rectangleInWorkspace(truth, wall);
    writeDetection(dir / "det.json", rect, wall);
    cv::imwrite((dir / "in.png").string(), quadrantPicture(640, 480));
    const std::string base = "correct --calib " + (dir / "calib.yaml").string() + " --detection " +
                             (dir / "det.json").string() + " --image " + (dir / "in.png").string();

    CliRun r = cli(base + " --out " + (dir / "fb.png").string() + " --json " + (dir / "fb.json").string(), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const cv::Mat fb = cv::imread((dir / "fb.png").string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(fb.cols, 1280);
    ASSERT_EQ(fb.rows, 800);
    ASSERT_EQ(fb.type(), CV_8UC3);
    const auto j = nlohmann::json::parse(slurp((dir / "fb.json").string()));
    ASSERT_EQ(j["homography"].size(), 3u);
    ASSERT_EQ(j["framebuffer_corners"].size(), 4u);
    const auto k = computeKeystone(truth, rect, cv::Size(640, 480));
    ASSERT_TRUE(k.keystone);
    Corners3 onwall;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d px(j["framebuffer_corners"][i][0].get<double>(),
                                 j["framebuffer_corners"][i][1].get<double>());
        EXPECT_LT((px - k.keystone->picture_px[i]).norm(), 1e-6);
        onwall[i] = *castToWall(truth, px, wall);
    }
    // Cast back onto the wall: an undistorted 4:3 picture.
    const auto e = shapeErrors(onwall);
    EXPECT_LT(e.worst_pct(), 1e-6);
    EXPECT_NEAR(e.top / e.left, 4.0 / 3.0, 1e-6);
    // The framebuffer: corners black, each quadrant's colour where the homography puts it.
    EXPECT_EQ(fb.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
    EXPECT_EQ(fb.at<cv::Vec3b>(799, 1279), cv::Vec3b(0, 0, 0));
    const cv::Matx33d H(j["homography"][0][0], j["homography"][0][1], j["homography"][0][2], j["homography"][1][0],
                        j["homography"][1][1], j["homography"][1][2], j["homography"][2][0], j["homography"][2][1],
                        j["homography"][2][2]);
    const cv::Vec3d q = H * cv::Vec3d(480, 360, 1);  // centre of the red (BGR 0,0,255) quadrant
    EXPECT_EQ(fb.at<cv::Vec3b>(static_cast<int>(std::lround(q[1] / q[2])), static_cast<int>(std::lround(q[0] / q[2]))),
              cv::Vec3b(0, 0, 255));

    auto refuse = [&](const std::string &args, const std::string &needle) {
        const std::string target = (dir / "refused.png").string();
        const CliRun rr = cli(args + " --out " + target, dir);
        EXPECT_EQ(rr.status, 2) << args << "\n" << rr.err;
        EXPECT_NE(rr.err.find(needle), std::string::npos) << "expected '" << needle << "' in: " << rr.err;
        EXPECT_FALSE(fs::exists(target));
    };
    refuse("correct --calib " + (dir / "nope.yaml").string() + " --detection " + (dir / "det.json").string() +
               " --image " + (dir / "in.png").string(),
           "nope.yaml: no such file");
    refuse("correct --calib " + (dir / "calib.yaml").string() + " --detection " + (dir / "det.json").string() +
               " --image " + (dir / "missing.png").string(),
           "missing.png: no such file");
    std::ofstream(dir / "junk.png") << "not a picture";
    refuse("correct --calib " + (dir / "calib.yaml").string() + " --detection " + (dir / "det.json").string() +
               " --image " + (dir / "junk.png").string(),
           "junk.png: not a readable image");
    std::ofstream(dir / "notfound.json") << R"({"found": false, "reason": "no vertical plane"})";
    refuse("correct --calib " + (dir / "calib.yaml").string() + " --detection " + (dir / "notfound.json").string() +
               " --image " + (dir / "in.png").string(),
           "found no surface");
    // A rectangle beyond the projector's reach: refused, not clipped.
    writeDetection(dir / "big.json", rig::rectangleInWorkspace(truth, wall, 1.4), wall);
    refuse("correct --calib " + (dir / "calib.yaml").string() + " --detection " + (dir / "big.json").string() +
               " --image " + (dir / "in.png").string(),
           "leaves the projector's framebuffer");
    refuse(base + " --json " + (dir / "nodir" / "x.json").string(), "output directory does not exist");
    const CliRun bad_ext = cli(base + " --out " + (dir / "fb.xyz").string(), dir);
    EXPECT_EQ(bad_ext.status, 2);
    EXPECT_FALSE(fs::exists(dir / "fb.xyz"));
    EXPECT_EQ(leftovers(dir), 0);
    if (!HasFailure()) fs::remove_all(dir);
}

namespace {

/// Writes a 12-frame 320x240 MJPG video of a bright bar moving across a quadrant picture; false
/// when this OpenCV cannot write one.
bool writeMovingBarVideo(const std::string &path) {
    cv::VideoWriter w(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, cv::Size(320, 240));
    if (!w.isOpened()) return false;
    for (int f = 0; f < 12; ++f) {
        cv::Mat pic = quadrantPicture(320, 240);
        pic(cv::Rect(20 * f, 0, 20, 240)).setTo(cv::Scalar(255, 255, 255));
        w.write(pic);
    }
    return true;
}

}  // namespace

TEST(CliCorrect, VideoAndImageSequenceFrameByFrame) {
    const fs::path dir = freshDir("correct_video");
    const Projector truth = rig::trueProjector();
    writeCalibration((dir / "calib.yaml").string(), truth);
    const Plane wall = rig::wall(1.5, -12.06);
    writeDetection(dir / "det.json", rig::rectangleInWorkspace(truth, wall), wall);
    // An input video: 12 frames, 320x240, a bright bar moving across a quadrant picture.
    const std::string in = (dir / "in.avi").string();
    ASSERT_TRUE(writeMovingBarVideo(in)) << "this OpenCV cannot write MJPG .avi";
    const std::string base =
        "correct --calib " + (dir / "calib.yaml").string() + " --detection " + (dir / "det.json").string();
    CliRun r =
        cli(base + " --image " + in + " --out " + (dir / "out.avi").string() + " --json " + (dir / "out.json").string(),
            dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("100%"), std::string::npos) << r.out;  // the progress (on stdout in a log)
    EXPECT_EQ(r.err, "");                                       // stderr: failures only
    cv::VideoCapture cap((dir / "out.avi").string());
    ASSERT_TRUE(cap.isOpened());
    int frames = 0;
    cv::Mat f;
    const auto j = nlohmann::json::parse(slurp((dir / "out.json").string()));
    EXPECT_EQ(j["picture"]["width"], 320);
    while (cap.read(f)) {
        ++frames;
        EXPECT_EQ(f.cols, 1280);
        EXPECT_EQ(f.rows, 800);
        EXPECT_LT(cv::norm(f.at<cv::Vec3b>(5, 5)), 30.0);  // black outside (MJPG is lossy)
    }
    EXPECT_EQ(frames, 12);

    // An image sequence in, an image sequence out.
    fs::create_directories(dir / "frames");
    fs::create_directories(dir / "outframes");
    for (int i = 0; i < 4; ++i) {
        char name[64];
        std::snprintf(name, sizeof name, "%03d.png", i);
        cv::Mat pic = quadrantPicture(400, 300);
        pic(cv::Rect(60 * i, 0, 30, 300)).setTo(cv::Scalar(255, 255, 255));  // each frame different
        cv::imwrite((dir / "frames" / name).string(), pic);
    }
    r = cli(base + " --video " + (dir / "frames" / "%03d.png").string() + " --out " +
                (dir / "outframes" / "f%03d.png").string(),
            dir);
    ASSERT_EQ(r.status, 0) << r.err;
    for (int i = 0; i < 4; ++i) {
        char name[64];
        std::snprintf(name, sizeof name, "f%03d.png", i);
        const cv::Mat o = cv::imread((dir / "outframes" / name).string());
        ASSERT_FALSE(o.empty()) << name;
        EXPECT_EQ(o.size(), cv::Size(1280, 800));
        // The same framebuffer as correcting that frame alone (one warper for the whole
        // sequence, its output buffer reused from frame to frame).
        std::snprintf(name, sizeof name, "%03d.png", i);
        const fs::path single = dir / ("single" + std::to_string(i) + ".png");
        r = cli(base + " --image " + (dir / "frames" / name).string() + " --out " + single.string(), dir);
        ASSERT_EQ(r.status, 0) << r.err;
        const cv::Mat s = cv::imread(single.string());
        ASSERT_EQ(s.size(), o.size());
        EXPECT_EQ(cv::norm(o, s, cv::NORM_INF), 0.0) << "frame " << i;
    }

    // Refusals leave nothing behind.
    r = cli(base + " --image " + in + " --out " + (dir / "out.txt").string(), dir);
    EXPECT_EQ(r.status, 2);
    std::ofstream(dir / "junk.mp4") << "not a video";
    r = cli(base + " --image " + (dir / "junk.mp4").string() + " --out " + (dir / "junk_out.avi").string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("junk.mp4: not a readable video"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "junk_out.avi"));
    r = cli(base + " --video " + (dir / "frames" / "%03d.png").string() + " --out " +
                (dir / "outframes" / "%s.png").string(),
            dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(leftovers(dir), 0);
    if (!HasFailure()) fs::remove_all(dir);
}

namespace {

/// Reads an X window dump (xwd, ZPixmap, 24/32 bits per pixel) into a BGR image.
cv::Mat readXwd(const std::string &path) {
    const std::string b = slurp(path);
    if (b.size() < 100) return {};
    auto u32 = [&](std::size_t off) {
        return (static_cast<uint32_t>(static_cast<uint8_t>(b[off])) << 24) |
               (static_cast<uint32_t>(static_cast<uint8_t>(b[off + 1])) << 16) |
               (static_cast<uint32_t>(static_cast<uint8_t>(b[off + 2])) << 8) |
               static_cast<uint32_t>(static_cast<uint8_t>(b[off + 3]));
    };
    const uint32_t header = u32(0), format = u32(8), width = u32(16), height = u32(20), byte_order = u32(28),
                   bpp = u32(44), bpl = u32(48), rmask = u32(56), gmask = u32(60), bmask = u32(64), ncolors = u32(76);
    if (format != 2 || (bpp != 32 && bpp != 24)) return {};
    const std::size_t data = header + 12ull * ncolors;
    if (b.size() < data + static_cast<std::size_t>(bpl) * height) return {};
    auto shift = [](uint32_t m) {
        int s = 0;
        while (m && !(m & 1)) m >>= 1, ++s;
        return s;
    };
    cv::Mat img(static_cast<int>(height), static_cast<int>(width), CV_8UC3);
    const int bytes = static_cast<int>(bpp / 8);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const std::size_t off = data + static_cast<std::size_t>(y) * bpl + x * bytes;
            uint32_t pix = 0;
            for (int i = 0; i < bytes; ++i) {
                const uint32_t byte = static_cast<uint8_t>(b[off + i]);
                pix |= byte_order == 0 ? byte << (8 * i) : byte << (8 * (bytes - 1 - i));
            }
            img.at<cv::Vec3b>(static_cast<int>(y), static_cast<int>(x)) = cv::Vec3b(
                static_cast<uchar>((pix & bmask) >> shift(bmask)), static_cast<uchar>((pix & gmask) >> shift(gmask)),
                static_cast<uchar>((pix & rmask) >> shift(rmask)));
        }
    return img;
}

bool onPath(const std::string &tool) { return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0; }

/// The first X display number from 91 on with neither a socket nor a lock file.
int freeDisplayNumber() {
    int n = 0;
    for (n = 91; n < 200; ++n)
        if (!fs::exists("/tmp/.X11-unix/X" + std::to_string(n)) && !fs::exists("/tmp/.X" + std::to_string(n) + "-lock"))
            break;
    return n;
}

/// Starts Xvfb on `display` with screen 0 at 640x480 and screen 1 at 1280x800, its output to
/// /dev/null; directly (not through a shell) so that it can be stopped and reaped by its pid,
/// set in `pid`. Returns posix_spawnp's result (0 when started).
int spawnTwoScreenXvfb(const std::string &display, pid_t &pid) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> args = {"Xvfb",    display, "-screen",     "0",         "640x480x24",
                                     "-screen", "1",     "1280x800x24", "-nolisten", "tcp"};
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int spawned = posix_spawnp(&pid, "Xvfb", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return spawned;
}

/// Stops a child process when it goes out of scope: SIGTERM, up to 5 s to exit, then SIGKILL;
/// reaped either way.
struct StopOnExit {
    pid_t pid;
    ~StopOnExit() {
        ::kill(pid, SIGTERM);
        for (int i = 0; i < 50 && ::waitpid(pid, nullptr, WNOHANG) == 0; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (::waitpid(pid, nullptr, WNOHANG) == 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, nullptr, 0);
        }
    }
};

}  // namespace

TEST(CliShow, FramebufferFullScreenUnderXvfb) {
    if (!onPath("Xvfb") || !onPath("xwd"))
        GTEST_SKIP() << "Xvfb or xwd not installed (apt-get install xvfb x11-apps; see scripts/setup.sh)";
    const fs::path dir = freshDir("show");
    // A framebuffer with distinct coloured blocks, of the screen's size.
    cv::Mat fb(800, 1280, CV_8UC3, cv::Scalar(0, 0, 0));
    fb(cv::Rect(100, 100, 400, 200)).setTo(cv::Scalar(0, 0, 255));
    fb(cv::Rect(700, 400, 500, 300)).setTo(cv::Scalar(0, 255, 0));
    fb(cv::Rect(0, 0, 60, 60)).setTo(cv::Scalar(255, 0, 0));
    fb(cv::Rect(1220, 740, 60, 60)).setTo(cv::Scalar(255, 255, 255));
    cv::imwrite((dir / "fb.png").string(), fb);

    const int n = freeDisplayNumber();
    const std::string display = ":" + std::to_string(n);
    // Two screens, as on a robot whose projector is a second output: the picture must go to
    // screen 1 (the framebuffer's size) and leave screen 0 alone.
    pid_t xvfb = 0;
    const int spawned = spawnTwoScreenXvfb(display, xvfb);
    ASSERT_EQ(spawned, 0) << "cannot start Xvfb";
    const StopOnExit killer{xvfb};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!fs::exists("/tmp/.X11-unix/X" + std::to_string(n)) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_TRUE(fs::exists("/tmp/.X11-unix/X" + std::to_string(n))) << "Xvfb did not start on " << display;

    CliRun shown;
    std::thread show([&] {
        shown =
            cli("show --image " + (dir / "fb.png").string() + " --display " + display + " --screen-index 1 --seconds 4",
                dir);
    });
    // Screenshot after the window had time to appear (bounded: retry for up to ~8 s).
    cv::Mat shot;
    double best = 1e9;
    for (int attempt = 0; attempt < 8; ++attempt) {
        std::this_thread::sleep_for(std::chrono::milliseconds(attempt == 0 ? 1500 : 300));
        const std::string xwd = (dir / "shot.xwd").string();
        if (std::system(("timeout 10 xwd -root -silent -display " + display + ".1 > " + xwd).c_str()) != 0) continue;
        shot = readXwd(xwd);
        if (shot.size() != fb.size()) continue;
        cv::Mat diff;
        cv::absdiff(shot, fb, diff);
        best = cv::mean(diff)[0] + cv::mean(diff)[1] + cv::mean(diff)[2];
        if (best < 1.0) break;
    }
    // Meanwhile screen 0 stays black: nothing was shown there.
    const std::string xwd0 = (dir / "shot0.xwd").string();
    const int xwd0_status = std::system(("timeout 10 xwd -root -silent -display " + display + ".0 > " + xwd0).c_str());
    show.join();  // (no ASSERT before this: the thread must be joined)
    EXPECT_EQ(xwd0_status, 0);
    const cv::Mat shot0 = readXwd(xwd0);
    EXPECT_EQ(shot0.size(), cv::Size(640, 480));
    if (!shot0.empty()) {
        EXPECT_EQ(cv::countNonZero(shot0.reshape(1)), 0);
    }
    ASSERT_EQ(shot.size(), fb.size()) << "no screenshot of " << display;
    EXPECT_EQ(shown.status, 0) << shown.err;
    // The whole screen shows the framebuffer, pixel for pixel.
    EXPECT_LT(best, 1.0) << "mean absolute difference between screen and framebuffer";
    EXPECT_EQ(shot.at<cv::Vec3b>(200, 300), cv::Vec3b(0, 0, 255));
    EXPECT_EQ(shot.at<cv::Vec3b>(550, 950), cv::Vec3b(0, 255, 0));
    EXPECT_EQ(shot.at<cv::Vec3b>(10, 10), cv::Vec3b(255, 0, 0));
    EXPECT_EQ(shot.at<cv::Vec3b>(790, 1270), cv::Vec3b(255, 255, 255));
    cv::imwrite((dir / "shot.png").string(), shot);

    // No display: a clear refusal.
    const CliRun none = cli("show --image " + (dir / "fb.png").string() + " --display :199 --seconds 1", dir);
    EXPECT_EQ(none.status, 2) << none.err;
    EXPECT_NE(none.err.find("cannot open this X display"), std::string::npos) << none.err;
    const CliRun missing = cli("show --image " + (dir / "nope.png").string() + " --display " + display, dir);
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("nope.png: no such file"), std::string::npos) << missing.err;
    if (!HasFailure()) fs::remove_all(dir);
}
