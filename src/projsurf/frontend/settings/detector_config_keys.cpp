#include "projsurf/frontend/settings/detector_config_keys.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <optional>

#include "projsurf/frontend/settings/aspect.hpp"
#include "projsurf/frontend/settings/method_words.hpp"
#include "projsurf/frontend/settings/suitability_mode.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/utf8_text.hpp"

namespace projsurf::frontend {
namespace {

constexpr double kInf = std::numeric_limits<double>::max();
constexpr double kHalfPi = 1.5707963267948966;
constexpr std::size_t kMaxListItems = 16;

constexpr KeyRange from(double lo, double hi) { return {lo, hi, false}; }
constexpr KeyRange above(double lo, double hi = kInf) { return {lo, hi, true}; }
// Every number is bounded both ways, by what it means: an unbounded "> 0" let 1e-300 and 1e300
// through to an OpenCV assertion (wall.shape.relief.node_px, sigma_px).
constexpr KeyRange kBands = from(0.01, 100.0);        ///< multiples of an inlier band, a noise, a spread
constexpr KeyRange kMetres = from(0.0001, 10.0);      ///< m, a length that must be positive
constexpr KeyRange kMetresOrZero = from(0.0, 10.0);   ///< m, a length or none
constexpr KeyRange kArea = from(0.0, 100.0);          ///< m^2
constexpr KeyRange kShare = from(0.0, 1.0);
constexpr KeyRange kAngle = from(0.0, kHalfPi);  ///< rad, 0 to 90 deg
constexpr KeyRange kAny{};
/// Counts that size a buffer stay within a depth image's pixels (io/files/limits.hpp: 2^24).
constexpr double kMaxCount = double(1 << 24);

template <typename T>
constexpr KeyType typeOf() {
    if constexpr (std::is_same_v<T, bool>) return KeyType::Bool;
    if constexpr (std::is_same_v<T, int>) return KeyType::Int;
    if constexpr (std::is_same_v<T, unsigned>) return KeyType::Unsigned;
    if constexpr (std::is_same_v<T, double>) return KeyType::Double;
    if constexpr (std::is_same_v<T, std::vector<double>>) return KeyType::DoubleList;
    return KeyType::Word;
}

template <typename T>
ConfigKey makeKey(const char *name, ConfigField<T> field, KeyRange range, const char *doc) {
    return ConfigKey{name, typeOf<T>(), range, doc, ConfigAccess{field}};
}

// The key is the field's path itself (#path), so that it cannot drift from the struct.
#define PROJSURF_KEY(T, path, range, doc) \
    makeKey<T>(                           \
        #path, [](DetectorConfig &c) -> T & { return c.path; }, range, doc)

std::vector<ConfigKey> topKeys() {
    return {
        PROJSURF_KEY(Method, method, kAny, "the detection method; paper: the paper's steps, for reproduction"),
        ConfigKey{"aspect", KeyType::Double, from(0.0, 100.0),
                  "picture width / height, or \"W:H\"; 0 = the projector framebuffer's",
                  AspectField{[](DetectorConfig &c) -> double & { return c.aspect; }}},
        PROJSURF_KEY(double, max_tilt, from(0.0, 1.5), "rad, plane normal vs horizontal (contract; paper 3.2.1)"),
        PROJSURF_KEY(unsigned, seed, from(0.0, 4294967295.0), "RANSAC random seed (runs are deterministic)"),
    };
}

std::vector<ConfigKey> toleranceKeys() {
    return {
        PROJSURF_KEY(double, tolerance.noise_k, from(1e-6, 1.0), "1/m, depth noise sigma_z = k z^2 (K&OE 2012, Kinect v1)"),
        PROJSURF_KEY(double, tolerance.sigmas, kBands, "inlier band in sigmas of the depth noise"),
        PROJSURF_KEY(double, tolerance.min_band, kMetres, "m, band floor (flat posters, 3 mm proud, stay inliers)"),
        PROJSURF_KEY(double, tolerance.max_band, kMetres, "m, band ceiling (beyond 4 m the Kinect is out of range)"),
        PROJSURF_KEY(double, tolerance.obstacle_bands, kBands,
                     "beyond this many bands a point is an obstacle or hole"),
        PROJSURF_KEY(double, tolerance.min_obstacle, kMetresOrZero, "m, and at least this far (paper 3.2.3 uses 0.05)"),
    };
}

std::vector<ConfigKey> unorganizedKeys() {
    return {
        PROJSURF_KEY(bool, unorganized.enabled, kAny,
                     "unorganized clouds as a pinhole's depth image; false: sequential RANSAC"),
        PROJSURF_KEY(double, unorganized.max_half_angle_deg, above(0.0, 89.0),
                     "deg off the optical axis kept (the projector's beam is < 30)"),
        PROJSURF_KEY(double, unorganized.fill, above(0.0, 16.0),
                     "pixels per point over the covered view (1: the cloud's own density)"),
        PROJSURF_KEY(int, unorganized.max_pixels, from(1, kMaxCount), "image size cap, px (about 1.3 x 1280x800)"),
        PROJSURF_KEY(int, unorganized.min_points, from(1, kMaxCount), "fewer points in front of the camera: no image"),
    };
}

std::vector<ConfigKey> planeKeys() {
    return {
        PROJSURF_KEY(bool, planes.image_regions, kAny, "organized clouds: planar regions instead of RANSAC"),
        PROJSURF_KEY(int, planes.regions.cell, from(1, 256), "grid elements per cell side (8 at the 2-px grid: 16 px)"),
        PROJSURF_KEY(double, planes.regions.min_fill, above(0.0, 1.0),
                     "share of a cell's points that must be readings"),
        PROJSURF_KEY(double, planes.regions.thickness_bands, kBands,
                     "a flat cell is thinner (RMS off its plane) than this many inlier bands"),
        PROJSURF_KEY(double, planes.regions.seed_tilt, kAngle,
                     "rad, a region starts from a cell whose normal is within this of horizontal"),
        PROJSURF_KEY(double, planes.regions.max_tilt, kAngle, "rad, a region's plane within this of horizontal"),
        PROJSURF_KEY(double, planes.regions.join_bands, kBands,
                     "a neighbour cell joins below this RMS distance to the region's plane, in bands"),
        PROJSURF_KEY(int, planes.regions.min_cells, from(1, kMaxCount), "smaller regions are not surfaces, cells"),
        PROJSURF_KEY(double, planes.regions.merge_angle, kAngle,
                     "rad, regions this parallel within each other's obstacle margin are one"),
        PROJSURF_KEY(int, planes.target_samples, from(3, kMaxCount), "points kept for the RANSAC search, measured"),
        PROJSURF_KEY(int, planes.max_planes, from(1, 20), "vertical planes tried, biggest first"),
        PROJSURF_KEY(int, planes.min_plane_points, from(3, kMaxCount), "sampled inliers for a plane to count"),
        PROJSURF_KEY(int, planes.ransac_iterations, from(1, 1e6),
                     "hypotheses per plane (adaptive stop usually earlier)"),
        PROJSURF_KEY(int, planes.score_subset, from(3, kMaxCount), "points a hypothesis is scored on, measured"),
        PROJSURF_KEY(double, planes.max_sample_span, kMetres,
                     "m, the 2nd and 3rd point of a hypothesis within this of the 1st"),
        PROJSURF_KEY(int, planes.refine_rounds, from(0, 100), "least-squares refits of each plane on its inliers"),
        PROJSURF_KEY(double, planes.merge_angle, kAngle,
                     "rad, a plane this parallel to a found one, within its margin, is a slice of it"),
        PROJSURF_KEY(double, planes.min_region_share, kShare,
                     "share of readings: depth images whose regions hold less also run the RANSAC search"),
    };
}

std::vector<ConfigKey> wallKeys() {
    return {
        PROJSURF_KEY(bool, wall.fit_shape, kAny, "follow the smooth bend real depth cameras give a flat wall"),
        PROJSURF_KEY(double, wall.shape.capture_bands, kBands, "points within this many inlier bands take part"),
        PROJSURF_KEY(double, wall.shape.tukey_bands, kBands, "Tukey biweight width, in inlier bands"),
        PROJSURF_KEY(int, wall.shape.iterations, from(1, 100), "reweighted least-squares rounds"),
        PROJSURF_KEY(int, wall.shape.min_points, from(6, kMaxCount), "fewer points: the wall stays flat"),
        PROJSURF_KEY(int, wall.shape.max_points, from(6, kMaxCount), "more are thinned evenly, measured"),
        PROJSURF_KEY(double, wall.shape.max_bend, kMetres, "m, a larger fitted bend anywhere is refused"),
        PROJSURF_KEY(double, wall.shape.bend_per_z2, from(0.0, 10.0), "1/m, or more than this times depth^2 there"),
        PROJSURF_KEY(bool, wall.shape.relief.enabled, kAny, "fit the relief (features of a few tens of px) too"),
        PROJSURF_KEY(double, wall.shape.relief.node_px, from(1.0, 1000.0), "px at the wall's depth between relief nodes"),
        PROJSURF_KEY(double, wall.shape.relief.sigma_px, from(0.5, 1000.0), "px, the relief's Gaussian sigma"),
        PROJSURF_KEY(double, wall.shape.relief.tukey_bands, kBands, "Tukey biweight width in inlier bands"),
        PROJSURF_KEY(int, wall.shape.relief.rounds, from(1, 100), "reweighting rounds"),
        PROJSURF_KEY(double, wall.shape.relief.min_weight_share, kShare,
                     "nodes below this share of the median node weight shrink towards 0"),
        PROJSURF_KEY(int, wall.shape.relief.max_nodes, from(1, 1024),
                     "nodes per side; a larger wall spaces them wider"),
        PROJSURF_KEY(double, wall.noise_min, kBands,
                     "the wall's measured noise kept above this multiple of the model's"),
        PROJSURF_KEY(double, wall.noise_max, kBands, "... and below this multiple (ToF is better, stereo worse)"),
        PROJSURF_KEY(double, wall.local_cap, kBands, "the wall's noise is at most this many times the local noise"),
        PROJSURF_KEY(int, wall.noise_offset_px, from(1, 256),
                     "px between the readings whose differences measure noise"),
        PROJSURF_KEY(int, wall.plane_refits, from(0, 100), "least-squares refits of the plane to the wall's shape"),
        PROJSURF_KEY(double, wall.refit_min_turn, kAngle, "rad, a refit turning the plane less ends the refits"),
        PROJSURF_KEY(double, wall.refit_min_shift, kMetresOrZero, "m, ... and moving it less (docs/wall_model.md)"),
    };
}

std::vector<ConfigKey> objectKeys() {
    return {
        PROJSURF_KEY(bool, objects.avoid, kAny, "skip faces that stand free; false takes any vertical face (paper)"),
        PROJSURF_KEY(int, objects.surround.bins, from(1, 1024), "positions along each edge"),
        PROJSURF_KEY(int, objects.surround.min_bin_points, from(1, kMaxCount), "face points a position needs"),
        PROJSURF_KEY(double, objects.surround.edge_quantile, kShare, "the edge at a position: this quantile of points"),
        PROJSURF_KEY(std::vector<double>, objects.surround.offsets, kMetres,
                     "m beyond the edge, looked at nearest first (1 to 16 numbers)"),
        PROJSURF_KEY(double, objects.surround.min_step, kMetres, "m, a reading this far off the plane is off it"),
        PROJSURF_KEY(int, objects.surround.search_px, from(0, 64),
                     "px, a missing reading is looked for this far around"),
        PROJSURF_KEY(double, objects.surround.max_gap, kMetres, "m, a gap this wide between a face's points ends it"),
        PROJSURF_KEY(double, objects.rule.min_seen, kShare, "share of an edge's positions seen past or in front"),
        PROJSURF_KEY(double, objects.rule.min_past, kShare, "share of those open behind for the edge to be open"),
        PROJSURF_KEY(double, objects.rule.wall_height, kMetresOrZero, "m, a face this tall and wide serves like a wall"),
        PROJSURF_KEY(double, objects.rule.wall_width, kMetresOrZero, "m, ... and this wide (wider than a door)"),
        PROJSURF_KEY(double, objects.rule.min_height, kMetresOrZero, "m, a face lower than this is a strip, no surface"),
        PROJSURF_KEY(double, objects.opening_depth, kMetres,
                     "m, an enclosed face this far behind a wall is beyond an opening"),
    };
}

std::vector<ConfigKey> freeSpaceKeys() {
    return {
        PROJSURF_KEY(double, free_space.cell, from(0.002, 0.5), "m, raster cell (area error < 0.05 m^2 at 3 m)"),
        PROJSURF_KEY(int, free_space.stride, from(1, 64), "pixel step of the pass on organized clouds"),
        PROJSURF_KEY(bool, free_space.exclude_other_surfaces, kAny,
                     "points clearly nearer another region's plane are no support"),
        PROJSURF_KEY(int, free_space.max_gap_cells, from(0, 1024), "largest gap between wall samples closed, cells"),
        PROJSURF_KEY(int, free_space.min_blocked_neighbours, from(0, 8),
                     "blocked cells a blocked cell needs in its 3x3"),
        PROJSURF_KEY(double, free_space.image_margin, from(0.0, 0.5),
                     "of the image width: margin around where a plane is seen"),
        PROJSURF_KEY(double, free_space.inlier_box_margin, from(0.0, 0.5),
                     "of the image width, when the cloud has no fitted intrinsics"),
        PROJSURF_KEY(bool, free_space.proud.enabled, kAny,
                     "cells whose readings stand off the wall's shape on average are not free"),
        PROJSURF_KEY(double, free_space.proud.window, kMetres, "m, side of the square the offsets are averaged over"),
        PROJSURF_KEY(int, free_space.proud.min_points, from(1, 100000), "a window with fewer readings says nothing"),
        PROJSURF_KEY(double, free_space.proud.spreads, from(0.0, 100.0),
                     "a window mean beyond this many robust spreads of the wall's window means is proud"),
        PROJSURF_KEY(double, free_space.proud.min_offset, kMetresOrZero,
                     "m, and beyond this (posters, whiteboards stay free)"),
        PROJSURF_KEY(double, free_space.proud.min_extent, kMetresOrZero,
                     "m, proud areas narrower than this are dropped (a few windows: the sensor's)"),
        PROJSURF_KEY(bool, free_space.steps.enabled, kAny,
                     "cells where the wall's readings step along a line (a frame's border) are not free"),
        PROJSURF_KEY(double, free_space.steps.width, kMetres, "m, width of each strip either side of a step"),
        PROJSURF_KEY(double, free_space.steps.length, kMetres, "m, the strips' length along the step"),
        PROJSURF_KEY(int, free_space.steps.min_points, from(1, 100000), "a strip with fewer readings says nothing"),
        PROJSURF_KEY(double, free_space.steps.spreads, from(0.0, 100.0),
                     "a step beyond this many robust spreads of the wall's steps is an edge"),
        PROJSURF_KEY(double, free_space.steps.min_step, kMetresOrZero,
                     "m, and beyond this (posters, whiteboards stay free)"),
        PROJSURF_KEY(double, check.max_outlier_fraction, kShare, "share of checked points off the wall that rejects"),
    };
}

std::vector<ConfigKey> suitabilityKeys() {
    return {
        PROJSURF_KEY(
            SuitabilityMode, suitability.mode, kAny,
            "with registered colour: ignore it, avoid unfit cells, or prefer a cleaner wall (docs/suitability.md)"),
        PROJSURF_KEY(double, suitability.cells.context, kMetresOrZero,
                     "m, the wall judged beyond the raster on each side"),
        PROJSURF_KEY(double, suitability.cells.weak_contrast, from(0.0, 100.0),
                     "window contrast above which cells near wide texture are textured too"),
        PROJSURF_KEY(double, suitability.cells.weak_over_wall, from(0.0, 100.0),
                     "... and above this many times the wall's"),
        PROJSURF_KEY(double, suitability.cells.texture_growth, kMetresOrZero,
                     "m, how far from wide texture weak cells join"),
        PROJSURF_KEY(double, suitability.cells.window, kMetres,
                     "m, side of the square texture and glare are judged on"),
        PROJSURF_KEY(double, suitability.cells.tone_window, kMetres,
                     "m, the square darkness and saturation are judged on"),
        PROJSURF_KEY(double, suitability.cells.dark_relative, kShare,
                     "darker than this share of the wall's median: dark"),
        PROJSURF_KEY(double, suitability.cells.dark_min, kShare, "luminance share below which a surface is too dark"),
        PROJSURF_KEY(double, suitability.cells.max_chroma, kShare,
                     "mean (max - min channel) / 255 above this: saturated"),
        PROJSURF_KEY(double, suitability.cells.max_contrast, from(0.0, 100.0), "luminance std / mean above this: textured"),
        PROJSURF_KEY(double, suitability.cells.glare_level, above(0.0, 1.0),
                     "a channel at this share of 255 is blown out"),
        PROJSURF_KEY(double, suitability.cells.max_glare_share, kShare, "more blown-out samples in the window: glare"),
        PROJSURF_KEY(double, suitability.cells.glare_wall_share, kShare,
                     "no glare on a wall whose median luminance reaches this share of glare_level"),
        PROJSURF_KEY(int, suitability.cells.row_step, from(1, 64),
                     "every this many rows of the point grid are sampled"),
        PROJSURF_KEY(int, suitability.cells.min_tone_samples, from(1, kMaxCount), "fewer: tone judged over the window"),
        PROJSURF_KEY(int, suitability.cells.min_samples, from(1, kMaxCount),
                     "fewer wall samples: colour decides nothing"),
        PROJSURF_KEY(int, suitability.cells.trim_cells, from(0, 64), "textured and glare cells given back on a rim"),
        PROJSURF_KEY(double, suitability.cells.max_hole, kArea,
                     "m^2, fit areas enclosed by unfit ones up to this"),
        PROJSURF_KEY(double, suitability.cells.min_unfit_area, kArea, "m^2, smaller unfit areas are fit"),
        PROJSURF_KEY(double, suitability.cells.min_texture_width, kMetresOrZero, "m, narrower textured areas are fit"),
        PROJSURF_KEY(double, suitability.prefer_exponent, from(0.0, 100.0),
                     "k of prefer's rule: area x (1 - unfit share)^k"),
    };
}

std::vector<ConfigKey> paperKeys() {
    return {
        PROJSURF_KEY(HullKind, paper.hull, kAny, "hull of the plane's inliers (paper 4.1 keeps concave)"),
        PROJSURF_KEY(double, paper.voxel_leaf, from(0.001, 1.0), "m, voxel-grid side (paper 3.2.1)"),
        PROJSURF_KEY(double, paper.ransac_distance, from(0.001, 1.0), "m, RANSAC inlier band (= voxel side)"),
        PROJSURF_KEY(int, paper.ransac_iterations, from(1, 1e6), "RANSAC iterations (PCL SACSegmentation's default)"),
        PROJSURF_KEY(double, paper.concave_alpha, kMetres, "m, alpha of the concave hull (2 voxels)"),
        PROJSURF_KEY(double, paper.cell, from(0.002, 0.5), "m, raster cell of the free-space matrices (paper 3.2.2)"),
        PROJSURF_KEY(double, paper.outlier_distance, kMetres,
                     "m, |z - mean z| above this is an outlier (paper 3.2.3)"),
        PROJSURF_KEY(int, paper.max_outliers, from(0, INT_MAX), "more outliers reject the surface (paper 4.3)"),
        PROJSURF_KEY(int, paper.max_voxels, from(1, kMaxCount), "more voxels are not searched (memory, time)"),
    };
}

#undef PROJSURF_KEY

std::vector<ConfigKey> allKeys() {
    std::vector<ConfigKey> all;
    for (auto part : {topKeys, toleranceKeys, unorganizedKeys, planeKeys, wallKeys, objectKeys, freeSpaceKeys,
                      suitabilityKeys, paperKeys}) {
        std::vector<ConfigKey> keys = part();
        all.insert(all.end(), keys.begin(), keys.end());
    }
    return all;
}

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
    static const std::vector<ConfigKey> keys = allKeys();
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

std::string configKeyOfSetting(const std::string &setting) {
    static const std::pair<const char *, const char *> kShared[] = {
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
    if (std::holds_alternative<AspectField>(key.access))
        return "0 (the framebuffer's), or a ratio or \"W:H\" within 0.01 to 100";
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

bool inRange(double v, const KeyRange &r) { return (r.lo_open ? v > r.lo : v >= r.lo) && v <= r.hi; }

[[noreturn]] void refuse(const ConfigKey &key, const std::string &got, bool quoted, const std::string &what) {
    throw InputError(what,
                     "must be " + expectation(key) + ", got " + (quoted ? "the quoted word " : "") + "'" + shownText(got) + "'");
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
                          [](AspectField) -> std::string { return "0, or a ratio or \"W:H\" within 0.01 to 100"; },
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

void copyConfigValue(const DetectorConfig &from, DetectorConfig &to, const ConfigKey &key) {
    DetectorConfig &source = const_cast<DetectorConfig &>(from);  // read only, as in configValue
    std::visit(Overloaded{
                   [&](AspectField a) { a.field(to) = a.field(source); },
                   [&](auto f) { f(to) = f(source); },
               },
               key.access);
}

}  // namespace projsurf::frontend
