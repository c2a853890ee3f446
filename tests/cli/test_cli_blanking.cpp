// `projsurf correct ... --cloud now.pcd | --depth now.png --camera camera.yaml` (contract
// "Blanking"): the pixels that would light a person standing in the beam are black, and the
// JSON says how many.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_run.hpp"
#include "eval/demo/walk_in.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/render/test_card.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/formats/detection_json.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

using namespace projsurf::eval;  // the evaluation under test

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::test;

TEST(CliBlanking, CorrectBlanksThePersonInTheBeam) {
    const fs::path dir = freshDir("people_cli_blanking");
    const Projector projector = sim::exampleProjector();
    const sim::Scenario sc = sim::makeScenario("wall", 2.5, 10.0);
    const sim::RgbdFrame empty = sim::renderFrame(sc.scene, sim::SensorModel(), 1);
    DetectorConfig cfg;
    const Detection det = detectSurface(empty.cloud, projector, cfg, sc.gravity);
    ASSERT_TRUE(det.found);
    writeCalibration((dir / "calib.yaml").string(), projector);
    writeFileAtomic((dir / "det.json").string(), detectionToJson(det, cfg, &projector).dump(2));
    cv::imwrite((dir / "card.png").string(), frontend::testCard(cv::Size(640, 400)));
    const sim::Scene with_person = eval::walkInScenes(sc.scene, -0.5, -0.5, 1, 1.4)[0];
    const sim::RgbdFrame now = sim::renderFrame(with_person, sim::SensorModel(), 2);
    writeCloudPcd((dir / "now.pcd").string(), now.cloud);
    writeCloudPcd((dir / "empty.pcd").string(), empty.cloud);
    cv::imwrite((dir / "now.png").string(), now.depth);
    writeCamera((dir / "camera.yaml").string(), sim::SensorModel().camera);

    const std::string base = "correct --calib " + (dir / "calib.yaml").string() + " --detection " +
                             (dir / "det.json").string() + " --image " + (dir / "card.png").string();
    auto run = [&](const std::string &name, const std::string &extra) {
        const auto r = cli(base + " --out " + (dir / (name + ".png")).string() + " --json " +
                               (dir / (name + ".json")).string() + " " + extra,
                           dir);
        EXPECT_EQ(r.status, 0) << r.err;
        return nlohmann::json::parse(slurp(dir / (name + ".json")));
    };
    const nlohmann::json plain = run("plain", "");
    EXPECT_FALSE(plain.contains("blanked_pixels"));  // the contract's keys only, as before
    const nlohmann::json blanked = run("blanked", "--cloud " + (dir / "now.pcd").string());
    ASSERT_TRUE(blanked.contains("blanked_pixels"));
    const int n = blanked["blanked_pixels"].get<int>();
    EXPECT_GT(n, 50000);
    // The pixels it blacked out were lit before, and are no more than it counted.
    const cv::Mat a = cv::imread((dir / "plain.png").string()), b = cv::imread((dir / "blanked.png").string());
    cv::Mat ga, gb;
    cv::cvtColor(a, ga, cv::COLOR_BGR2GRAY);
    cv::cvtColor(b, gb, cv::COLOR_BGR2GRAY);
    const int darkened = cv::countNonZero((ga > 0) & (gb == 0));
    EXPECT_GT(darkened, n / 4);
    EXPECT_LE(darkened, n);
    // No lit pixel lands on the person.
    const eval::BeamScore s = eval::scoreBlanking(with_person, sc.wall, projector, a, b);
    EXPECT_GT(s.on_person, 10000);
    EXPECT_EQ(s.lit_on_person, 0);
    // The depth PNG gives the same answer within the millimetre rounding.
    const nlohmann::json from_depth =
        run("depth", "--depth " + (dir / "now.png").string() + " --camera " + (dir / "camera.yaml").string());
    EXPECT_NEAR(from_depth["blanked_pixels"].get<double>(), n, 0.02 * n);
    // The empty wall blanks nothing.
    EXPECT_EQ(run("empty", "--cloud " + (dir / "empty.pcd").string())["blanked_pixels"].get<int>(), 0);
    fs::remove_all(dir);
}

TEST(CliBlanking, BadArgumentsAreOneClearLine) {
    const fs::path dir = freshDir("people_cli_blanking_bad");
    writeCalibration((dir / "calib.yaml").string(), sim::exampleProjector());
    const sim::Scenario sc = sim::makeScenario("wall", 2.0, 0.0);
    const sim::RgbdFrame f = sim::renderFrame(sc.scene, sim::SensorModel(), 1);
    DetectorConfig cfg;
    const Projector projector = sim::exampleProjector();
    writeFileAtomic((dir / "det.json").string(),
                    detectionToJson(detectSurface(f.cloud, projector, cfg, sc.gravity), cfg, &projector).dump());
    cv::imwrite((dir / "card.png").string(), frontend::testCard(cv::Size(64, 40)));
    const std::string base = "correct --calib " + (dir / "calib.yaml").string() + " --detection " +
                             (dir / "det.json").string() + " --image " + (dir / "card.png").string() + " --out " +
                             (dir / "fb.png").string();
    for (const std::string &extra :
         {std::string("--depth x.png"), std::string("--cloud a.pcd --depth b.png --camera c.yaml"),
          "--cloud " + (dir / "missing.pcd").string()}) {
        const auto r = cli(base + " " + extra, dir);
        EXPECT_EQ(r.status, 2) << extra;
        EXPECT_EQ(r.err.rfind("projsurf: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(dir / "fb.png")) << extra;
    }
    fs::remove_all(dir);
}

TEST(CliBlanking, DemoShowsAPersonWalkingInTheBlankedPictureAndAPlannedMove) {
    const fs::path dir = freshDir("people_demo_walk_in");
    const auto r = cli("demo --out " + (dir / "demo").string() + " --seed 2", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "demo" / "walk_in.png"));
    EXPECT_TRUE(fs::exists(dir / "demo" / "walk_in_compare.png"));
    // Every walk-in frame: no lit pixel on the person, and the last one has them in the beam.
    int frames = 0;
    for (std::size_t at = r.out.find("walk-in frame"); at != std::string::npos;
         at = r.out.find("walk-in frame", at + 1)) {
        const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
        EXPECT_NE(line.find("; 0 of "), std::string::npos) << line;
        ++frames;
    }
    EXPECT_EQ(frames, 3) << r.out;
    const cv::Mat compare = cv::imread((dir / "demo" / "walk_in_compare.png").string());
    EXPECT_GT(compare.cols, compare.rows);
    // And the planned move, with the picture before and after it.
    EXPECT_TRUE(fs::exists(dir / "demo" / "plan.png"));
    EXPECT_NE(r.out.find("plan: move "), std::string::npos) << r.out;
    fs::remove_all(dir);
}
