// The detector's settings as a YAML file: every DetectorConfig field under one key, read and
// written back to the same config; every refusal names the file and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "cli_run.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/detector_config_keys.hpp"
#include "projsurf/frontend/settings/method_settings.hpp"
#include "projsurf/frontend/settings/shared_settings.hpp"
#include "projsurf/io/files/errors.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::frontend;
using projsurf::test::freshDir;
using projsurf::test::slurp;

namespace {

std::string valueOf(const DetectorConfig &c, const std::string &key) {
    const ConfigKey *k = findConfigKey(key);
    EXPECT_NE(k, nullptr) << key;
    if (!k) return "";
    std::string text;
    for (const std::string &item : configValue(c, *k).items) text += item + ";";
    return text;
}

/// Every key's value as text: two configs are equal when these are.
std::vector<std::string> allValues(const DetectorConfig &c) {
    std::vector<std::string> out;
    for (const ConfigKey &k : detectorConfigKeys()) out.push_back(k.key + "=" + valueOf(c, k.key));
    return out;
}

bool inRange(double v, const KeyRange &r) { return (r.lo_open ? v > r.lo : v >= r.lo) && v <= r.hi; }

/// A valid value of `key` other than its value in `c` (the settings checked together stay ordered).
SettingText otherValue(const DetectorConfig &c, const ConfigKey &key) {
    SettingText v = configValue(c, key);
    const std::string now = v.items.front();
    auto number = [&](double d) {
        double x = d * 1.25 + 0.001;
        if (!inRange(x, key.range) || x == d) x = key.range.lo_open ? (key.range.lo + key.range.hi) / 2 : key.range.lo;
        return x;
    };
    switch (key.type) {
    case KeyType::Bool: v.items = {now == "true" ? "false" : "true"}; break;
    case KeyType::Int:
    case KeyType::Unsigned: {
        const long long n = std::stoll(now);
        v.items = {std::to_string(n + 1 <= key.range.hi ? n + 1 : static_cast<long long>(key.range.lo))};
        break;
    }
    case KeyType::Double: v.items = {key.key == "aspect" ? "1.6" : std::to_string(number(std::stod(now)))}; break;
    case KeyType::DoubleList: v.items = {"0.05", "0.3"}; break;
    case KeyType::Word: {
        const std::string words = keyRangeText(key);  // "a | b | c"
        for (std::size_t at = 0; at < words.size();) {
            const std::size_t bar = words.find(" | ", at);
            const std::string word = words.substr(at, bar - at);
            if (word != now) {
                v.items = {word};
                break;
            }
            at = bar == std::string::npos ? words.size() : bar + 3;
        }
        break;
    }
    }
    return v;
}

void write(const fs::path &path, const std::string &text) { std::ofstream(path, std::ios::binary) << text; }

/// `|` inside a cell of a Markdown table.
std::string cell(std::string text) {
    for (std::size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2) text.insert(at, "\\");
    return text;
}

/// The key's row in docs/interface.md: key, type and range, default, doc.
std::string keyTableRow(const ConfigKey &k) {
    const SettingText v = configValue(DetectorConfig{}, k);
    std::string value;
    for (const std::string &item : v.items)
        value += (value.empty() ? "" : ", ") + (v.quoted ? "\"" + item + "\"" : item);
    if (v.sequence) value = "[" + value + "]";
    return "| `" + k.key + "` | " + keyTypeName(k.type) + ": " + cell(keyRangeText(k)) + " | `" + value + "` | " +
           cell(k.doc) + " |";
}

/// The one-line message readDetectorConfig throws for a file holding `text`.
std::string refusal(const fs::path &dir, const std::string &text) {
    const fs::path path = dir / "detector.yaml";
    write(path, text);
    DetectorConfig c;
    try {
        readDetectorConfig(path.string(), c);
    } catch (const InputError &e) {
        EXPECT_EQ(allValues(c), allValues(DetectorConfig{})) << "a refused file changed the config";
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST(DetectorConfigKeys, EveryKeyIsUniqueDocumentedAndReachesItsOwnField) {
    const std::vector<ConfigKey> &keys = detectorConfigKeys();
    // Every field of DetectorConfig and the structs it nests is a key or says "not a key:":
    // scripts/config_keys.py stops the build on any other field, so no count is kept here.
    ASSERT_FALSE(keys.empty());
    std::set<std::string> names;
    for (const ConfigKey &k : keys) {
        EXPECT_TRUE(names.insert(k.key).second) << k.key << " twice";
        EXPECT_FALSE(k.doc.empty()) << k.key;
        // Changing this key changes it alone: no two keys share a field, each reads what it set.
        DetectorConfig c;
        const SettingText other = otherValue(c, k);
        setConfigValue(c, k, other, k.key);
        EXPECT_NE(valueOf(c, k.key), valueOf(DetectorConfig{}, k.key)) << k.key;
        for (const ConfigKey &o : keys) {
            if (o.key != k.key) {
                EXPECT_EQ(valueOf(c, o.key), valueOf(DetectorConfig{}, o.key)) << k.key << " moved " << o.key;
            }
        }
    }
    for (const char *key :
         {"method", "aspect", "max_tilt", "seed", "planes.max_planes", "planes.regions.min_fill",
          "wall.shape.relief.max_nodes", "objects.avoid", "objects.surround.offsets", "objects.rule.wall_width",
          "free_space.cell", "check.max_outlier_fraction", "suitability.mode", "suitability.cells.max_hole",
          "paper.voxel_leaf", "paper.hull", "unorganized.enabled", "tolerance.noise_k"})
        EXPECT_NE(findConfigKey(key), nullptr) << key;
}

TEST(DetectorConfigKeys, TheFrontEndsSharedSettingNamesHaveKeys) {
    for (const Method m : {Method::Default, Method::Paper})
        for (const std::string &setting : settingsIgnoredBy(m))
            EXPECT_NE(findConfigKey(configKeyOfSetting(setting)), nullptr) << setting;
    EXPECT_EQ(configKeyOfSetting("max_planes"), "planes.max_planes");
    EXPECT_EQ(configKeyOfSetting("voxel_leaf"), "paper.voxel_leaf");
    EXPECT_EQ(configKeyOfSetting("no_such_setting"), "");
    for (const std::string &setting : sharedNumberSettings())
        EXPECT_EQ(sharedSettingKey(setting).key, configKeyOfSetting(setting)) << setting;
}

TEST(DetectorConfigKeys, TheSharedNumberSettingsComeFromTheTableInTheCliOrder) {
    // Derived from configKeyOfSetting()'s table: the words (method, hull, suitability) and the
    // aspect's W:H are not numbers. The order is the CLI's flags' and Python's keyword list's.
    const std::vector<std::string> expected = {"max_tilt",     "seed", "voxel_leaf", "ransac_distance",
                                               "max_outliers", "cell", "max_planes", "max_outlier_fraction"};
    EXPECT_EQ(sharedNumberSettings(), expected);
    for (const std::string &name : sharedSettingNames()) EXPECT_NE(configKeyOfSetting(name), "") << name;
}

TEST(DetectorConfigKeys, TheDeadRegionTiltIsNoKey) {
    // The default method sets planes.regions.max_tilt from max_tilt: a key would do nothing.
    EXPECT_EQ(findConfigKey("planes.regions.max_tilt"), nullptr);
    EXPECT_NE(findConfigKey("max_tilt"), nullptr);
}

TEST(DetectorConfigKeys, TheKeysTakeRangeAndDocFromTheirDeclaration) {
    // detection/detector_config.hpp: `int max_planes = 4;  ///< [1, 20] vertical planes tried, ...`
    const ConfigKey *k = findConfigKey("planes.max_planes");
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(k->type, KeyType::Int);
    EXPECT_EQ(k->range.lo, 1.0);
    EXPECT_EQ(k->range.hi, 20.0);
    EXPECT_EQ(k->doc.rfind("vertical planes tried", 0), 0u) << k->doc;
    const ConfigKey *fill = findConfigKey("planes.regions.min_fill");  // (0, 1]
    ASSERT_NE(fill, nullptr);
    EXPECT_TRUE(fill->range.lo_open);
    EXPECT_EQ(keyRangeText(*findConfigKey("seed")), "0 to 4294967295");
    EXPECT_EQ(keyRangeText(*findConfigKey("wall.refit_min_turn")), "0 to 1.570796327");  // [0, pi/2]
}

TEST(SharedSettings, EachIsCheckedByItsKeyWithTheOneMessage) {
    DetectorConfig c;
    setSharedSetting(c, "max_tilt", "0", "~max_tilt");
    EXPECT_EQ(c.max_tilt, 0.0);
    setSharedSetting(c, "seed", "4294967295", "~seed");
    EXPECT_EQ(c.seed, 4294967295u);
    setSharedSetting(c, "max_planes", "20", "--max-planes");
    EXPECT_EQ(c.planes.max_planes, 20);
    try {
        setSharedSetting(c, "max_tilt", "2", "~max_tilt");
        FAIL() << "2 rad accepted";
    } catch (const InputError &e) {
        EXPECT_STREQ(e.what(), "~max_tilt: must be a number from 0 to 1.5, got '2'");
    }
    EXPECT_THROW(setSharedSetting(c, "seed", "4294967296", "seed"), InputError);
    EXPECT_THROW(setSharedSetting(c, "max_planes", "2.0", "max_planes"), InputError);
    EXPECT_THROW(setSharedSetting(c, "cell", "nan", "cell"), InputError);
    EXPECT_EQ(c.max_tilt, 0.0);  // refused values change nothing
    EXPECT_NE(sharedSettingHelp("max_tilt").find("0 to 1.5"), std::string::npos) << sharedSettingHelp("max_tilt");
}

TEST(DetectorConfigFile, PrintedConfigReadsBackToTheSameConfig) {
    const fs::path dir = freshDir("config_round_trip");
    DetectorConfig changed;
    for (const ConfigKey &k : detectorConfigKeys()) setConfigValue(changed, k, otherValue(changed, k), k.key);
    changed.paper.voxel_leaf = 0.1 / 3.0;  // a double with no short decimal form
    changed.objects.surround.offsets = {0.1 / 7.0, 0.2, 1e-3};
    ASSERT_NE(allValues(changed), allValues(DetectorConfig{}));
    write(dir / "all.yaml", detectorConfigYaml(changed));
    DetectorConfig read;
    readDetectorConfig((dir / "all.yaml").string(), read);
    EXPECT_EQ(allValues(read), allValues(changed));
    EXPECT_EQ(read.paper.voxel_leaf, 0.1 / 3.0);
    EXPECT_EQ(read.objects.surround.offsets, changed.objects.surround.offsets);
    EXPECT_EQ(detectorConfigYaml(read), detectorConfigYaml(changed));
    fs::remove_all(dir);
}

TEST(DetectorConfigFile, NestedAndDottedKeysAreTheSameAndOthersKeepTheirValues) {
    const fs::path dir = freshDir("config_nested");
    write(dir / "nested.yaml", "planes:\n  max_planes: 6\n  regions: {min_cells: 9}\nmethod: paper\n");
    write(dir / "dotted.yaml", "planes.max_planes: 6\nplanes.regions.min_cells: 9\nmethod: \"paper\"\n");
    DetectorConfig nested, dotted;
    readDetectorConfig((dir / "nested.yaml").string(), nested);
    readDetectorConfig((dir / "dotted.yaml").string(), dotted);
    EXPECT_EQ(nested.planes.max_planes, 6);
    EXPECT_EQ(nested.planes.regions.min_cells, 9);
    EXPECT_EQ(nested.method, Method::Paper);
    EXPECT_EQ(allValues(nested), allValues(dotted));
    EXPECT_EQ(nested.free_space.cell, DetectorConfig{}.free_space.cell);
    // Over a config that is not the default: what the file does not give stays as it was.
    DetectorConfig over;
    over.seed = 7;
    readDetectorConfig((dir / "nested.yaml").string(), over);
    EXPECT_EQ(over.seed, 7u);
    EXPECT_EQ(over.planes.max_planes, 6);
    write(dir / "empty.yaml", "# nothing but a comment\n");
    DetectorConfig empty;
    readDetectorConfig((dir / "empty.yaml").string(), empty);
    EXPECT_EQ(allValues(empty), allValues(DetectorConfig{}));
    fs::remove_all(dir);
}

TEST(DetectorConfigFile, UnknownKeysAreNamedWithTheKeyMeant) {
    const fs::path dir = freshDir("config_unknown");
    const std::string file = (dir / "detector.yaml").string();
    EXPECT_EQ(refusal(dir, "planes:\n  max_plane: 6\n"),
              file + ": unknown key 'planes.max_plane' (did you mean 'planes.max_planes'?)");
    EXPECT_EQ(refusal(dir, "max_planes: 6\n"), file + ": unknown key 'max_planes' (did you mean 'planes.max_planes'?)");
    EXPECT_EQ(refusal(dir, "zzz: 1\n"), file + ": unknown key 'zzz'");
    EXPECT_NE(refusal(dir, "planes: 5\n").find(": key 'planes' holds settings (planes."), std::string::npos);
    EXPECT_NE(refusal(dir, "projector:\n  resolution: [1280, 800]\n")
                  .find("unknown key 'projector.resolution' (a calibration or camera file"),
              std::string::npos);
    fs::remove_all(dir);
}

// The settings every front end takes as an option of its own, not from the file (issue 40):
// the refusal names the option, so `min_width: 0.7` in a file is not a dead end.
TEST(DetectorConfigFile, MinimumSizeAndGravityAreRefusedNamingTheirOptions) {
    const fs::path dir = freshDir("config_flags");
    const std::string file = (dir / "detector.yaml").string();
    EXPECT_EQ(refusal(dir, "min_width: 0.7\n"),
              file + ": unknown key 'min_width' (the smallest picture is not a detector setting: give it as detect "
                     "--min-width, the node's ~min_width or Python's min_width=)");
    EXPECT_NE(refusal(dir, "min-area: 0.5\n").find("detect --min-area, the node's ~min_area or Python's min_area="),
              std::string::npos);
    EXPECT_NE(refusal(dir, "gravity: [0, 1, 0]\n").find("give it as detect or plan --gravity, the node's ~gravity"),
              std::string::npos);
    fs::remove_all(dir);
}

TEST(DetectorConfigFile, ValuesOutOfRangeOrOfTheWrongTypeNameTheKey) {
    const fs::path dir = freshDir("config_values");
    const std::string at = (dir / "detector.yaml").string() + ": key ";
    EXPECT_EQ(refusal(dir, "planes.max_planes: 0\n"),
              at + "'planes.max_planes': must be a whole number from 1 to 20, got '0'");
    EXPECT_EQ(refusal(dir, "planes.max_planes: 21\n"),
              at + "'planes.max_planes': must be a whole number from 1 to 20, got '21'");
    EXPECT_EQ(refusal(dir, "tolerance.min_band: 0\n"),
              at + "'tolerance.min_band': must be a number from 0.0001 to 10, got '0'");
    EXPECT_EQ(refusal(dir, "max_tilt: .nan\n"), at + "'max_tilt': must be a number from 0 to 1.5, got '.nan'");
    EXPECT_EQ(refusal(dir, "max_tilt: .inf\n"), at + "'max_tilt': must be a number from 0 to 1.5, got '.inf'");
    EXPECT_EQ(refusal(dir, "wall.noise_max: 1e999\n"),
              at + "'wall.noise_max': must be a number from 0.01 to 100, got '1e999'");
    // Inside "> 0" before, and an OpenCV assertion in the detection (issue 39).
    EXPECT_EQ(refusal(dir, "wall.shape.relief.node_px: 1e-300\n"),
              at + "'wall.shape.relief.node_px': must be a number from 1 to 1000, got '1e-300'");
    EXPECT_EQ(refusal(dir, "wall.shape.relief.sigma_px: 1e300\n"),
              at + "'wall.shape.relief.sigma_px': must be a number from 0.5 to 1000, got '1e300'");
    EXPECT_EQ(refusal(dir, "seed: -1\n"), at + "'seed': must be a whole number from 0 to 4294967295, got '-1'");
    // The wrong type.
    EXPECT_EQ(refusal(dir, "planes.max_planes: six\n"),
              at + "'planes.max_planes': must be a whole number from 1 to 20, got 'six'");
    EXPECT_EQ(refusal(dir, "planes.max_planes: 2.5\n"),
              at + "'planes.max_planes': must be a whole number from 1 to 20, got '2.5'");
    EXPECT_EQ(refusal(dir, "planes.max_planes: \"6\"\n"),
              at + "'planes.max_planes': must be a whole number from 1 to 20, got the quoted word '6'");
    EXPECT_EQ(refusal(dir, "planes.max_planes: [6]\n"),
              at + "'planes.max_planes': must be a whole number from 1 to 20, got '[...]'");
    EXPECT_EQ(refusal(dir, "objects.avoid: yes\n"), at + "'objects.avoid': must be true or false, got 'yes'");
    EXPECT_EQ(refusal(dir, "objects.surround.offsets: [0.1, -0.2]\n"),
              at + "'objects.surround.offsets': must be a list of 1 to 16 numbers, each 0.0001 to 10, got '-0.2'");
    // Words go through the front ends' one parser of each.
    EXPECT_EQ(refusal(dir, "method: fast\n"), at + "'method': expected 'default' or 'paper', got 'fast'");
    EXPECT_EQ(refusal(dir, "paper.hull: round\n"), at + "'paper.hull': expected 'concave' or 'convex', got 'round'");
    EXPECT_EQ(refusal(dir, "suitability.mode: always\n"),
              at + "'suitability.mode': expected 'off', 'avoid' or 'prefer', got 'always'");
    EXPECT_NE(refusal(dir, "aspect: 16x9\n").find(at + "'aspect': expected a positive aspect ratio W:H"),
              std::string::npos);
    // Each value in range, but not together.
    EXPECT_EQ(refusal(dir, "tolerance: {min_band: 0.1}\n"),
              (dir / "detector.yaml").string() + ": 'tolerance.min_band' must not exceed 'tolerance.max_band'");
    fs::remove_all(dir);
}

TEST(DetectorConfigFile, AspectReadsAsTheAspectFlag) {
    const fs::path dir = freshDir("config_aspect");
    write(dir / "a.yaml", "aspect: \"16:9\"\n");
    DetectorConfig c;
    readDetectorConfig((dir / "a.yaml").string(), c);
    EXPECT_DOUBLE_EQ(c.aspect, 16.0 / 9.0);
    write(dir / "a.yaml", "aspect: 0\n");
    readDetectorConfig((dir / "a.yaml").string(), c);
    EXPECT_EQ(c.aspect, 0.0);
    fs::remove_all(dir);
}

TEST(DetectorConfigFile, HostileFilesAreOneLineNamingTheFile) {
    const fs::path dir = freshDir("config_hostile");
    const std::string file = (dir / "detector.yaml").string();
    EXPECT_EQ(refusal(dir, "planes: {max_planes: 6\n").rfind(file + ": malformed YAML: ", 0), 0u);
    EXPECT_EQ(refusal(dir, "- 1\n- 2\n"), file + ": expected a YAML mapping of settings at the top level");
    EXPECT_EQ(refusal(dir, "seed: 1\nseed: 2\n"), file + ": key 'seed' is given twice");
    EXPECT_EQ(refusal(dir, "seed: 1\nplanes: {max_planes: 2}\nplanes.max_planes: 3\n"),
              file + ": key 'planes.max_planes' is given twice");
    EXPECT_EQ(refusal(dir, "seed:\n"), file + ": key 'seed' has no value");
    EXPECT_EQ(refusal(dir, "? [a, b]\n: 1\n"), file + ": a key under the top level is not a plain word");
    EXPECT_EQ(refusal(dir, std::string("seed: 1\0\n", 9)), file + ": binary data, not a YAML file");
    EXPECT_NE(refusal(dir, "seed: 1\n" + std::string(1100000, '#') + "\n").find("exceeds the limit of 1048576 bytes"),
              std::string::npos);
    // Aliases that repeat a mapping exponentially often.
    std::string bomb = "a0: &a0 {x: 1}\n";
    for (int i = 1; i < 30; ++i)
        bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " {p: *a" + std::to_string(i - 1) + ", q: *a" +
                std::to_string(i - 1) + "}\n";
    EXPECT_EQ(refusal(dir, bomb), file + ": more than 100000 YAML nodes (aliases repeating a mapping?)");
    DetectorConfig c;
    EXPECT_THROW(readDetectorConfig(dir.string(), c), InputError);  // a directory
    EXPECT_THROW(readDetectorConfig((dir / "missing.yaml").string(), c), InputError);
    fs::remove_all(dir);
}

TEST(DetectorConfigFile, TheShippedExampleIsTheDefaultsAsPrinted) {
    const fs::path example = fs::path(PROJSURF_SOURCE_DIR) / "config/detector.yaml";
    DetectorConfig c;
    c.seed = 1;  // the file sets every key
    readDetectorConfig(example.string(), c);
    EXPECT_EQ(allValues(c), allValues(DetectorConfig{}));
    EXPECT_EQ(slurp(example), detectorConfigYaml(DetectorConfig{}))
        << "regenerate it: projsurf detect --print-config > config/detector.yaml";
}

TEST(DetectorConfigFile, TheInterfaceDocumentsTableIsTheDeclaredOne) {
    // docs/interface.md's key table, row for row, as the declarations give it; on a difference
    // the table to paste is written beside the test's temporary files.
    std::string expected;
    for (const ConfigKey &k : detectorConfigKeys()) expected += keyTableRow(k) + "\n";
    const std::string doc = slurp(fs::path(PROJSURF_SOURCE_DIR) / "docs/interface.md");
    const std::string header = "| key | type: accepts | default | what (unit first) |\n|---|---|---|---|\n";
    const std::size_t begin = doc.find(header);
    ASSERT_NE(begin, std::string::npos) << "docs/interface.md has no key table";
    std::size_t end = begin + header.size();
    while (end < doc.size() && doc.compare(end, 3, "| `") == 0) end = doc.find('\n', end) + 1;
    const std::string documented = doc.substr(begin + header.size(), end - begin - header.size());
    if (documented != expected) {
        const fs::path out = fs::temp_directory_path() / "projsurf_interface_keys.md";
        write(out, header + expected);
        FAIL() << "docs/interface.md's key table differs from the declarations: paste " << out.string();
    }
}
