#include "projsurf/frontend/settings/detector_config_keys.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>

#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/detector_config_table.hpp"
#include "projsurf/frontend/settings/method_words.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/utf8_text.hpp"

namespace projsurf::frontend {
namespace {

constexpr double kInf = std::numeric_limits<double>::max();
constexpr std::size_t kMaxListItems = 16;

/// The shortest text that reads back as exactly `v`, with ".0" on whole numbers (a double).
std::string exactText(double v) {
    char text[64];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    std::string out(text, end);
    if (out.find_first_of(".eEn") == std::string::npos) out += ".0";
    return out;
}

/// Editing distance (insertions, deletions, substitutions) between two short words.
std::size_t editDistance(const std::string &a, const std::string &b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::string lastWord(const std::string &key) { return key.substr(key.find_last_of('.') + 1); }

}  // namespace

const std::vector<ConfigKey> &detectorConfigKeys() {
    static const std::vector<ConfigKey> keys = declaredConfigKeys();
    return keys;
}

const ConfigKey *findConfigKey(const std::string &key) {
    for (const ConfigKey &k : detectorConfigKeys())
        if (k.key == key) return &k;
    return nullptr;
}

std::string nearestConfigKey(const std::string &unknown) {
    std::string same_word;  // `max_planes` at the top level: the one key ending in it
    int same_word_count = 0;
    std::string nearest;
    std::size_t best = std::max<std::size_t>(2, unknown.size() / 5) + 1;
    for (const ConfigKey &k : detectorConfigKeys()) {
        if (lastWord(k.key) == lastWord(unknown)) same_word = k.key, ++same_word_count;
        const std::size_t d = editDistance(unknown, k.key);
        if (d < best) best = d, nearest = k.key;
    }
    if (!nearest.empty()) return nearest;
    return same_word_count == 1 ? same_word : "";
}

namespace {
/// The settings the front ends share by name, and their keys.
constexpr std::pair<const char *, const char *> kShared[] = {
    {"method", "method"},
    {"aspect", "aspect"},
    {"max_tilt", "max_tilt"},
    {"seed", "seed"},
    {"hull", "paper.hull"},
    {"voxel_leaf", "paper.voxel_leaf"},
    {"ransac_distance", "paper.ransac_distance"},
    {"max_outliers", "paper.max_outliers"},
    {"cell", "free_space.cell"},
    {"max_planes", "planes.max_planes"},
    {"max_outlier_fraction", "check.max_outlier_fraction"},
    {"suitability", "suitability.mode"},
};
}  // namespace

std::vector<std::string> sharedSettingNames() {
    std::vector<std::string> names;
    for (const auto &[name, key] : kShared) names.emplace_back(name);
    return names;
}

std::string configKeyOfSetting(const std::string &setting) {
    for (const auto &[name, key] : kShared)
        if (setting == name) return key;
    return "";
}

const char *keyTypeName(KeyType type) {
    switch (type) {
    case KeyType::Bool: return "bool";
    case KeyType::Int: return "int";
    case KeyType::Unsigned: return "unsigned";
    case KeyType::Double: return "double";
    case KeyType::DoubleList: return "list of double";
    case KeyType::Word: break;
    }
    return "word";
}

namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

/// What parseAspect takes besides 0: "a ratio or \"W:H\" within 0.01 to 100".
std::string aspectRatios() {
    return "a ratio or \"W:H\" within " + numberText(kMinAspect) + " to " + numberText(kMaxAspect);
}

std::string numericRange(const KeyRange &r) {
    if (r.hi >= kInf) return (r.lo_open ? "> " : ">= ") + numberText(r.lo);
    if (r.lo_open) return "> " + numberText(r.lo) + " and <= " + numberText(r.hi);
    return numberText(r.lo) + " to " + numberText(r.hi);
}

/// What a value of `key` must be, for messages: "a whole number from 1 to 20".
std::string expectation(const ConfigKey &key) {
    switch (key.type) {
    case KeyType::Bool: return "true or false";
    case KeyType::Int:
    case KeyType::Unsigned:
        return "a whole number " + std::string(key.range.hi >= kInf || key.range.lo_open ? "" : "from ") +
               numericRange(key.range);
    case KeyType::DoubleList:
        return "a list of 1 to " + std::to_string(kMaxListItems) + " numbers, each " + numericRange(key.range);
    case KeyType::Word: return "one word, " + keyRangeText(key);
    case KeyType::Double: break;
    }
    if (std::holds_alternative<AspectField>(key.access)) return "0 (the framebuffer's), or " + aspectRatios();
    return "a number " + std::string(key.range.hi >= kInf || key.range.lo_open ? "" : "from ") +
           numericRange(key.range);
}

std::optional<double> parseNumber(const std::string &text) {
    const char *begin = text.data(), *end = text.data() + text.size();
    if (begin != end && *begin == '+') ++begin;
    double v = 0.0;
    const auto [at, ec] = std::from_chars(begin, end, v);
    if (ec != std::errc() || at != end || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<long long> parseWhole(const std::string &text) {
    const char *begin = text.data(), *end = text.data() + text.size();
    if (begin != end && *begin == '+') ++begin;
    long long v = 0;
    const auto [at, ec] = std::from_chars(begin, end, v);
    if (ec != std::errc() || at != end) return std::nullopt;
    return v;
}

/// Within the range as its text states it: an end such as pi/2 is printed to 10 digits
/// (1.570796327), and the printed number itself is taken.
bool inRange(double v, const KeyRange &r) {
    const auto printed = [](double end) { return std::abs(end) < 1e300 ? std::stod(numberText(end)) : end; };
    const double lo = std::min(r.lo, printed(r.lo)), hi = std::max(r.hi, printed(r.hi));
    return (r.lo_open ? v > lo : v >= lo) && v <= hi;
}

[[noreturn]] void refuse(const ConfigKey &key, const std::string &got, bool quoted, const std::string &what) {
    throw InputError(what, "must be " + expectation(key) + ", got " + (quoted ? "the quoted word " : "") + "'" +
                               shownText(got) + "'");
}

/// The one item of a scalar value.
const std::string &scalar(const ConfigKey &key, const SettingText &value, const std::string &what) {
    if (value.sequence || value.items.size() != 1) refuse(key, "[...]", false, what);
    return value.items.front();
}

double number(const ConfigKey &key, const std::string &item, bool quoted, const std::string &what) {
    const std::optional<double> v = quoted ? std::nullopt : parseNumber(item);
    if (!v || !inRange(*v, key.range)) refuse(key, item, quoted, what);
    return *v;
}

long long whole(const ConfigKey &key, const std::string &item, bool quoted, const std::string &what) {
    const std::optional<long long> v = quoted ? std::nullopt : parseWhole(item);
    if (!v || !inRange(static_cast<double>(*v), key.range)) refuse(key, item, quoted, what);
    return *v;
}

bool flag(const ConfigKey &key, const std::string &item, bool quoted, const std::string &what) {
    if (!quoted && (item == "true" || item == "True" || item == "TRUE")) return true;
    if (!quoted && (item == "false" || item == "False" || item == "FALSE")) return false;
    refuse(key, item, quoted, what);
}

std::vector<double> numbers(const ConfigKey &key, const SettingText &value, const std::string &what) {
    if (value.items.empty() || value.items.size() > kMaxListItems) refuse(key, "[...]", false, what);
    std::vector<double> out;
    for (const std::string &item : value.items) out.push_back(number(key, item, value.quoted, what));
    return out;
}

}  // namespace

std::string keyRangeText(const ConfigKey &key) {
    return std::visit(Overloaded{
                          [](ConfigField<bool>) -> std::string { return "true | false"; },
                          [](ConfigField<Method>) -> std::string { return "default | paper"; },
                          [](ConfigField<HullKind>) -> std::string { return "concave | convex"; },
                          [](ConfigField<SuitabilityMode>) -> std::string { return "off | avoid | prefer"; },
                          [](AspectField) -> std::string { return "0, or " + aspectRatios(); },
                          [&](ConfigField<std::vector<double>>) {
                              return "1 to " + std::to_string(kMaxListItems) + " numbers, each " +
                                     numericRange(key.range);
                          },
                          [&](auto) { return numericRange(key.range); },
                      },
                      key.access);
}

SettingText configValue(const DetectorConfig &config, const ConfigKey &key) {
    // The fields are only read here; the accessors are written for reading and writing both.
    DetectorConfig &c = const_cast<DetectorConfig &>(config);
    SettingText out;
    out.key = key.key;
    std::visit(Overloaded{
                   [&](ConfigField<bool> f) { out.items = {f(c) ? "true" : "false"}; },
                   [&](ConfigField<int> f) { out.items = {std::to_string(f(c))}; },
                   [&](ConfigField<unsigned> f) { out.items = {std::to_string(f(c))}; },
                   [&](ConfigField<double> f) { out.items = {exactText(f(c))}; },
                   [&](AspectField a) { out.items = {exactText(a.field(c))}; },
                   [&](ConfigField<std::vector<double>> f) {
                       out.sequence = true;
                       for (double v : f(c)) out.items.push_back(exactText(v));
                   },
                   [&](ConfigField<Method> f) { out.items = {methodName(f(c))}, out.quoted = true; },
                   [&](ConfigField<HullKind> f) { out.items = {hullName(f(c))}, out.quoted = true; },
                   [&](ConfigField<SuitabilityMode> f) { out.items = {suitabilityModeName(f(c))}, out.quoted = true; },
               },
               key.access);
    return out;
}

void setConfigValue(DetectorConfig &c, const ConfigKey &key, const SettingText &value, const std::string &what) {
    const bool q = value.quoted;
    std::visit(Overloaded{
                   [&](ConfigField<bool> f) { f(c) = flag(key, scalar(key, value, what), q, what); },
                   [&](ConfigField<int> f) { f(c) = static_cast<int>(whole(key, scalar(key, value, what), q, what)); },
                   [&](ConfigField<unsigned> f) {
                       f(c) = static_cast<unsigned>(whole(key, scalar(key, value, what), q, what));
                   },
                   [&](ConfigField<double> f) { f(c) = number(key, scalar(key, value, what), q, what); },
                   [&](AspectField a) {
                       const std::string &text = scalar(key, value, what);
                       const std::optional<double> v = q ? std::nullopt : parseNumber(text);
                       a.field(c) = v && *v == 0.0 ? 0.0 : parseAspect(what, text);
                   },
                   [&](ConfigField<std::vector<double>> f) { f(c) = numbers(key, value, what); },
                   [&](ConfigField<Method> f) { f(c) = parseMethod(what, scalar(key, value, what)); },
                   [&](ConfigField<HullKind> f) { f(c) = parseHull(what, scalar(key, value, what)); },
                   [&](ConfigField<SuitabilityMode> f) { f(c) = parseSuitabilityMode(what, scalar(key, value, what)); },
               },
               key.access);
}

}  // namespace projsurf::frontend
