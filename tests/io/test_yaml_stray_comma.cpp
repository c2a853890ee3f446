// The ',' that yaml-cpp 0.7 never returns from is found before yaml-cpp runs; valid YAML with
// commas where YAML allows them (plain scalars, flow collections, quotes, block scalars,
// comments) and every YAML file in the repository pass.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "projsurf/io/errors.hpp"
#include "projsurf/io/yaml_stray_comma.hpp"
#include "projsurf/io/yaml_tree.hpp"

namespace projsurf {
namespace {

TEST(YamlStrayComma, TheInputsYamlCppLoopsOnAreFoundOnTheirLine) {
    // The first two are the fuzzer's finds (calibration and camera readers, CI of 2026-12-05);
    // a third, ",\x85ca", is refused as text that is not UTF-8.
    const std::pair<std::string, int> cases[] = {
        {"[39.2999997, 24]\n  , 800]\n  fov_dep p'", 2},
        {", ca", 1},
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
        {"a: 1\n---\n, b", 3},
        {"--- , b", 1},
        {"a: 1\n...\n, b", 3},
        {"\"x\" # c\n, b", 2},
        {"\"multi\n line\", b", 2},
        {"a: 1\n--- [1], 2", 2},
        {"&acam,MM", 1},
        {"!t,a", 1},
    };
    for (const auto &[text, line] : cases) {
        EXPECT_EQ(strayCommaLine(text), line) << text;
        EXPECT_THROW(loadCheckedYaml("f.yaml", text), InputError) << text;
    }
}

TEST(YamlStrayComma, TextThatIsNotUtf8IsRefusedBeforeYamlCppReadsIt) {
    EXPECT_THROW(loadCheckedYaml("f.yaml", ",\x85" "ca"), InputError);
    EXPECT_THROW(loadCheckedYaml("f.yaml", "a: \xff\xfe:\n  1"), InputError);
    EXPECT_NO_THROW(loadCheckedYaml("f.yaml", "name: caf\xc3\xa9"));
}

TEST(YamlStrayComma, CommasYamlAllowsPass) {
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
        EXPECT_EQ(strayCommaLine(text), 0) << text;
        EXPECT_NO_THROW(YAML::Load(text)) << text;
    }
}

TEST(YamlStrayComma, EveryYamlFileOfTheRepositoryPasses) {
    const std::filesystem::path root = PROJSURF_SOURCE_DIR;
    int files = 0;
    for (const char *dir : {"config", "examples", "labels", "data", "ros"}) {
        if (!std::filesystem::is_directory(root / dir)) continue;
        for (const auto &e : std::filesystem::recursive_directory_iterator(root / dir)) {
            if (e.path().extension() != ".yaml" && e.path().extension() != ".yml") continue;
            std::ifstream in(e.path());
            std::stringstream text;
            text << in.rdbuf();
            EXPECT_EQ(strayCommaLine(text.str()), 0) << e.path();
            ++files;
        }
    }
    EXPECT_GT(files, 50);
}

}  // namespace
}  // namespace projsurf
