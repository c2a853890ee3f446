// `projsurf detect --explain` on the frame that ships in data/: the candidates in the JSON, the
// lines on stdout and the overlay, and nothing of it without the flag.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_run.hpp"

namespace fs = std::filesystem;
using namespace projsurf::test;

namespace {

const std::string kFrame = std::string(PROJSURF_SOURCE_DIR) + "/data/tum_o3d_fr3_office_partition";

/// detect on the frame with `extra` options, its JSON and overlay in `dir` under `name`.
CliRun detectFrame(const fs::path &dir, const std::string &name, const std::string &extra) {
    return cli("detect --depth " + kFrame + "/depth.png --camera " + kFrame + "/camera.yaml --rgb " + kFrame +
                   "/rgb.png --calib " + kFrame + "/calib.yaml --gravity auto --aspect 16:9 --json " +
                   (dir / (name + ".json")).string() + " --overlay " + (dir / (name + ".png")).string() + " " + extra,
               dir);
}

nlohmann::json readJson(const fs::path &path) { return nlohmann::json::parse(slurp(path)); }

}  // namespace

TEST(CliExplain, CandidatesSayWhyAndChangeNothingElse) {
    const fs::path dir = freshDir("explain");
    const CliRun plain = detectFrame(dir, "plain", "");
    const CliRun explained = detectFrame(dir, "explained", "--explain");
    ASSERT_EQ(plain.status, 0) << plain.err;
    ASSERT_EQ(explained.status, 0) << explained.err;
    nlohmann::json a = readJson(dir / "plain.json"), b = readJson(dir / "explained.json");
    EXPECT_FALSE(a.contains("candidates"));
    ASSERT_TRUE(b.contains("candidates"));
    const nlohmann::json candidates = b["candidates"];
    // Everything else is the same answer.
    a.erase("timing_ms");
    b.erase("timing_ms");
    b.erase("candidates");
    EXPECT_EQ(a, b);
    ASSERT_TRUE(a["found"].get<bool>());
    ASSERT_GE(candidates.size(), 2u);
    int chosen = 0;
    for (const auto &c : candidates) {
        EXPECT_FALSE(c["reason"].get<std::string>().empty());
        EXPECT_GT(c["distance_m"].get<double>(), 0.3);
        EXPECT_GT(c["seen"]["width_m"].get<double>(), 0.0);
        EXPECT_NEAR(c["normal"][0].get<double>() * c["normal"][0].get<double>() +
                        c["normal"][1].get<double>() * c["normal"][1].get<double>() +
                        c["normal"][2].get<double>() * c["normal"][2].get<double>(),
                    1.0, 1e-5);
        if (c["verdict"] == "chosen") {
            ++chosen;
            EXPECT_NEAR(c["rectangle"]["width_m"].get<double>(), a["rectangle"]["width_m"].get<double>(), 1e-9);
            EXPECT_NEAR(c["distance_m"].get<double>(), std::abs(a["plane"]["coefficients"][3].get<double>()), 1e-5);
        }
    }
    EXPECT_EQ(chosen, 1);
    // stdout: the summary, then one line per candidate.
    EXPECT_EQ(std::count(plain.out.begin(), plain.out.end(), '\n'), 1) << plain.out;
    EXPECT_EQ(std::count(explained.out.begin(), explained.out.end(), '\n'), 1 + static_cast<long>(candidates.size()))
        << explained.out;
    EXPECT_NE(explained.out.find("candidate 1: "), std::string::npos) << explained.out;
    // The overlay gains the reasons below the picture; the picture itself is the same size.
    const cv::Mat p = cv::imread((dir / "plain.png").string()), e = cv::imread((dir / "explained.png").string());
    ASSERT_FALSE(p.empty());
    ASSERT_FALSE(e.empty());
    EXPECT_EQ(p.cols, e.cols);
    EXPECT_GT(e.rows, p.rows);
    fs::remove_all(dir);
}

TEST(CliExplain, ARectangleBelowTheMinimumIsTooSmallWithNumbersThatDiffer) {
    const fs::path dir = freshDir("explain_small");
    const CliRun r = detectFrame(dir, "small", "--explain --min-width 0.6225");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = readJson(dir / "small.json");
    EXPECT_FALSE(j["found"].get<bool>());
    // The chosen rectangle is 0.622 m wide: narrower than 0.6225 m, and the reason says so in
    // digits that show it.
    const std::string reason = j["reason"].get<std::string>();
    EXPECT_NE(reason.find("narrower than --min-width 0.6225 m"), std::string::npos) << reason;
    EXPECT_EQ(reason.find("0.622 x"), std::string::npos) << reason;
    int too_small = 0;
    for (const auto &c : j["candidates"]) too_small += c["verdict"] == "too_small";
    EXPECT_GE(too_small, 1) << j["candidates"].dump();
    fs::remove_all(dir);
}
