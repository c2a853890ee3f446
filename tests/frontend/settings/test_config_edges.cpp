// Every key of the detector settings file at the edges of its range: accepted at each end,
// refused just outside with one line naming the file and the key. The CLI's --config, the node's
// ~config and Python's config= all read the file with this one reader (readDetectorConfig);
// python/tests/test_config_edges.py walks the same edges through Python and the CLI.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fresh_dir.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/detector_config_keys.hpp"
#include "projsurf/io/files/errors.hpp"

namespace fs = std::filesystem;
using namespace projsurf;
using namespace projsurf::frontend;

namespace {

/// A value as YAML text, exact enough to land on the edge it is meant for.
std::string yamlNumber(double v) {
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
}

struct Edge {
    std::string value;  ///< YAML text
    bool inside;
};

/// The values at the ends of a key's range and just outside them.
std::vector<Edge> edgesOf(const ConfigKey &k) {
    const KeyRange &r = k.range;
    const bool bounded = r.hi < 1e300;
    switch (k.type) {
    case KeyType::Bool: return {{"true", true}, {"false", true}, {"2", false}};
    case KeyType::Word: {
        std::vector<Edge> out{{"nonsense", false}};
        const std::string words = keyRangeText(k);  // "a | b | c"
        for (std::size_t at = 0; at < words.size();) {
            const std::size_t bar = words.find(" | ", at);
            out.push_back({words.substr(at, bar - at), true});
            at = bar == std::string::npos ? words.size() : bar + 3;
        }
        return out;
    }
    case KeyType::Int:
    case KeyType::Unsigned: {
        std::vector<Edge> out{{yamlNumber(r.lo), !r.lo_open}, {yamlNumber(r.lo - 1), false}};
        if (r.lo_open) out.push_back({yamlNumber(r.lo + 1), true});
        if (bounded) out.insert(out.end(), {{yamlNumber(r.hi), true}, {yamlNumber(r.hi + 1), false}});
        return out;
    }
    case KeyType::Double:
    case KeyType::DoubleList: {
        const double step = bounded ? std::max(1e-9, (r.hi - r.lo) * 1e-3) : 1e-3;
        std::vector<Edge> out{{yamlNumber(r.lo), !r.lo_open}, {yamlNumber(r.lo - step), false}};
        if (r.lo_open) out.push_back({yamlNumber(r.lo + step), true});
        if (bounded) out.insert(out.end(), {{yamlNumber(r.hi), true}, {yamlNumber(r.hi + step), false}});
        if (k.key == "aspect") out.push_back({"0", true});  // 0: the framebuffer's, below the ratios' range
        if (k.type == KeyType::DoubleList)
            for (Edge &e : out) e.value = "[" + e.value + "]";
        return out;
    }
    }
    return {};
}

/// Settings checked together (the first must not exceed the second, or sigma_px must not exceed
/// 10 x node_px): the partner is put at the end that lets every value of the key under test pass.
const std::map<std::string, std::pair<std::string, bool>> &partners() {
    static const std::map<std::string, std::pair<std::string, bool>> p = {
        {"tolerance.min_band", {"tolerance.max_band", true}},
        {"tolerance.max_band", {"tolerance.min_band", false}},
        {"wall.noise_min", {"wall.noise_max", true}},
        {"wall.noise_max", {"wall.noise_min", false}},
        {"wall.shape.min_points", {"wall.shape.max_points", true}},
        {"wall.shape.max_points", {"wall.shape.min_points", false}},
        {"wall.shape.relief.sigma_px", {"wall.shape.relief.node_px", true}},
        {"wall.shape.relief.node_px", {"wall.shape.relief.sigma_px", false}},
    };
    return p;
}

/// "" when the reader takes `text`, else its one-line message.
std::string readText(const fs::path &path, const std::string &text, DetectorConfig &c) {
    std::ofstream(path, std::ios::binary) << text;
    try {
        readDetectorConfig(path.string(), c);
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(DetectorConfigEdges, EveryKeyIsTakenAtTheEndsOfItsRangeAndRefusedJustOutside) {
    const fs::path dir = test::freshDir("config", "edges");
    const fs::path path = dir / "detector.yaml";
    int cases = 0;
    for (const ConfigKey &k : detectorConfigKeys()) {
        std::string partner;
        if (const auto p = partners().find(k.key); p != partners().end()) {
            const ConfigKey *other = findConfigKey(p->second.first);
            ASSERT_NE(other, nullptr) << p->second.first;
            partner = other->key + ": " + yamlNumber(p->second.second ? other->range.hi : other->range.lo) + "\n";
        }
        for (const Edge &e : edgesOf(k)) {
            DetectorConfig c;
            const std::string message = readText(path, partner + k.key + ": " + e.value + "\n", c);
            ++cases;
            if (e.inside) {
                EXPECT_EQ(message, "") << k.key << " = " << e.value;
                const std::string now = configValue(c, k).items.front();
                if (k.type == KeyType::Word || k.type == KeyType::Bool) {
                    EXPECT_EQ(now, e.value) << k.key;
                } else if (k.type != KeyType::DoubleList) {
                    EXPECT_DOUBLE_EQ(std::stod(now), std::stod(e.value)) << k.key;
                }
            } else {
                EXPECT_EQ(message.rfind(path.string() + ": key '" + k.key + "': ", 0), 0u)
                    << k.key << " = " << e.value << " gave: " << message;
                EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            }
        }
    }
    EXPECT_GT(cases, 4 * static_cast<int>(detectorConfigKeys().size()) - 100);  // every key, several edges each
    fs::remove_all(dir);
}
