#pragma once
// The labelled real-frame suite: the detector run on every labelled frame with the label's
// projector and gravity (as `projsurf detect --depth <frame>/depth.png --camera
// <frame>/camera.yaml --calib <label> --gravity gx,gy,gz` would), scored against the label,
// once per seed for stability, with a picture of label and answer per frame. For the labels
// judged on colour, the detector also runs with the frame's registered colour
// (as `detect --rgb <frame>/rgb.png --suitability avoid`), and both answers are scored against
// the colour-aware label.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "eval/real/cloud_variants.hpp"
#include "eval/real/real_gallery.hpp"
#include "eval/real/real_labels.hpp"
#include "eval/real/real_scoring.hpp"

namespace projsurf::eval {

struct SeedRun {
    unsigned seed = 0;
    bool found = false;
    bool valid = false;
    double area = 0.0;  ///< m^2
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// The colour part of a frame whose label has a `colour:` section.
struct ColourRun {
    bool judged = false;       ///< the label has a colour section (nothing else is set otherwise)
    bool colour_used = false;  ///< rgb.png read and registered to the depth (checkColourRegistration)
    std::string colour_note;   ///< why the colour was not used ("" when it was)
    GalleryEntry detection;    ///< with colour, suitability avoid (the depth-only one when not used)
    ColourScore depth_only;    ///< LabelledFrame::detection against the colour-aware label
    ColourScore with_colour;   ///< `detection` against it
    std::string command;       ///< the equivalent `projsurf detect` command line
    cv::Mat overlay;           ///< BGR: renderColourLabelOverlay
};

/// The frame once more with the example calibration's projector (sim::exampleProjector(), as
/// examples/calib/example_calib.yaml) and the label's gravity: a user's first run, one projector
/// for every frame. Scored for validity only: a found rectangle must be valid on a labelled
/// surface (not on furniture, a person or an obstacle); nothing found is right where the
/// reference search with that projector finds no usable surface either.
struct ExampleRun {
    GalleryEntry detection;
    RealScore score;           ///< against the label (its best is the label projector's: ratio unused)
    LabelBest reference;       ///< the reference search with the example projector
    bool right = false;        ///< valid, or nothing found where the reference finds nothing
    bool off_surface = false;  ///< found but not valid: the answer the target forbids
    /// The same as `projsurf detect` reports it: its default minimum picture size
    /// (frontend::defaultMinimumSize) turns a smaller answer into found: false, and a reference
    /// below it means no usable surface at that size.
    bool shown = false;            ///< found and at least the minimum size
    bool reference_shown = false;  ///< the reference is at least the minimum size
    bool right_shown = false;      ///< valid and shown, or nothing shown where no reference is
    std::string command;           ///< the equivalent `projsurf detect` command line
    cv::Mat overlay;               ///< BGR: label polygons, reference (blue), detector (magenta)
};

struct LabelledFrame {
    std::string name;  ///< frame folder name
    std::string label_path;
    RealLabel label;
    GalleryEntry detection;  ///< at the configuration's seed
    RealScore score;
    std::vector<SeedRun> seeds;
    double seed_spread = 0.0;  ///< (max - min) / max of the area over the seeds (0 when none found)
    double seed_shift = 0.0;   ///< m, largest distance of a seed's rectangle centre from the main one
    bool seed_same_validity = true;
    std::string command;  ///< the equivalent `projsurf detect` command line
    cv::Mat overlay;      ///< BGR: label polygons, label best (blue), detector (magenta)
    ColourRun colour;
    ExampleRun example;
    VariantRun unorganized;           ///< the frame's points as an unorganized cloud
    std::vector<VariantRun> shifted;  ///< the depth image cropped by a pixel or three
};

struct LabelledSummary {
    int frames = 0;
    int right = 0;                                 ///< valid answers, or found: false where nothing is usable
    int with_best = 0;                             ///< frames whose label has a best rectangle
    double median_ratio = 0.0, worst_ratio = 0.0;  ///< over frames with a best (invalid = 0)
    int seed_stable = 0;                           ///< spread <= 2 % and the same validity on every seed
    int unorganized_agree = 0;                     ///< the unorganized cloud's answer agrees (VariantRun)
    int shift_stable = 0;                          ///< every cropped image's answer agrees
};

/// Over every frame, the example-calibration runs.
struct ExampleSummary {
    int frames = 0;
    int right = 0;
    int valid = 0;         ///< found and valid
    int off_surface = 0;   ///< found and not valid (target: 0)
    int missed = 0;        ///< nothing found where the reference finds a surface
    int rightly_none = 0;  ///< nothing found and the reference finds nothing
    /// The same, for what `detect` shows (ExampleRun::shown).
    int right_shown = 0, valid_shown = 0, off_shown = 0, missed_shown = 0, none_shown = 0;
};

/// Over the frames judged on colour: how often each answer is right against the colour-aware
/// label and lands on clean wall (<= 2 % over unsuitable polygons).
struct ColourSummary {
    int judged = 0;       ///< frames whose label has a colour section
    int colour_used = 0;  ///< of them, with registered colour
    int right_depth = 0, right_colour = 0;
    int with_best = 0;  ///< judged frames with a colour best (a usable surface); the rest count below only:
    int found_depth = 0, found_colour = 0;
    int clean_depth = 0, clean_colour = 0;                       ///< found and <= 2 % over unsuitable polygons
    double median_ratio_depth = 0.0, median_ratio_colour = 0.0;  ///< area / colour best (invalid = 0)
    double worst_share_depth = 0.0, worst_share_colour = 0.0;    ///< largest share over unsuitable polygons
};

/// Seeds for the stability check: 1-5 and 42 (the default).
std::vector<unsigned> stabilitySeeds();

/// Evaluates one label file; the frame is real_dir/<label.frame>. Throws InputError when the
/// label or its frame cannot be read.
LabelledFrame evaluateLabelledFrame(const std::string &label_path, const std::string &real_dir,
                                    const DetectorConfig &config, const std::vector<unsigned> &seeds);

LabelledSummary summariseLabelled(const std::vector<LabelledFrame> &frames);
/// "labelled real frames: 17 of 23 right; area ratio median 0.81, worst 0.00 (20 with a best
/// rectangle); seed-stable 19 of 23".
std::string labelledSummaryLine(const LabelledSummary &summary);

/// Every figure of the summary lines for all frames and for each half of the split (the label's
/// `split`: tune, check), side by side: a Markdown table. Frames with no side count in "all" only.
std::string halvesTable(const std::vector<LabelledFrame> &frames);

ExampleSummary summariseExample(const std::vector<LabelledFrame> &frames);
/// "labelled real frames, example calibration: 25 of 30 right; 20 valid, 2 off the labelled
/// surfaces, 3 missed, 5 rightly nothing".
std::string exampleSummaryLine(const ExampleSummary &summary);
/// "labelled real frames, example calibration, as detect shows them (at least 0.15 m wide and
/// 0.012 m^2): 27 of 30 right; ...".
std::string exampleShownSummaryLine(const ExampleSummary &summary);
/// The example-calibration table (Markdown; part of labelledReportMarkdown).
/// Frame, reference area, detector area, right, off surface, free share, surface, why (CSV).
std::string exampleCsv(const std::vector<LabelledFrame> &frames);
std::string exampleReportMarkdown(const std::vector<LabelledFrame> &frames, const std::string &pictures);

ColourSummary summariseColour(const std::vector<LabelledFrame> &frames);
/// "labelled real frames with colour: 15 judged (14 with registered colour); right 9 with colour,
/// 9 depth only; of the 11 with a usable surface, on clean wall ... 11 with colour, 11 depth only; ...".
std::string colourSummaryLine(const ColourSummary &summary);
/// The colour table (Markdown; part of labelledReportMarkdown when any frame is judged).
std::string colourReportMarkdown(const std::vector<LabelledFrame> &frames, const std::string &pictures);

/// The report section (Markdown); pictures are linked as `<pictures>/<frame>.png`.
std::string labelledReportMarkdown(const std::vector<LabelledFrame> &frames, const std::string &labels_dir,
                                   const std::string &pictures);
/// One line per frame: frame, label best, detector area, ratio, right, free share, seed areas,
/// spread (CSV with a header line).
std::string labelledCsv(const std::vector<LabelledFrame> &frames);
/// Markdown: the unorganized and shifted-grid variants per frame (part of labelledReportMarkdown).
std::string variantReportMarkdown(const std::vector<LabelledFrame> &frames);
/// The frames judged on colour: frame, colour used, colour best, per answer (depth only, with
/// colour): area, ratio, right, share over unsuitable polygons (CSV with a header line).
std::string colourCsv(const std::vector<LabelledFrame> &frames);
/// Writes dir/<frame>.png per frame, dir/contact_sheet.png and dir/results.csv, and for the
/// frames judged on colour dir/<frame>_colour.png and dir/colour_results.csv, and dir/<frame>_example.png and
/// dir/example_results.csv; `dir` is created.
void writeLabelledPictures(const std::string &dir, const std::vector<LabelledFrame> &frames);

}  // namespace projsurf::eval
