#include "eval/realistic/colour_suite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "eval/paper/experiments.hpp"
#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/detection/rectangle_search.hpp"
#include "projsurf/sim/depth_sensor.hpp"
#include "projsurf/sim/exact_depth.hpp"
#include "projsurf/sim/ground_truth.hpp"
#include "projsurf/sim/ray_cast.hpp"
#include "projsurf/sim/render.hpp"
#include "projsurf/sim/scenes/scenarios_realistic.hpp"
#include "projsurf/sim/scenes/wall_frame.hpp"
#include "projsurf/types/formatted.hpp"

namespace projsurf::eval {

using namespace projsurf::sim;  // the simulator the evaluation runs on
namespace {

constexpr double kTexel = 0.005;  ///< m per texel of the things' textures
constexpr double kFlat = 0.005;   ///< m, the things stand this far proud (free by the depth truth's 1 cm)

/// Room paints (BGR reflectance): what a room's walls are painted.
struct Paint {
    const char *name;
    cv::Vec3f bgr;
};
const std::vector<Paint> &paints() {
    static const std::vector<Paint> p{{"white", {0.84f, 0.86f, 0.87f}},      {"beige", {0.60f, 0.74f, 0.84f}},
                                      {"pale_blue", {0.84f, 0.74f, 0.62f}},  {"sage", {0.52f, 0.66f, 0.56f}},
                                      {"terracotta", {0.32f, 0.44f, 0.68f}}, {"grey", {0.42f, 0.42f, 0.42f}}};
    return p;
}

cv::Mat plainTexture(double w, double h, const cv::Vec3f &c) {
    return cv::Mat(std::max(1, static_cast<int>(h / kTexel)), std::max(1, static_cast<int>(w / kTexel)), CV_32FC3,
                   cv::Scalar(c[0], c[1], c[2]));
}

cv::Scalar randomColour(cv::RNG &rng, float lo = 0.05f, float hi = 0.95f) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

/// A photograph: shapes of 2-15 cm in random colours on a random ground.
void paintPhoto(cv::Mat &t, const cv::Rect &area, cv::RNG &rng) {
    cv::Mat roi = t(area);
    roi.setTo(randomColour(rng, 0.2f, 0.8f));
    const int shapes = area.area() / 60 + 4;
    for (int i = 0; i < shapes; ++i) {
        const cv::Point c(rng.uniform(0, area.width), rng.uniform(0, area.height));
        const int r = rng.uniform(2, 15);
        if (i % 2)
            cv::circle(roi, c, r, randomColour(rng), cv::FILLED);
        else
            cv::rectangle(roi, {c.x - r, c.y - r / 2, 2 * r, r}, randomColour(rng), cv::FILLED);
    }
}

/// A framed picture: a dark wooden frame 4 cm wide, a photograph in it.
cv::Mat framedPicture(double w, double h, cv::RNG &rng) {
    cv::Mat t = plainTexture(w, h, {0.10f, 0.16f, 0.24f});
    const int b = static_cast<int>(0.04 / kTexel);
    paintPhoto(t, cv::Rect(b, b, t.cols - 2 * b, t.rows - 2 * b), rng);
    return t;
}

/// A calendar: white paper, a photograph on the upper half, a grid of days below (lines 1 cm
/// apart... 5 cm cells, dark lines and numbers).
cv::Mat calendar(double w, double h, cv::RNG &rng) {
    cv::Mat t = plainTexture(w, h, {0.92f, 0.92f, 0.92f});
    // row ~ b: row 0 is the bottom edge. Photo on the top half.
    paintPhoto(t, cv::Rect(2, t.rows / 2, t.cols - 4, t.rows / 2 - 2), rng);
    const int cell = static_cast<int>(0.05 / kTexel);
    for (int y = 4; y < t.rows / 2 - 2; y += cell) cv::line(t, {2, y}, {t.cols - 3, y}, cv::Scalar(0.1, 0.1, 0.1), 1);
    for (int x = 2; x < t.cols - 2; x += cell) cv::line(t, {x, 4}, {x, t.rows / 2 - 4}, cv::Scalar(0.1, 0.1, 0.1), 1);
    for (int y = 6; y < t.rows / 2 - 4; y += cell)
        for (int x = 4; x < t.cols - 6; x += cell)
            cv::rectangle(t, {x, y, 3, 4}, cv::Scalar(0.15, 0.15, 0.6), cv::FILLED);
    return t;
}

/// A busy poster: stripes, chequers and blobs in strong colours.
cv::Mat busyPoster(double w, double h, cv::RNG &rng) {
    cv::Mat t = plainTexture(w, h, {0.9f, 0.8f, 0.2f});
    for (int x = 0; x < t.cols; x += 8) cv::rectangle(t, {x, 0, 4, t.rows}, randomColour(rng), cv::FILLED);
    paintPhoto(t, cv::Rect(t.cols / 6, t.rows / 5, t.cols * 2 / 3, t.rows * 3 / 5), rng);
    return t;
}

/// A flat thing on the wall (kFlat proud), its texture, its own emission.
void addThing(Scene &scene, const WallFrame &w, double s0, double s1, double h0, double h1, const cv::Mat &texture,
              const cv::Vec3f &albedo, float emission, const std::string &label) {
    Quad q;
    q.corner = w.at(s0, h0, kFlat);
    q.edge_a = (s1 - s0) * w.right;
    q.edge_b = (h1 - h0) * w.up;
    q.albedo = albedo;
    q.texture = texture;
    q.emission = emission;
    q.label = label;
    scene.quads.push_back(q);
}

}  // namespace

const std::vector<std::string> &colourSceneNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n{"pictures", "calendar_poster", "tv_flat", "window_pane", "dark_panel", "mixed"};
        for (const auto &p : paints()) n.push_back(std::string("plain_") + p.name);
        return n;
    }();
    return names;
}

const std::vector<ColourCase> &colourSuiteCases() {
    static const std::vector<ColourCase> cases{
        {"pictures", 2.5, 0.0},        {"pictures", 3.0, 20.0},    {"calendar_poster", 2.0, -10.0},
        {"tv_flat", 2.5, 10.0},        {"window_pane", 2.5, 0.0},  {"dark_panel", 2.0, 0.0},
        {"mixed", 3.0, 0.0},           {"plain_white", 2.5, 0.0},  {"plain_beige", 2.0, 15.0},
        {"plain_pale_blue", 3.0, 0.0}, {"plain_sage", 2.5, -20.0}, {"plain_terracotta", 2.5, 0.0},
        {"plain_grey", 3.5, 0.0},
    };
    return cases;
}

ColourScene makeColourScene(const std::string &name, double distance, double angle_deg) {
    const auto &names = colourSceneNames();
    if (std::find(names.begin(), names.end(), name) == names.end())
        throw std::invalid_argument("unknown colour scene '" + name + "'");
    ColourScene cs;
    cs.scenario = makeRealisticScenario("plain_bowed", distance, angle_deg);
    cs.scenario.name = name;
    Scene &scene = cs.scenario.scene;
    const WallFrame w(distance, angle_deg);
    cv::RNG rng(0x15u + static_cast<unsigned>(std::hash<std::string>{}(name)&0xffff));
    auto thing = [&](double s0, double s1, double h0, double h1, const cv::Mat &texture, const cv::Vec3f &albedo,
                     float emission, const std::string &label) {
        addThing(scene, w, s0, s1, h0, h1, texture, albedo, emission, label);
        cs.unfit.push_back({s0, s1, h0, h1});
    };
    if (name.rfind("plain_", 0) == 0) {
        cs.plain = true;
        for (const auto &p : paints())
            if (name == std::string("plain_") + p.name)
                for (auto &q : scene.quads)
                    if (q.surface == 0) q.albedo = p.bgr;
        cs.scenario.description = "a plain wall painted " + name.substr(6);
        return cs;
    }
    if (name == "pictures" || name == "mixed") {
        thing(-0.55, 0.05, 1.05, 1.50, framedPicture(0.60, 0.45, rng), {}, 0.0f, "picture");
        thing(0.25, 0.75, 0.95, 1.65, framedPicture(0.50, 0.70, rng), {}, 0.0f, "picture");
    }
    if (name == "calendar_poster" || name == "mixed") {
        thing(-0.95, -0.65, 1.00, 1.45, calendar(0.30, 0.45, rng), {}, 0.0f, "calendar");
        thing(0.90, 1.50, 0.80, 1.65, busyPoster(0.60, 0.85, rng), {}, 0.0f, "poster");
    }
    if (name == "tv_flat" || name == "mixed") {
        thing(-1.45, -0.45, 0.95, 1.55, cv::Mat(), {0.03f, 0.03f, 0.035f}, 0.0f, "tv");
    }
    if (name == "window_pane") {
        thing(-0.30, 0.60, 1.00, 1.90, cv::Mat(), {0.8f, 0.8f, 0.8f}, 1.0f,
              "window");  // daylight through frosted glass
    }
    if (name == "dark_panel") {
        thing(-0.40, 0.50, 0.70, 1.30, cv::Mat(), {0.06f, 0.06f, 0.07f}, 0.0f, "panel");
    }
    cs.scenario.description = name + ": flat unfit things on the wall";
    return cs;
}

bool ColourRow::ok() const {
    if (rounds == 0 || found < rounds) return false;
    if (plain) return worst_plain_pct <= 2.0;
    return max_unfit_pct <= 2.0 && min_area_pct >= 95.0;
}

ColourSuiteOptions quickColourSuite() {
    ColourSuiteOptions o;
    o.rounds = 2;
    return o;
}

namespace {

/// The wall's (s, h) box of a rectangle.
std::array<double, 4> wallBoxOf(const Rectangle &r, const WallFrame &w) {
    std::array<double, 4> b{1e9, -1e9, 1e9, -1e9};
    for (const auto &c : r.corners) {
        const Eigen::Vector3d q = c - w.origin;
        const double s = q.dot(w.right), h = q.dot(w.up);
        b[0] = std::min(b[0], s), b[1] = std::max(b[1], s), b[2] = std::min(b[2], h), b[3] = std::max(b[3], h);
    }
    return b;
}

double overlap(const std::array<double, 4> &a, const std::array<double, 4> &b) {
    return std::max(0.0, std::min(a[1], b[1]) - std::max(a[0], b[0])) *
           std::max(0.0, std::min(a[3], b[3]) - std::max(a[2], b[2]));
}

/// % of the rectangle on unfit things.
double unfitPct(const Detection &det, const ColourScene &cs, const WallFrame &w) {
    if (!det.found || det.rectangle.area() <= 0) return 0.0;
    const auto box = wallBoxOf(det.rectangle, w);
    double on = 0.0;
    for (const auto &u : cs.unfit) on += overlap(box, u);
    return 100.0 * on / det.rectangle.area();
}

/// The largest rectangle on fit wall as the detector sees the wall: its free cells with
/// suitability off (the shown plane's raster, footprint applied) without the unfit things.
double suitableBest(const Detection &off, const ColourScene &cs, const WallFrame &w, double aspect) {
    const DetectionDebug &g = off.debug;
    if (!off.found || g.free_space.empty() || g.grid_cell <= 0) return 0.0;
    cv::Mat mask = g.free_space.clone();
    for (int r = 0; r < mask.rows; ++r)
        for (int c = 0; c < mask.cols; ++c) {
            const Eigen::Vector2d uv(g.grid_origin.x() + (c + 0.5) * g.grid_cell,
                                     g.grid_origin.y() - (r + 0.5) * g.grid_cell);
            const Eigen::Vector3d q = g.frame.toCamera(uv) - w.origin;
            const double s = q.dot(w.right), h = q.dot(w.up);
            for (const auto &u : cs.unfit)
                if (s >= u[0] && s <= u[1] && h >= u[2] && h <= u[3]) mask.at<uchar>(r, c) = 0;
        }
    RasterFrame raster;
    raster.top_left = g.grid_origin;
    raster.cell = g.grid_cell;
    raster.cols = mask.cols;
    raster.rows = mask.rows;
    const auto rect = largestFreeRectangle(mask, raster, g.frame, aspect, Eigen::Vector2d::Zero());
    return rect ? rect->area() : 0.0;
}

}  // namespace

ColourSuiteResult runColourSuite(const ColourSuiteOptions &o, const DetectorConfig &config,
                                 const std::function<void(int, int, const std::string &)> &progress) {
    const auto t0 = std::chrono::steady_clock::now();
    ColourSuiteResult res;
    res.rounds = o.rounds;
    const Projector projector = exampleProjector();
    const int total = static_cast<int>(o.cases.size()) * o.rounds;
    int done = 0;
    Lighting light;
    light.ambient = o.ambient;
    for (std::size_t ci = 0; ci < o.cases.size(); ++ci) {
        const ColourCase &cc = o.cases[ci];
        const ColourScene cs = makeColourScene(cc.scene, cc.distance, cc.angle_deg);
        const Scenario &sc = cs.scenario;
        const WallFrame w(cc.distance, cc.angle_deg);
        ColourRow row;
        row.scene = cc;
        row.plain = cs.plain;
        row.min_area_pct = 1e9;
        TruthOptions topt;
        topt.cell = o.truth_cell;
        topt.aspect = projector.aspect();
        const DepthSensor any = makeDepthSensor(SensorKind::Kinect1, 0);
        const GroundTruth truth = computeGroundTruth(sc.scene, any.truthModel(), projector, sc.gravity, topt);
        row.depth_best = truth.found ? truth.best.rectangle.area() : 0.0;
        const ExactDepth exact = castExactDepth(sc.scene, any.camera());
        const cv::Mat clean = renderView(sc.scene, cameraView(exact.camera), std::nullopt, light);
        std::vector<double> times;
        double area = 0.0, area_off = 0.0, fit_sum = 0.0;
        for (int r = 0; r < o.rounds; ++r) {
            const DepthSensor unit = makeDepthSensor(SensorKind::Kinect1, r);
            const unsigned seed = o.seed + 1000u * static_cast<unsigned>(ci) + static_cast<unsigned>(r);
            RgbdFrame frame;
            fillFrameDepth(measureDepth(sc.scene, exact, unit, seed), exact.camera, frame);
            cv::Mat noise(clean.size(), CV_16SC3);
            cv::RNG rng(seed);
            rng.fill(noise, cv::RNG::NORMAL, 0.0, o.rgb_noise);
            cv::Mat rgb;
            clean.convertTo(rgb, CV_16SC3);
            rgb += noise;
            rgb.convertTo(rgb, CV_8UC3);
            attachColour(frame.cloud, rgb);
            DetectorConfig cfg = config;
            cfg.seed = seed;
            if (cfg.suitability.mode == SuitabilityMode::Off) cfg.suitability.mode = SuitabilityMode::Avoid;
            const Detection det = detectSurface(frame.cloud, projector, cfg, sc.gravity);
            cfg.suitability.mode = SuitabilityMode::Off;
            const Detection off = detectSurface(frame.cloud, projector, cfg, sc.gravity);
            ++row.rounds;
            row.found += det.found;
            const double a = det.found ? det.rectangle.area() : 0.0, a_off = off.found ? off.rectangle.area() : 0.0;
            area += a;
            area_off += a_off;
            row.max_unfit_pct = std::max(row.max_unfit_pct, unfitPct(det, cs, w));
            row.max_off_unfit_pct = std::max(row.max_off_unfit_pct, unfitPct(off, cs, w));
            const double fit = suitableBest(off, cs, w, projector.aspect());
            fit_sum += fit;
            row.min_area_pct = std::min(row.min_area_pct, fit > 0 ? 100.0 * a / fit : 0.0);
            if (a_off > 0) row.worst_plain_pct = std::max(row.worst_plain_pct, 100.0 * std::abs(a / a_off - 1.0));
            if (det.timing_ms.count("suitability")) times.push_back(det.timing_ms.at("suitability"));
            if (progress) progress(++done, total, "colour " + cc.scene);
        }
        row.mean_area = row.rounds ? area / row.rounds : 0.0;
        row.mean_area_off = row.rounds ? area_off / row.rounds : 0.0;
        row.suitable_best = row.rounds ? fit_sum / row.rounds : 0.0;
        if (row.min_area_pct > 1e8) row.min_area_pct = 0.0;
        row.suitability_ms = times.empty() ? 0.0 : quantile(times, 0.5);
        res.rows.push_back(row);
    }
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
}

std::string colourSuiteMarkdown(const ColourSuiteResult &result) {
    std::ostringstream md;
    md << "Scenes of `sim/colour_suite.hpp` (realistic Kinect v1 depth, registered colour under room light), "
       << result.rounds
       << " rounds each, default method with `--suitability avoid` and, for comparison, `off`. Targets: "
          "the rectangle on unfit things <= 2 % of its area in every round and >= 95 % of the largest rectangle on "
          "fit wall (fit best: the largest rectangle on the detector's own free cells with suitability off, the "
          "unfit things taken out; mean over the rounds); on plain walls the area within 2 % of `off`. Depth truth "
          "best: the simulator's ground truth of the wall by depth alone.\n\n";
    md << "| scene | distance | angle | depth truth best | fit best | area (avoid) | worst on unfit | worst area / fit "
          "best | area (off) | "
          "worst on unfit (off) | plain: worst vs off | suitability ms | target |\n";
    md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto &r : result.rows) {
        md << "| " << r.scene.scene << " | " << formatted("%.1f m", r.scene.distance) << " | "
           << formatted("%.0f°", r.scene.angle_deg) << " | " << formatted("%.2f m²", r.depth_best) << " | "
           << formatted("%.2f m²", r.suitable_best) << " | " << formatted("%.2f m²", r.mean_area) << " | "
           << (r.plain ? std::string("-") : formatted("%.1f %%", r.max_unfit_pct)) << " | "
           << (r.plain ? std::string("-") : formatted("%.0f %%", r.min_area_pct)) << " | "
           << formatted("%.2f m²", r.mean_area_off) << " | "
           << (r.plain ? std::string("-") : formatted("%.0f %%", r.max_off_unfit_pct)) << " | "
           << (r.plain ? formatted("%.1f %%", r.worst_plain_pct) : std::string("-")) << " | "
           << formatted("%.2f", r.suitability_ms) << " | " << (r.ok() ? "holds" : "**misses**") << " |\n";
    }
    return md.str();
}

std::string colourSuiteSummary(const ColourSuiteResult &result) {
    int ok = 0;
    for (const auto &r : result.rows) ok += r.ok();
    return "colour suite: " + std::to_string(ok) + " / " + std::to_string(result.rows.size()) +
           " scenes meet the targets (" + std::to_string(result.rounds) + " rounds each, " +
           formatted("%.0f s", result.seconds) + ")";
}

}  // namespace projsurf::eval
