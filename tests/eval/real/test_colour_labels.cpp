// The colour section of the real-frame labels: the reader and its errors, the
// colour-aware reference best and the share over unsuitable polygons on a synthetic wall with
// a known answer, and the guard that every stored colour label is what the reference computes.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "fresh_dir.hpp"
#include "label_fixtures.hpp"
#include "eval/real/label_reference.hpp"
#include "eval/real/labelled_eval.hpp"
#include "eval/real/real_labels.hpp"
#include "eval/real/real_scoring.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

using namespace projsurf::eval;  // the evaluation under test

using namespace projsurf;
namespace fs = std::filesystem;
using namespace projsurf::test;

namespace {

// The whole image is one frontal wall; the colour makes its left half unsuitable.
const char *kLabel = R"(frame: synthetic
gravity: {source: stated, vector: [0, 1, 0]}
projector:
  resolution: [1280, 800]
  fov_deg: [39.3, 24]
  axis: {origin: [0, 0, 0], direction: [0, 0, 1]}
surfaces:
  - name: wall
    regions:
      - polygon: [[-0.5, -0.5], [639.5, -0.5], [639.5, 479.5], [-0.5, 479.5]]
obstacles: []
best:
  found: false
colour:
  note: a test
  unsuitable:
    - name: poster on the left half
      why: textured
      polygon: [[-1, -1], [319.5, -1], [319.5, 481], [-1, 481]]
  best:
    found: false
)";

Rectangle asRectangle(const LabelBest &b) {
    Rectangle r;
    r.corners = b.corners;
    r.width = b.width;
    r.height = b.height;
    return r;
}

}  // namespace

TEST(ColourLabels, ReadsWritesAndKeepsOldFilesValid) {
    const fs::path dir = test::freshDir("colour_labels", "read");
    RealLabel l = readRealLabel(writeLabel(dir, "good.yaml", kLabel));
    ASSERT_TRUE(l.colour.judged);
    EXPECT_EQ(l.colour.note, "a test");
    ASSERT_EQ(l.colour.unsuitable.size(), 1u);
    EXPECT_EQ(l.colour.unsuitable[0].why, "textured");
    EXPECT_EQ(l.colour.unsuitable[0].polygon.name, "poster on the left half");
    EXPECT_EQ(l.colour.unsuitable[0].polygon.pixels.size(), 4u);
    EXPECT_FALSE(l.colour.best.found);
    // Written and read back: the same section, with a colour best.
    const SyntheticWall wall(2.0);
    l.best = referenceBest(wall.cloud, wall.camera, l);
    l.colour.best = colourReferenceBest(wall.camera, l);
    ASSERT_TRUE(l.colour.best.found);
    writeRealLabel((dir / "again.yaml").string(), l);
    const RealLabel r = readRealLabel((dir / "again.yaml").string());
    ASSERT_TRUE(r.colour.judged);
    EXPECT_EQ(r.colour.note, l.colour.note);
    ASSERT_EQ(r.colour.unsuitable.size(), 1u);
    EXPECT_EQ(r.colour.unsuitable[0].why, "textured");
    EXPECT_EQ(r.colour.unsuitable[0].polygon.pixels, l.colour.unsuitable[0].polygon.pixels);
    ASSERT_TRUE(r.colour.best.found);
    EXPECT_NEAR(r.colour.best.area(), l.colour.best.area(), 1e-6);
    // "Judged, nothing found" is kept apart from "not judged".
    const std::string empty =
        replaced(replaced(kLabel, "    - name: poster on the left half\n      why: textured\n", ""),
                 "      polygon: [[-1, -1], [319.5, -1], [319.5, 481], [-1, 481]]\n", "");
    const RealLabel e =
        readRealLabel(writeLabel(dir, "empty.yaml", replaced(empty, "  unsuitable:\n", "  unsuitable: []\n")));
    EXPECT_TRUE(e.colour.judged);
    EXPECT_TRUE(e.colour.unsuitable.empty());
    writeRealLabel((dir / "empty_again.yaml").string(), e);
    EXPECT_TRUE(readRealLabel((dir / "empty_again.yaml").string()).colour.judged);
    const std::string old = std::string(kLabel).substr(0, std::string(kLabel).find("colour:"));
    const RealLabel o = readRealLabel(writeLabel(dir, "old.yaml", old));
    EXPECT_FALSE(o.colour.judged);
    writeRealLabel((dir / "old_again.yaml").string(), o);
    std::ifstream in(dir / "old_again.yaml");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("colour"), std::string::npos) << "an old label gains no colour section: " << text;
    fs::remove_all(dir);
}

TEST(ColourLabels, MalformedSectionsGiveAClearError) {
    const fs::path dir = test::freshDir("colour_labels", "malformed");
    const std::string good = kLabel, path = (dir / "bad.yaml").string();
    ASSERT_EQ(readError(dir, good), "");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {good.substr(0, good.find("colour:")) + "colour: [1, 2]\n", "'colour' must be a mapping"},
        {replaced(good, "  unsuitable:\n", "  unsuited:\n"), "missing key 'colour.unsuitable'"},
        {replaced(good, "why: textured", "why: ugly"), "'colour.unsuitable[0].why' must be one of"},
        {replaced(good, "      why: textured\n", ""), "missing key 'colour.unsuitable[0].why'"},
        {replaced(good, "polygon: [[-1, -1], [319.5, -1], [319.5, 481], [-1, 481]]", "polygon: [[-1, -1]]"),
         "'colour.unsuitable[0].polygon' must be a list of at least 3"},
        {replaced(good, "  best:\n    found: false", "  best:\n    found: true\n    surface: floor"),
         "'colour.best.surface' names no surface: 'floor'"},
        {replaced(good, "  best:\n    found: false", "  best:\n    found: maybe"),
         "'colour.best.found' must be true or false"},
    };
    for (const auto &[text, expected] : cases) {
        const std::string message = readError(dir, text);
        EXPECT_NE(message.find(path + ": "), std::string::npos) << message;
        EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
    }
    fs::remove_all(dir);
}

TEST(ColourLabels, ColourBestAvoidsTheUnsuitablePolygons) {
    const fs::path dir = test::freshDir("colour_labels", "reference");
    const SyntheticWall wall(2.0);
    RealLabel l = readRealLabel(writeLabel(dir, "good.yaml", kLabel));
    l.best = referenceBest(wall.cloud, wall.camera, l);
    l.colour.best = colourReferenceBest(wall.camera, l);
    ASSERT_TRUE(l.best.found);
    ASSERT_TRUE(l.colour.best.found);
    // Depth alone: the footprint's full height, centred on the axis, so half of it is over the
    // poster; with colour: width-limited by the right half (as test_real_labels' obstacle case).
    const double half_w = 2.0 * std::tan(0.5 * 39.3 * M_PI / 180), cell = 0.0025;
    EXPECT_LE(l.colour.best.width, half_w + 1e-9);
    EXPECT_GE(l.colour.best.width, half_w - 2 * 1.6 * cell);
    EXPECT_LT(l.colour.best.area(), l.best.area());
    for (const auto &c : l.colour.best.corners) EXPECT_GE(c.x(), -0.5 * cell);
    const double depth_share = unsuitableShare(l, wall.camera, asRectangle(l.best));
    EXPECT_GT(depth_share, 0.3);
    EXPECT_LT(depth_share, 0.7);
    EXPECT_LE(unsuitableShare(l, wall.camera, asRectangle(l.colour.best)), 0.02);
    // Scored against the colour-aware label: the colour best is right with ratio 1, the depth
    // best is wrong (half of it over the poster), and only the colour best is on clean wall.
    const ColourScore on_colour = scoreColourRectangle(l, wall.camera, true, asRectangle(l.colour.best));
    EXPECT_TRUE(on_colour.score.right) << on_colour.score.why;
    EXPECT_NEAR(on_colour.score.ratio, 1.0, 1e-9);
    EXPECT_TRUE(on_colour.clean());
    const ColourScore on_depth = scoreColourRectangle(l, wall.camera, true, asRectangle(l.best));
    EXPECT_FALSE(on_depth.score.right);
    EXPECT_FALSE(on_depth.clean());
    EXPECT_NEAR(on_depth.unsuitable_share, depth_share, 1e-12);
    // Nothing found is on no wall at all.
    EXPECT_FALSE(scoreColourRectangle(l, wall.camera, false, Rectangle{}).clean());
    // Without unsuitable polygons the colour best is the depth best.
    l.colour.unsuitable.clear();
    const LabelBest same = colourReferenceBest(wall.camera, l);
    ASSERT_TRUE(same.found);
    EXPECT_NEAR(same.area(), l.best.area(), 1e-12);
    EXPECT_EQ(unsuitableShare(l, wall.camera, asRectangle(l.best)), 0.0);
    fs::remove_all(dir);
}

// Every real frame with registered colour is judged; its polygons lie in the image; the stored
// colour best is what the reference computes today. (The detector's colour scores are not
// pinned here: `projsurf eval` prints them, see labels/README.md, section Colour.)
TEST(ColourLabelSuite, StoredColourBestIsTheReference) {
    const std::string labels = std::string(PROJSURF_SOURCE_DIR) + "/labels/real";
    int judged = 0, here = 0;
    for (const std::string &file : listLabelFiles(labels)) {
        SCOPED_TRACE(file);
        RealLabel label = readRealLabel(file);
        const std::string dir = labelledFrameDir(label.frame);
        if (dir.empty()) continue;  // in ../shared/data/real, which is not here
        ++here;
        const bool registered = fs::exists(dir + "/rgb.png");
        EXPECT_EQ(label.colour.judged, registered)
            << label.frame << ": the frames with a registered rgb.png, and only they, are judged on colour";
        if (!label.colour.judged) continue;
        ++judged;
        const std::string cam_yaml = dir + "/camera.yaml";
        const CameraIntrinsics camera = readCamera(cam_yaml);
        for (const auto &u : label.colour.unsuitable)
            for (const auto &p : u.polygon.pixels) {
                EXPECT_GE(p.x(), 0.0) << u.polygon.name;
                EXPECT_GE(p.y(), 0.0) << u.polygon.name;
                EXPECT_LE(p.x(), camera.width - 1.0) << u.polygon.name;
                EXPECT_LE(p.y(), camera.height - 1.0) << u.polygon.name;
            }
        const Cloud cloud = readDepthCloud(dir + "/depth.png", cam_yaml);
        RealLabel refit = label;
        referenceBest(cloud, camera, refit);
        const LabelBest now = colourReferenceBest(camera, refit), stored = label.colour.best;
        ASSERT_EQ(now.found, stored.found) << label.frame << ": re-run labels/remake.sh (labels/README.md)";
        if (!stored.found) continue;
        EXPECT_EQ(now.surface, stored.surface);
        EXPECT_NEAR(now.area(), stored.area(), 1e-3 * stored.area())
            << label.frame << ": stored colour best " << stored.area() << " m^2, the reference now gives "
            << now.area();
        for (int k = 0; k < 4; ++k) EXPECT_LT((now.corners[k] - stored.corners[k]).norm(), 0.005) << "corner " << k;
        // The colour best is no larger than the depth best, and lies on no unsuitable polygon.
        EXPECT_LE(stored.area(), label.best.area() * (1 + 1e-6));
        EXPECT_LE(unsuitableShare(label, camera, asRectangle(stored)), 0.02);
    }
    if (here == 0) GTEST_SKIP() << "no labelled frame is here (../shared/data/real, data/real)";
    EXPECT_GT(judged, 0);
}

// The eval's colour run is what `projsurf detect --rgb --suitability avoid` gives with the
// label's projector and gravity (the command it reports, run, gives the same rectangle), and both
// answers are scored against the colour-aware label.
TEST(ColourLabelSuite, EvalDetectsWithColourAsTheCliDoes) {
    const std::string real = std::string(PROJSURF_SHARED_DIR) + "/data/real";
    if (!fs::is_directory(real)) GTEST_SKIP() << real << " is not here (the real frames stay in ../shared)";
    const fs::path dir = test::freshDir("colour_labels", "cli_same");
    const std::string frame = "nyu_rgbdtut_cafe_counter";
    const std::string label = std::string(PROJSURF_SOURCE_DIR) + "/labels/real/check/" + frame + ".yaml";
    const LabelledFrame f = evaluateLabelledFrame(label, real, DetectorConfig{}, {});
    const ColourRun &c = f.colour;
    ASSERT_TRUE(c.judged);
    ASSERT_TRUE(c.colour_used) << c.colour_note;
    ASSERT_TRUE(c.detection.found);
    EXPECT_FALSE(c.overlay.empty());
    const CameraIntrinsics camera = readCamera(real + "/" + frame + "/camera.yaml");
    const ColourScore again = scoreColourRectangle(f.label, camera, true, c.detection.rectangle);
    EXPECT_EQ(again.score.right, c.with_colour.score.right);
    EXPECT_EQ(again.unsuitable_share, c.with_colour.unsuitable_share);
    EXPECT_EQ(scoreColourRectangle(f.label, camera, true, f.detection.rectangle).unsuitable_share,
              c.depth_only.unsuitable_share);
    ASSERT_NE(c.command.find(" --rgb "), std::string::npos) << c.command;
    const fs::path json = dir / "colour.json";
    const std::string cmd = std::string(PROJSURF_CLI) + c.command.substr(std::string("projsurf").size()) + " --json " +
                            json.string() + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_TRUE(j["found"].get<bool>());
    EXPECT_EQ(j["suitability"]["mode"].get<std::string>(), "avoid");
    for (int k = 0; k < 4; ++k)
        for (int a = 0; a < 3; ++a)
            EXPECT_NEAR(j["rectangle"]["corners"][k][a].get<double>(), c.detection.rectangle.corners[k][a], 1e-4)
                << "corner " << k;
    // The report has the colour table and its summary line.
    const std::string md = labelledReportMarkdown({f}, "labels/real", "labels");
    EXPECT_NE(md.find("### With colour"), std::string::npos);
    EXPECT_NE(md.find(colourSummaryLine(summariseColour({f}))), std::string::npos);
    EXPECT_NE(md.find("](labels/" + frame + "_colour.png)"), std::string::npos);
    fs::remove_all(dir);
}
