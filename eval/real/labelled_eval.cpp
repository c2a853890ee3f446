#include "eval/real/labelled_eval.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "eval/plot/plot.hpp"
#include "eval/real/label_overlay.hpp"
#include "eval/real/label_reference.hpp"
#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/formatted.hpp"

namespace fs = std::filesystem;

namespace projsurf::eval {
namespace {

/// Written so that it reads back to the same doubles: the command then gives the same answer.
std::string vec(const Eigen::Vector3d &v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", v.x(), v.y(), v.z());
    return buf;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string pct(double share) { return formatted("%.1f", 100.0 * share); }

/// The detector with the frame's registered colour (as `detect --rgb --suitability avoid`: the
/// colour is used only when checkColourRegistration does not reject it), scored with the
/// depth-only answer against the colour-aware label.
ColourRun runWithColour(const LabelledFrame &f, const std::string &dir, const CameraIntrinsics &camera,
                        const Cloud &depth_cloud, const DetectorConfig &config, const cv::Mat &background) {
    ColourRun c;
    c.judged = true;
    c.depth_only = scoreColourRectangle(f.label, camera, f.detection.found, f.detection.rectangle);
    const std::string rgb = dir + "/rgb.png";
    Cloud cloud = depth_cloud;
    std::error_code ec;
    if (!fs::exists(rgb, ec)) {
        c.colour_note = "no registered rgb.png";
    } else {
        const cv::Mat colour = readImage(rgb, cv::IMREAD_COLOR);
        const RegistrationResult r = checkColourRegistration(cloud, colour, config.suitability.registration);
        if (r.checked && !r.registered)
            c.colour_note = "not registered to the depth (" + r.summary() + ")";
        else if (!attachColour(cloud, colour))
            c.colour_note = "not the depth image's size";
        else
            c.colour_used = true;
    }
    c.command = f.command + " --rgb " + rgb + " --suitability avoid";
    if (c.colour_used) {
        DetectorConfig cfg = config;
        cfg.suitability.mode = SuitabilityMode::Avoid;
        const Detection det = detectSurface(cloud, f.label.projector, cfg, f.label.gravity);
        c.detection.name = f.name;
        c.detection.read = true;
        c.detection.found = det.found;
        c.detection.reason = det.reason;
        if (det.found) {
            c.detection.rectangle = det.rectangle;
            c.detection.width = det.rectangle.width;
            c.detection.height = det.rectangle.height;
            c.detection.area = det.rectangle.area();
        }
    } else {
        c.detection = f.detection;
    }
    c.with_colour = scoreColourRectangle(f.label, camera, c.detection.found, c.detection.rectangle);
    cv::Mat img =
        renderColourLabelOverlay(background, f.label, camera, c.detection.found ? &c.detection.rectangle : nullptr,
                                 f.detection.found ? &f.detection.rectangle : nullptr);
    std::string caption = f.name + ": ";
    if (!c.detection.found)
        caption += "nothing found";
    else
        caption += formatted("%.3f m^2", c.detection.area) +
                   formatted(", %.0f %% unsuitable", 100.0 * c.with_colour.unsuitable_share) +
                   (c.colour_used ? formatted(" (depth only %.0f %%)", 100.0 * c.depth_only.unsuitable_share)
                                  : std::string(" (colour not used)"));
    caption +=
        f.label.colour.best.found ? ", best " + formatted("%.3f", f.label.colour.best.area()) : ", no usable surface";
    c.overlay = withCaption(img, caption, 0.45);
    return c;
}

/// At least `projsurf detect`'s default minimum picture size.
bool atLeastMinimumSize(double width, double height) {
    Rectangle r;
    r.width = width;
    r.height = height;
    return frontend::belowMinimum(r, frontend::defaultMinimumSize(Method::Default), "", "--min-width", "--min-area")
        .empty();
}

/// The detector with the example calibration's projector: validity against the label, and the
/// reference search with the same projector to tell a miss from rightly nothing.
ExampleRun runWithExampleProjector(const LabelledFrame &f, const std::string &dir, const CameraIntrinsics &camera,
                                   const Cloud &cloud, const DetectorConfig &config, const cv::Mat &background) {
    ExampleRun e;
    RealLabel label = f.label;
    label.projector = sim::exampleProjector();
    e.reference = referenceBest(cloud, camera, label);
    label.best = e.reference;
    e.detection = detectRealFrame(dir, label.projector, config, f.label.gravity);
    e.command = "projsurf detect --depth " + dir + "/depth.png --camera " + dir +
                "/camera.yaml --calib examples/calib/example_calib.yaml --gravity " + vec(f.label.gravity) +
                " --seed " + std::to_string(config.seed);
    e.score = scoreRealRectangle(label, camera, e.detection.found, e.detection.rectangle);
    e.off_surface = e.detection.found && !e.score.valid;
    e.right = e.score.valid || (!e.detection.found && !e.reference.found);
    e.shown = e.detection.found && atLeastMinimumSize(e.detection.width, e.detection.height);
    e.reference_shown = e.reference.found && atLeastMinimumSize(e.reference.width, e.reference.height);
    e.right_shown = e.shown ? e.score.valid : !e.reference_shown;
    cv::Mat img = renderLabelOverlay(background, label, camera, e.detection.found ? &e.detection.rectangle : nullptr);
    std::string caption = f.name + " (example calibration): ";
    if (!e.detection.found)
        caption += "nothing found";
    else
        caption +=
            formatted("%.3f m^2", e.detection.area) + (e.score.valid ? ", valid" : ", INVALID (" + e.score.why + ")");
    caption += e.reference.found ? ", reference " + formatted("%.3f m^2", e.reference.area()) : ", reference: nothing";
    e.overlay = withCaption(img, caption, 0.45);
    return e;
}

}  // namespace

std::vector<unsigned> stabilitySeeds() { return {1, 2, 3, 4, 5, 42}; }

LabelledFrame evaluateLabelledFrame(const std::string &label_path, const std::string &real_dir,
                                    const DetectorConfig &config, const std::vector<unsigned> &seeds) {
    LabelledFrame f;
    f.label_path = label_path;
    f.name = fs::path(label_path).stem().string();
    f.label = readRealLabel(label_path);
    f.name = f.label.frame;
    const std::string dir = (fs::path(real_dir) / f.label.frame).string();
    const std::string cam_yaml = dir + "/camera.yaml";
    const CameraIntrinsics camera = readCamera(cam_yaml);
    const Cloud cloud = readDepthCloud(dir + "/depth.png", cam_yaml);
    cv::Mat background;
    std::error_code ec;
    if (fs::exists(dir + "/rgb.png", ec)) background = readImage(dir + "/rgb.png", cv::IMREAD_COLOR);
    if (background.cols != cloud.width || background.rows != cloud.height) background = depthColour(cloud);

    const DetectorConfig &cfg = config;
    f.detection = detectRealFrame(dir, f.label.projector, cfg, f.label.gravity);
    if (!f.detection.read) throw InputError(f.detection.problem);
    f.command = "projsurf detect --depth " + dir + "/depth.png --camera " + dir + "/camera.yaml --calib " + label_path +
                " --gravity " + vec(f.label.gravity) + " --seed " + std::to_string(cfg.seed);
    f.score = scoreRealRectangle(f.label, camera, f.detection.found, f.detection.rectangle);

    double lo = 1e9, hi = 0.0;
    for (unsigned seed : seeds) {
        DetectorConfig c = cfg;
        c.seed = seed;
        const GalleryEntry g =
            seed == cfg.seed ? f.detection : detectRealFrame(dir, f.label.projector, c, f.label.gravity);
        SeedRun run;
        run.seed = seed;
        run.found = g.found;
        run.area = g.found ? g.area : 0.0;
        run.valid = scoreRealRectangle(f.label, camera, g.found, g.rectangle).right;
        if (g.found) run.centre = g.rectangle.center();
        if (run.valid != f.score.right) f.seed_same_validity = false;
        if (g.found && f.detection.found)
            f.seed_shift = std::max(f.seed_shift, (run.centre - f.detection.rectangle.center()).norm());
        lo = std::min(lo, run.area);
        hi = std::max(hi, run.area);
        f.seeds.push_back(run);
    }
    f.seed_spread = hi > 0 ? (hi - lo) / hi : 0.0;

    // The same frame handed over unorganized, and on a grid moved by a pixel or three.
    const Detection organized = detectSurface(cloud, f.label.projector, cfg, f.label.gravity);
    f.unorganized = unorganizedVariant(cloud, organized, f.label.projector, cfg, f.label.gravity);
    f.shifted = shiftedVariants(cloud, organized, f.label.projector, cfg, f.label.gravity);

    cv::Mat img = renderLabelOverlay(background, f.label, camera, f.detection.found ? &f.detection.rectangle : nullptr);
    std::string caption = f.name + ": ";
    if (!f.score.found)
        caption += "nothing found";
    else
        caption +=
            formatted("%.3f m^2", f.score.area) + (f.score.valid ? ", valid" : ", INVALID (" + f.score.why + ")");
    caption +=
        f.label.best.found ? ", label best " + formatted("%.3f m^2", f.label.best.area()) : ", no usable surface";
    f.overlay = withCaption(img, caption, 0.45);
    if (f.label.colour.judged) f.colour = runWithColour(f, dir, camera, cloud, cfg, background);
    f.example = runWithExampleProjector(f, dir, camera, cloud, cfg, background);
    return f;
}

LabelledSummary summariseLabelled(const std::vector<LabelledFrame> &frames) {
    LabelledSummary s;
    std::vector<double> ratios;
    for (const auto &f : frames) {
        ++s.frames;
        if (f.score.right) ++s.right;
        if (f.score.has_best) {
            ++s.with_best;
            ratios.push_back(f.score.ratio);
        }
        if (f.seed_spread <= 0.02 && f.seed_same_validity) ++s.seed_stable;
        s.unorganized_agree += f.unorganized.agrees;
        s.shift_stable += std::all_of(f.shifted.begin(), f.shifted.end(), [](const VariantRun &r) { return r.agrees; });
    }
    s.median_ratio = median(ratios);
    s.worst_ratio = ratios.empty() ? 0.0 : *std::min_element(ratios.begin(), ratios.end());
    return s;
}

std::string labelledSummaryLine(const LabelledSummary &s) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "labelled real frames: %d of %d right; area ratio median %.2f, worst %.2f (%d with a best "
                  "rectangle, invalid = 0); seed-stable %d of %d; unorganized cloud agrees %d of %d; "
                  "shift-stable %d of %d",
                  s.right, s.frames, s.median_ratio, s.worst_ratio, s.with_best, s.seed_stable, s.frames,
                  s.unorganized_agree, s.frames, s.shift_stable, s.frames);
    return buf;
}

std::string halvesTable(const std::vector<LabelledFrame> &frames) {
    std::vector<std::vector<LabelledFrame>> parts(3);  // all, tune, check
    for (const auto &f : frames) {
        parts[0].push_back(f);
        if (f.label.split == "tune") parts[1].push_back(f);
        if (f.label.split == "check") parts[2].push_back(f);
    }
    std::vector<std::vector<std::string>> rows;
    const auto add = [&rows](const std::string &figure, const std::vector<std::string> &cells) {
        rows.push_back({figure});
        rows.back().insert(rows.back().end(), cells.begin(), cells.end());
    };
    std::vector<std::string> frames_c, right, invalid, median_c, worst, seed, unorg, shift, ex_right, ex_off, colour;
    for (const auto &part : parts) {
        const LabelledSummary l = summariseLabelled(part);
        const ExampleSummary e = summariseExample(part);
        const ColourSummary c = summariseColour(part);
        const int n = l.frames;
        const auto of = [](int k, int total) { return std::to_string(k) + " / " + std::to_string(total); };
        const int bad = static_cast<int>(
            std::count_if(part.begin(), part.end(), [](const LabelledFrame &f) { return f.score.found && !f.score.valid; }));
        frames_c.push_back(std::to_string(n));
        right.push_back(of(l.right, n) + (n ? formatted(" (%.0f %%)", 100.0 * l.right / n) : ""));
        invalid.push_back(std::to_string(bad));
        median_c.push_back(formatted("%.2f", l.median_ratio));
        worst.push_back(formatted("%.2f", l.worst_ratio));
        seed.push_back(of(l.seed_stable, n));
        unorg.push_back(of(l.unorganized_agree, n));
        shift.push_back(of(l.shift_stable, n));
        ex_right.push_back(of(e.right_shown, e.frames));
        ex_off.push_back(std::to_string(e.off_shown));
        colour.push_back(c.judged ? of(c.right_colour, c.judged) : "-");
    }
    add("frames", frames_c);
    add("right (valid, or rightly nothing)", right);
    add("answers not valid (off the surface, on an obstacle)", invalid);
    add("area ratio, median", median_c);
    add("area ratio, worst", worst);
    add("seed-stable", seed);
    add("unorganized cloud agrees", unorg);
    add("shift-stable", shift);
    add("example calibration, right as detect shows", ex_right);
    add("example calibration, off the labelled surfaces", ex_off);
    add("with colour, right (frames judged on colour)", colour);
    std::ostringstream md;
    md << "| figure | all | tune | check |\n|---|---:|---:|---:|\n";
    for (const auto &r : rows) md << "| " << r[0] << " | " << r[1] << " | " << r[2] << " | " << r[3] << " |\n";
    return md.str();
}

ExampleSummary summariseExample(const std::vector<LabelledFrame> &frames) {
    ExampleSummary s;
    for (const auto &f : frames) {
        const ExampleRun &e = f.example;
        ++s.frames;
        s.right += e.right;
        s.valid += e.score.valid;
        s.off_surface += e.off_surface;
        s.missed += !e.detection.found && e.reference.found;
        s.rightly_none += !e.detection.found && !e.reference.found;
        s.right_shown += e.right_shown;
        s.valid_shown += e.shown && e.score.valid;
        s.off_shown += e.shown && !e.score.valid;
        s.missed_shown += !e.shown && e.reference_shown;
        s.none_shown += !e.shown && !e.reference_shown;
    }
    return s;
}

std::string exampleSummaryLine(const ExampleSummary &s) {
    using std::to_string;
    return "labelled real frames, example calibration: " + to_string(s.right) + " of " + to_string(s.frames) +
           " right; " + to_string(s.valid) + " valid, " + to_string(s.off_surface) +
           " off the labelled surfaces (furniture, obstacles), " + to_string(s.missed) + " missed, " +
           to_string(s.rightly_none) + " rightly nothing";
}

std::string exampleShownSummaryLine(const ExampleSummary &s) {
    using std::to_string;
    const frontend::MinimumSize m = frontend::defaultMinimumSize(Method::Default);
    return "labelled real frames, example calibration, as detect shows them (at least " + formatted("%.2f", m.width) +
           " m wide and " + formatted("%.3f", m.area) + " m^2): " + to_string(s.right_shown) + " of " +
           to_string(s.frames) + " right; " + to_string(s.valid_shown) + " valid, " + to_string(s.off_shown) +
           " off the labelled surfaces, " + to_string(s.missed_shown) + " missed, " + to_string(s.none_shown) +
           " rightly nothing";
}

std::string exampleReportMarkdown(const std::vector<LabelledFrame> &frames, const std::string &pictures) {
    std::ostringstream md;
    md << "### With the example calibration\n\n"
          "The same frames with one projector for all, `examples/calib/example_calib.yaml` (what a user has before "
          "calibrating), and the label's gravity. Judged for validity only: a rectangle must be valid on a labelled "
          "surface as above (so not on furniture, a person or an obstacle: the target is none off the labelled "
          "surfaces); nothing found is right where the reference search with this projector (blue) finds no usable "
          "surface either, a *miss* otherwise.\n\n";
    const ExampleSummary summary = summariseExample(frames);
    md << "**" << exampleSummaryLine(summary) << ".**\n\n";
    md << "`projsurf detect` does not show a picture below its minimum size (`--min-width`, `--min-area`): the "
          "column *as shown* judges what it reports, where a smaller answer is found: false and a smaller reference "
          "means no usable surface.\n\n**"
       << exampleShownSummaryLine(summary) << ".**\n\n";
    md << "| Frame | reference (m²) | detector (m²) | right | as shown | free % | surface | why not "
          "|\n|---|---:|---:|---|---|---:|---|---|\n";
    for (const auto &f : frames) {
        const ExampleRun &e = f.example;
        md << "| [" << f.name << "](" << pictures << "/" << f.name << "_example.png) | "
           << (e.reference.found ? formatted("%.3f", e.reference.area()) : "none") << " | "
           << (e.detection.found ? formatted("%.3f", e.detection.area) : "—") << " | "
           << (e.right         ? "yes"
               : e.off_surface ? "**no: off**"
                               : "**no: miss**")
           << " | "
           << (e.right_shown ? "yes"
               : e.shown     ? "**no: off**"
                             : "**no: miss**")
           << " | " << (e.detection.found ? formatted("%.0f", 100.0 * e.score.free_fraction) : "") << " | "
           << e.score.surface << " | " << (e.score.valid || !e.detection.found ? "" : e.score.why) << " |\n";
    }
    md << "\nCommand: `projsurf detect --depth <frame>/depth.png --camera <frame>/camera.yaml --calib "
          "examples/calib/example_calib.yaml --gravity <label gravity>`.\n\n";
    return md.str();
}

std::string exampleCsv(const std::vector<LabelledFrame> &frames) {
    std::ostringstream csv;
    csv << "frame,reference_m2,area_m2,right,off_surface,free,surface,why,right_as_shown\n";
    for (const auto &f : frames) {
        const ExampleRun &e = f.example;
        csv << f.name << "," << (e.reference.found ? formatted("%.4f", e.reference.area()) : "") << ","
            << (e.detection.found ? formatted("%.4f", e.detection.area) : "") << "," << (e.right ? "yes" : "no") << ","
            << (e.off_surface ? "yes" : "no") << "," << formatted("%.3f", e.score.free_fraction) << ","
            << e.score.surface << ",\"" << (e.score.valid ? "" : e.score.why) << "\"," << (e.right_shown ? "yes" : "no")
            << "\n";
    }
    return csv.str();
}

ColourSummary summariseColour(const std::vector<LabelledFrame> &frames) {
    ColourSummary s;
    std::vector<double> ratio_depth, ratio_colour;
    for (const auto &f : frames) {
        const ColourRun &c = f.colour;
        if (!c.judged) continue;
        ++s.judged;
        if (c.colour_used) ++s.colour_used;
        const auto count = [](const ColourScore &a, int &right, int &found, int &clean, double &worst,
                              std::vector<double> &ratios) {
            right += a.score.right;
            found += a.score.found;
            clean += a.clean();
            worst = std::max(worst, a.unsuitable_share);
            if (a.score.has_best) ratios.push_back(a.score.ratio);
        };
        if (!f.label.colour.best.found) {  // no usable surface: right or not, and no wall to be clean
            s.right_depth += c.depth_only.score.right;
            s.right_colour += c.with_colour.score.right;
            continue;
        }
        ++s.with_best;
        count(c.depth_only, s.right_depth, s.found_depth, s.clean_depth, s.worst_share_depth, ratio_depth);
        count(c.with_colour, s.right_colour, s.found_colour, s.clean_colour, s.worst_share_colour, ratio_colour);
    }
    s.median_ratio_depth = median(ratio_depth);
    s.median_ratio_colour = median(ratio_colour);
    return s;
}

std::string colourSummaryLine(const ColourSummary &s) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "labelled real frames with colour: %d judged (%d with registered colour); right %d with colour, %d "
                  "depth only; of the %d with a usable surface, on clean wall (found, <= 2 %% over unsuitable) %d with "
                  "colour, %d depth only; area / colour best median %.2f with colour, %.2f depth only (invalid = 0); "
                  "worst share over unsuitable %.1f %% with colour, %.1f %% depth only",
                  s.judged, s.colour_used, s.right_colour, s.right_depth, s.with_best, s.clean_colour, s.clean_depth,
                  s.median_ratio_colour, s.median_ratio_depth, 100.0 * s.worst_share_colour,
                  100.0 * s.worst_share_depth);
    return buf;
}

std::string colourReportMarkdown(const std::vector<LabelledFrame> &frames, const std::string &pictures) {
    const ColourSummary s = summariseColour(frames);
    std::ostringstream md;
    if (s.judged == 0) return md.str();
    md << "### With colour\n\n"
          "The labels of the frames with a registered `rgb.png` also name what the picture should not be shown on "
          "although depth calls it free (orange; `labels/README.md`, section *Colour*); the colour-aware best (blue) "
          "is the reference's search with those polygons as further obstacles. The detector runs once more with "
          "the frame's colour (as `detect --rgb <frame>/rgb.png --suitability avoid`; the colour is used only when "
          "the registration check passes), its rectangle in magenta, the depth-only answer above in white. Both "
          "are scored against the colour-aware label: *right* and *ratio* (area / colour best) as above, and the "
          "share of the rectangle's area over unsuitable polygons (the target: ≤ 2 %).\n\n";
    md << "**" << colourSummaryLine(s) << ".**\n\n";
    md << "| Frame | colour | colour best (m²) | unsuitable polygons | depth only: m² | ratio | right | % unsuitable | "
          "with colour: m² | ratio | right | % unsuitable | why not (with colour) |\n"
          "|---|---|---:|---:|---:|---:|---|---:|---:|---:|---|---:|---|\n";
    for (const auto &f : frames) {
        const ColourRun &c = f.colour;
        if (!c.judged) continue;
        md << "| [" << f.name << "](" << pictures << "/" << f.name << "_colour.png) | "
           << (c.colour_used ? "used" : "not used: " + c.colour_note) << " | "
           << (f.label.colour.best.found ? formatted("%.3f", f.label.colour.best.area()) : "none") << " | "
           << f.label.colour.unsuitable.size() << " | ";
        for (const ColourScore *a : {&c.depth_only, &c.with_colour})
            md << (a->score.found ? formatted("%.3f", a->score.area) : "—") << " | "
               << (a->score.has_best ? formatted("%.2f", a->score.ratio) : "") << " | "
               << (a->score.right ? "yes" : "**no**") << " | "
               << (a->score.found ? pct(a->unsuitable_share) + (a->clean() ? "" : " ✗") : "") << " | ";
        md << (c.with_colour.score.right ? "" : c.with_colour.score.why) << " |\n";
    }
    md << "\n✗ = more than 2 % of the rectangle over unsuitable polygons. Command with colour: `projsurf detect "
          "--depth <frame>/depth.png --camera <frame>/camera.yaml --calib <label file> --gravity <label gravity> "
          "--rgb <frame>/rgb.png --suitability avoid`.\n\n";
    return md.str();
}

std::string colourCsv(const std::vector<LabelledFrame> &frames) {
    std::ostringstream csv;
    csv << "frame,colour_used,colour_best_m2,unsuitable_polygons,depth_area_m2,depth_ratio,depth_right,depth_"
           "unsuitable,"
           "colour_area_m2,colour_ratio,colour_right,colour_unsuitable,why\n";
    for (const auto &f : frames) {
        const ColourRun &c = f.colour;
        if (!c.judged) continue;
        csv << f.name << "," << (c.colour_used ? "yes" : "no") << ","
            << (f.label.colour.best.found ? formatted("%.4f", f.label.colour.best.area()) : "") << ","
            << f.label.colour.unsuitable.size();
        for (const ColourScore *a : {&c.depth_only, &c.with_colour})
            csv << "," << (a->score.found ? formatted("%.4f", a->score.area) : "") << ","
                << formatted("%.4f", a->score.ratio) << "," << (a->score.right ? "yes" : "no") << ","
                << formatted("%.4f", a->unsuitable_share);
        csv << ",\"" << c.with_colour.score.why << "\"\n";
    }
    return csv.str();
}

std::string labelledReportMarkdown(const std::vector<LabelledFrame> &frames, const std::string &labels_dir,
                                   const std::string &pictures) {
    std::ostringstream md;
    md << "## Labelled real frames\n\n";
    if (frames.empty()) {
        md << "No label files were found" << (labels_dir.empty() ? "" : " in `" + labels_dir + "`") << ".\n\n";
        return md.str();
    }
    const LabelledSummary s = summariseLabelled(frames);
    md << "Each frame has a hand-made label in `" << labels_dir
       << "` (see `labels/README.md`): the gravity and a virtual projector to use, the usable surfaces (green), "
          "the obstacles (red) and the reference's best rectangle (blue; the projector's footprint in yellow). "
          "The detector (default method, its rectangle in magenta) runs with the label's projector and gravity, "
          "as the command in each frame's picture link would. **Valid** = upright (sides within 2° of gravity), "
          "within max(5 cm, 3 % of the range) of a labelled surface's plane and at least 95 % of its area free by the "
          "labels (so a valid answer may exceed the label's best by a few percent); a frame "
          "whose label has no usable surface is right when nothing is found. *Ratio* = area / label best for a "
          "valid answer, 0 otherwise. Seeds 1-5 and 42: area spread (max − min) / max, and how far the "
          "rectangle's centre moves.\n\n";
    md << "**" << labelledSummaryLine(s)
       << ".** Targets: every answer right, ratio ≥ 0.90, seed spread "
          "≤ 2 %.\n\n";
    md << "By half (the label's `split`; labels/README.md, *The two halves*: a detection change is chosen on the "
          "tune half and kept only if the check half does not get worse):\n\n"
       << halvesTable(frames) << "\n";
    md << "![labelled frames](" << pictures << "/contact_sheet.png)\n\n";
    md << "| Frame | label best (m²) | detector (m²) | ratio | right | free % | why not | seed areas (m²) | spread | "
          "centre moves (m) |\n|---|---:|---:|---:|---|---:|---|---|---:|---:|\n";
    for (const auto &f : frames) {
        md << "| [" << f.name << "](" << pictures << "/" << f.name << ".png) | ";
        md << (f.label.best.found ? formatted("%.3f", f.label.best.area()) : "none") << " | "
           << (f.score.found ? formatted("%.3f", f.score.area) : "—") << " | "
           << (f.score.has_best ? formatted("%.2f", f.score.ratio) : "") << " | " << (f.score.right ? "yes" : "**no**")
           << " | " << (f.score.found ? formatted("%.0f", 100.0 * f.score.free_fraction) : "") << " | "
           << (f.score.right ? "" : f.score.why) << " | ";
        for (std::size_t i = 0; i < f.seeds.size(); ++i)
            md << (i ? " " : "") << (f.seeds[i].found ? formatted("%.3f", f.seeds[i].area) : "—")
               << (f.seeds[i].valid ? "" : "✗");
        md << " | " << formatted("%.1f %%", 100.0 * f.seed_spread) << (f.seed_same_validity ? "" : ", validity changes")
           << " | " << formatted("%.2f", f.seed_shift) << " |\n";
    }
    md << "\n✗ = not right on that seed. Commands: `projsurf detect --depth <frame>/depth.png --camera "
          "<frame>/camera.yaml --calib <label file> --gravity <label gravity> --seed <s>` (the label file holds the "
          "projector block of a calibration file).\n\n";
    md << variantReportMarkdown(frames);
    md << exampleReportMarkdown(frames, pictures);
    md << colourReportMarkdown(frames, pictures);
    return md.str();
}

std::string variantReportMarkdown(const std::vector<LabelledFrame> &frames) {
    std::ostringstream md;
    md << "### The same frames unorganized, and on a shifted pixel grid\n\n"
          "Each frame's finite points shuffled into an unorganized cloud, and its depth image cropped by "
          "(1, 1), (2, 0) and (0, 3) px, detected with the same settings. Agrees: both find nothing, or the "
          "plane within 1 deg and 2 cm of the organized answer's and the area within 10 %.\n\n"
          "| Frame | organized (m²) | unorganized (m²) | plane deg / cm | agrees | cropped (m²) | all agree |\n"
          "|---|---:|---:|---|---|---|---|\n";
    auto area = [](bool found, double a) { return found ? formatted("%.3f", a) : std::string("—"); };
    for (const auto &f : frames) {
        const VariantRun &u = f.unorganized;
        md << "| " << f.name << " | " << area(f.detection.found, f.detection.area) << " | " << area(u.found, u.area)
           << " | "
           << (u.found && f.detection.found
                   ? formatted("%.2f", u.angle_deg) + " / " + formatted("%.1f", 100.0 * u.offset)
                   : "")
           << " | " << (u.agrees ? "yes" : "**no**") << " | ";
        bool all = true;
        for (std::size_t i = 0; i < f.shifted.size(); ++i) {
            md << (i ? " " : "") << area(f.shifted[i].found, f.shifted[i].area);
            all = all && f.shifted[i].agrees;
        }
        md << " | " << (all ? "yes" : "**no**") << " |\n";
    }
    md << "\n";
    return md.str();
}

std::string labelledCsv(const std::vector<LabelledFrame> &frames) {
    std::ostringstream csv;
    csv << "frame,best_m2,area_m2,ratio,right,free,why,seed_areas_m2,seed_spread\n";
    for (const auto &f : frames) {
        csv << f.name << "," << (f.label.best.found ? formatted("%.4f", f.label.best.area()) : "") << ","
            << (f.score.found ? formatted("%.4f", f.score.area) : "") << "," << formatted("%.4f", f.score.ratio) << ","
            << (f.score.right ? "yes" : "no") << "," << formatted("%.3f", f.score.free_fraction) << ",\"" << f.score.why
            << "\",";
        for (std::size_t i = 0; i < f.seeds.size(); ++i)
            csv << (i ? " " : "") << f.seeds[i].seed << ":" << formatted("%.4f", f.seeds[i].area);
        csv << "," << formatted("%.4f", f.seed_spread) << "\n";
    }
    return csv.str();
}

void writeLabelledPictures(const std::string &dir, const std::vector<LabelledFrame> &frames) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    writeFileAtomic((fs::path(dir) / "results.csv").string(), labelledCsv(frames));
    if (summariseColour(frames).judged > 0)
        writeFileAtomic((fs::path(dir) / "colour_results.csv").string(), colourCsv(frames));
    writeFileAtomic((fs::path(dir) / "example_results.csv").string(), exampleCsv(frames));
    std::vector<cv::Mat> panels;
    for (const auto &f : frames) {
        if (!f.example.overlay.empty())
            writeImageAtomic((fs::path(dir) / (f.name + "_example.png")).string(), f.example.overlay);
        if (!f.colour.overlay.empty())
            writeImageAtomic((fs::path(dir) / (f.name + "_colour.png")).string(), f.colour.overlay);
        if (f.overlay.empty()) continue;
        writeImageAtomic((fs::path(dir) / (f.name + ".png")).string(), f.overlay);
        cv::Mat thumb;
        cv::resize(f.overlay, thumb, cv::Size(), 0.6, 0.6, cv::INTER_AREA);
        cv::copyMakeBorder(thumb, thumb, 3, 3, 3, 3, cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255));
        panels.push_back(thumb);
    }
    if (!panels.empty())
        writeImageAtomic(
            (fs::path(dir) / "contact_sheet.png").string(),
            tilePanels(panels, 3,
                       "Labelled real frames: usable (green), obstacles (red), label best (blue), detector (magenta)"));
}

}  // namespace projsurf::eval
