// `--gravity auto` (the floor's gravity) against the labels' reference gravity, which comes from a
// separate fit (labels/floor_gravity.py), on every labelled real frame that has one (the table in
// docs/wall_model.md, "Gravity from the floor"). The labels' own gravity.vector is an earlier
// run of auto on most frames, so it is no check. Prints the table; asserts what holds today.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "eval/real/real_labels.hpp"
#include "label_fixtures.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/io/formats/cloud_io.hpp"

using namespace projsurf;
using namespace projsurf::eval;  // the evaluation under test
namespace fs = std::filesystem;

namespace {

double angleDeg(const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

TEST(GravityRealFloor, AutoMatchesTheLabelsReferenceWhereTheFloorIsSeen) {
    const std::string real = std::string(PROJSURF_SHARED_DIR) + "/data/real";
    if (!fs::is_directory(real)) GTEST_SKIP() << real << " is not here (the real frames stay in ../shared)";
    // Frames are in ../shared/data/real or, for those that ship, in the repository's data/real.
    const auto choice = frontend::parseGravityChoice("--gravity", "auto");
    std::printf("| frame | reference | auto vs reference, deg |\n|---|---|---:|\n");
    int frames = 0, within_1deg = 0;
    double worst = 0.0;
    for (const std::string &file : listLabelFiles(std::string(PROJSURF_SOURCE_DIR) + "/labels/real")) {
        const RealLabel label = readRealLabel(file);
        if (label.reference_gravity_source != "floor_fit") continue;
        const std::string dir = test::labelledFrameDir(label.frame);
        ASSERT_FALSE(dir.empty()) << label.frame << ": no frame for this label";
        const Cloud cloud = readDepthCloud(dir + "/depth.png", dir + "/camera.yaml");
        const auto g = frontend::resolveGravity(choice, cloud);
        const double off = g.floor_found ? angleDeg(g.gravity, label.reference_gravity) : 180.0;
        std::printf("| %s | %s | %s |\n", label.frame.c_str(), label.reference_gravity_source.c_str(),
                    g.floor_found ? std::to_string(off).substr(0, 4).c_str() : "no floor");
        ++frames;
        within_1deg += off <= 1.0;
        worst = std::max(worst, off);
        // Every frame where the separate fit sees the floor: auto sees it too, within 1 deg
        // (the target; the worst today is 0.93 deg).
        EXPECT_LE(off, 1.0) << label.frame;
    }
    std::printf("%d of %d frames within 1 deg; worst %.2f deg\n", within_1deg, frames, worst);
    EXPECT_GE(frames, 15) << "the labels' reference gravity went missing";
}
