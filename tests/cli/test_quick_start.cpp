// The quick start's pieces: the example calibration in the repository is the simulator's
// example projector, and `calibrate --write-picture` writes a picture whose disc the
// calibration's own disc finder locates at the principal point.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "cli_run.hpp"
#include "projsurf/calibration/calibration.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

namespace {}  // namespace

TEST(QuickStart, ExampleCalibrationIsTheSimulatorsExampleProjector) {
    const Projector file = readCalibration(std::string(PROJSURF_SOURCE_DIR) + "/examples/calib/example_calib.yaml");
    const Projector sim = sim::exampleProjector();
    EXPECT_EQ(file.width, sim.width);
    EXPECT_EQ(file.height, sim.height);
    EXPECT_NEAR(file.fov_h, sim.fov_h, 1e-12);
    EXPECT_NEAR(file.fov_v, sim.fov_v, 1e-12);
    EXPECT_LT((file.origin - sim.origin).norm(), 1e-12);
    EXPECT_LT((file.direction - sim.direction).norm(), 1e-12);
}

TEST(QuickStart, WritePictureGivesTheDiscAtThePrincipalPoint) {
    const fs::path dir = freshDir("write_picture");
    for (const auto &[w, h] : {std::pair<int, int>{1280, 800}, {1920, 1080}, {854, 480}}) {
        const fs::path png = dir / ("disc_" + std::to_string(w) + ".png");
        const CliRun r = cli("calibrate --write-picture " + png.string() + " --resolution " + std::to_string(w) + "," +
                                 std::to_string(h),
                             dir);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_NE(r.out.find("calibration picture"), std::string::npos) << r.out;
        const cv::Mat picture = cv::imread(png.string(), cv::IMREAD_UNCHANGED);
        ASSERT_EQ(picture.cols, w);
        ASSERT_EQ(picture.rows, h);
        const auto disc = findDisc(picture);
        ASSERT_TRUE(disc.has_value());
        EXPECT_EQ(disc->candidates, 1);
        EXPECT_NEAR(disc->centroid.x(), 0.5 * (w - 1), 0.05);
        EXPECT_NEAR(disc->centroid.y(), 0.5 * (h - 1), 0.05);
        EXPECT_NEAR(disc->radius_px, h / 8.0, 1.0);
        // Black around the disc: the corners of the picture.
        EXPECT_EQ(picture.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
        EXPECT_EQ(picture.at<cv::Vec3b>(h - 1, w - 1), cv::Vec3b(0, 0, 0));
    }
    fs::remove_all(dir);
}

TEST(QuickStart, CalibrateStillNeedsCapturesWithoutWritePicture) {
    const fs::path dir = freshDir("calibrate_args");
    CliRun r = cli("calibrate --out " + (dir / "c.yaml").string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--captures is required"), std::string::npos) << r.err;
    r = cli("calibrate --write-picture " + (dir / "d.png").string() + " --captures " + dir.string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("projsurf: error: --write-picture: only writes the calibration picture"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "d.png"));
    r = cli("calibrate --write-picture " + (dir / "no_such_dir" / "d.png").string(), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    fs::remove_all(dir);
}

TEST(QuickStart, TheReadmeCommandsRunFromAPlainClone) {
    // Only what the repository holds: data/ (a real frame and its calibration).
    const fs::path dir = freshDir("quick_start_clone");
    const std::string src = PROJSURF_SOURCE_DIR, frame = src + "/data/tum_o3d_fr3_office_partition",
                      calib = frame + "/calib.yaml";
    CliRun r = cli("detect --depth " + frame + "/depth.png --camera " + frame + "/camera.yaml --rgb " + frame +
                       "/rgb.png --calib " + calib + " --gravity auto --aspect 16:9 --json " + (dir / "det.json").string() +
                       " --overlay " + (dir / "det.png").string(),
                   dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("found "), std::string::npos) << r.out;
    r = cli("verify --write-card " + (dir / "card.png").string() + " --resolution 1280,720", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    r = cli("correct --calib " + calib + " --detection " + (dir / "det.json").string() + " --image " +
                (dir / "card.png").string() + " --out " + (dir / "framebuffer.png").string(),
            dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const cv::Mat fb = cv::imread((dir / "framebuffer.png").string(), cv::IMREAD_COLOR);
    ASSERT_EQ(fb.cols, 1280);
    ASSERT_EQ(fb.rows, 800);
    EXPECT_GT(cv::countNonZero(fb.reshape(1) > 200), 1000);  // the card is in the framebuffer, lit
    fs::remove_all(dir);
}
