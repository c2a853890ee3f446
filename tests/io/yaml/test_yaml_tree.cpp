// The text yaml-cpp 0.7's LoadAll never returns from (a token it cannot place at a document's
// root starts an empty document without being consumed, again and again) is refused at once;
// valid YAML with commas where YAML allows them and every YAML file in the repository load.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/yaml/yaml_tree.hpp"

namespace projsurf {
namespace {

TEST(YamlTree, TextYamlCppLoadAllNeverLeavesIsRefusedNamingTheLine) {
    // The first two and the last two are the fuzzer's finds (calibration and camera readers,
    // 2026-12-05); 0 where the line yaml-cpp names is not the point.
    const std::pair<std::string, int> cases[] = {
        {"[39.2999997, 24]\n  , 800]\n  fov_dep p'", 2},
        {",\x85" "ca", 1},
        {",", 1},
        {", a", 1},
        {"- a\n,b", 2},
        {"\"x\", b", 1},
        {"'x', b", 1},
        {"[a] , b", 1},
        {"{a: 1}, b", 1},
        {"&a , b", 1},
        {"!t , b", 1},
        {"&a [1], b", 1},
        {"# c\n, b", 2},
        {"%YAML 1.2\n---\n,b", 3},
        {"a: 1\n---\n, b", 2},  // the "---" starts the second
        {"--- , b", 1},
        {"a: 1\n...\n, b", 3},
        {"\"x\" # c\n, b", 2},
        {"\"multi\n line\", b", 2},
        {"a: 1\n--- [1], 2", 2},
        {"&acam,MM", 1},
        {"!t,a", 1},
        {"#  0f12, 0 ]0\n:. [0\n#(0]\n  ,e]\n : [0.0, -0.05, 1.0]\n", 0},
        {"[]er2:19?\n?\n ped th_scalee\n", 0},
    };
    for (const auto &[text, line] : cases) {
        try {
            loadCheckedYaml("f.yaml", text);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const InputError &e) {
            if (line > 0) {
                EXPECT_NE(std::string(e.what()).find("line " + std::to_string(line) + ":"), std::string::npos)
                    << text << " -> " << e.what();
            }
        }
    }
}

TEST(YamlTree, CommasYamlAllowsLoad) {
    const char *valid[] = {
        "a: b, c",
        "a: [1, 2, 3]\nb: {x: 1, y: [2, 3]}",
        "a: [1,\n  2,\n  3]",
        "{\"camera\": {\"fx\": 525, \"fy\": 525}, \"n\": [1, 2]}",
        "a: \"x, y\"\nb: 'it''s, here'\nc: \"q\\\", r\"",
        "a: it's, here",
        "a: 1 # a comment, with a comma\n# , another\nb: 2",
        "note: |\n  , a literal line\n  ,, and another\nb: 1",
        "note: >-\n\n  , folded\nb: 1",
        "- [1, 2]\n- {a: 1, b: 2}\n- x, y",
        "url: http://a,b",
        "\"x\": 1, b",
        "",
    };
    for (const char *text : valid) {
        EXPECT_NO_THROW(loadCheckedYaml("f.yaml", text)) << text;
    }
}

TEST(YamlTree, EveryYamlFileOfTheRepositoryLoads) {
    const std::filesystem::path root = PROJSURF_SOURCE_DIR;
    int files = 0;
    for (const char *dir : {"config", "examples", "labels", "data", "ros"}) {
        if (!std::filesystem::is_directory(root / dir)) continue;
        for (const auto &e : std::filesystem::recursive_directory_iterator(root / dir)) {
            if (e.path().extension() != ".yaml" && e.path().extension() != ".yml") continue;
            std::ifstream in(e.path());
            std::stringstream text;
            text << in.rdbuf();
            EXPECT_NO_THROW(loadCheckedYaml(e.path().string(), text.str())) << e.path();
            ++files;
        }
    }
    EXPECT_GT(files, 50);
}

}  // namespace
}  // namespace projsurf
