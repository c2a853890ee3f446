// projsurf eval: re-run the paper's experiments (section 4: Tables 1-3, Fig 15) in simulation
// for the paper's method and the default one, run detection on the real frames, and write a
// Markdown report with charts beside the paper's published numbers.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include "cli/commands.hpp"
#include "eval/paper/experiments.hpp"
#include "eval/procam/procam_comparison.hpp"
#include "eval/procam/procam_reference.hpp"
#include "eval/real/labelled_eval.hpp"
#include "eval/real/real_gallery.hpp"
#include "eval/real/real_labels.hpp"
#include "eval/realistic/colour_suite.hpp"
#include "eval/realistic/plan_suite.hpp"
#include "eval/realistic/projector_eval.hpp"
#include "eval/realistic/realistic_suite.hpp"
#include "eval/report/report.hpp"
#include "projsurf/frontend/inputs/chessboard_calibration.hpp"
#include "projsurf/frontend/render/progress.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/formats/procam_captures.hpp"
#include "projsurf/io/formats/procam_xml.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"

namespace fs = std::filesystem;

namespace projsurf::cli {
namespace {

struct EvalOptions {
    std::string out;
    int rounds = 10;     // noise seeds per pose (paper: 10 detection rounds per pose)
    bool quick = false;  // 2 rounds, 2 m poses only (tests, CI)
    unsigned seed = 1;
    std::string real_dir = "../shared/data/real";  // relative to the working directory
    bool real_dir_given = false;
    std::string labels_dir = "labels/real";  // label files of the real frames, relative to the repository root
    bool labels_dir_given = false;
    bool no_progress = false;
    bool projector_only = false;  // only the projector table
    bool colour_only = false;     // only the colour suite
    bool realistic_only = false;  // only the realistic-sensor suite
    std::string procam;           // a procam-calibration sample_data folder: ours beside its XML
    std::string json;             // with --procam: the comparison as JSON
    std::string published;        // with --procam: the published XML, default DIR/calibration_result.xml
    // The board's square: procam-calibration's README runs its sample_data with chess_block_size
    // 75 (read as mm); its XML's translation is in those units.
    double square_m = 0.075;
    double published_square = 75;
    bool plan_only = false;      // only the plan suite (where to stand)
    bool oblique = false;        // with plan_only: the oblique walls (issue 41) instead of the suite
    bool labelled_only = false;  // only the labelled real frames
    bool paper_only = false;     // only the paper's experiments (Tables 1-3, Fig. 15)
};

/// Our chessboard calibration of a procam-calibration folder beside the published method run
/// to convergence on the same captures, and beside its calibration_result.xml (information).
void runProcam(const EvalOptions &o) {
    if (!(o.square_m > 0 && o.square_m < 10)) throw InputError("--square-m", "must be between 0 and 10 m");
    if (!o.json.empty()) requireWritableFile(o.json);
    const std::string xml =
        o.published.empty() ? (fs::path(o.procam) / "calibration_result.xml").string() : o.published;
    const PublishedProcam published = readProcamXml(xml);
    const ProcamFolder folder = readProcamFolder(o.procam, std::nullopt);
    const frontend::ChessboardCalibration cal = frontend::calibrateChessboard(folder, o.square_m);
    eval::PublishedMethodConfig ref_cfg;
    ref_cfg.square_m = o.square_m;
    ref_cfg.board = cal.inner;
    const eval::PublishedMethodRun ref = eval::runPublishedMethod(folder, ref_cfg);
    const StereoFit pub = eval::publishedFit(published, o.square_m / o.published_square);
    eval::ProcamTableInput in;
    in.ours = &cal.fit;
    in.reference = &ref.fit;
    in.published = &pub;
    in.reference_defaults = &ref.opencv_defaults;
    in.vs_reference = eval::compareProcam(cal.fit, ref.fit);
    in.vs_published = eval::compareProcam(cal.fit, pub);
    in.square_m = o.square_m;
    in.decoded_board_share = cal.decoded_board_share;
    in.opencv_decoder = ref.opencv_decoder;
    std::printf("eval --procam %s: %zu poses, board %dx%d inner corners, projector %dx%d; published: %s\n",
                o.procam.c_str(), folder.poses.size(), cal.inner.width, cal.inner.height, cal.width, cal.height,
                xml.c_str());
    for (const auto &p : cal.poses)
        std::printf("  %s: %s, %d/%d corners carried, board %.1f %% decoded\n", p.dir.c_str(),
                    p.board ? "board" : "no board", p.carried, p.corners, 100 * p.board_share);
    std::printf("\n%s", eval::procamTable(in).c_str());
    for (const auto &w : stereoWarnings(cal.fit)) std::fprintf(stderr, "projsurf: warning: ours: %s\n", w.c_str());
    for (const auto &c : ref.fit.convergence)
        if (c.on_cap) std::fprintf(stderr, "projsurf: warning: reference: %s\n", convergenceWarning(c).c_str());
    if (!o.json.empty()) {
        std::vector<double> shares;
        for (const auto &p : cal.poses)
            if (p.board) shares.push_back(p.board_share);
        writeFileAtomic(o.json, eval::procamJson(o.json, in, shares));
    }
}

/// The repository's own real frames (relative to its root): those whose licence lets them ship.
const char *const kRepoFrames = "data/real";

/// The 1-minute load average (Linux), NaN when unknown.
double loadAverage() {
    double load = std::nan("");
    if (FILE *f = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(f, "%lf", &load) != 1) load = std::nan("");
        std::fclose(f);
    }
    return load;
}

/// The default label folder: labels/real from the working directory (the repository root),
/// else from the repository that holds the binary (build/projsurf).
std::string defaultLabelsDir(const std::string &relative) {
    std::error_code ec;
    if (fs::is_directory(relative, ec)) return relative;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path candidate = exe.parent_path().parent_path() / relative;
        if (fs::is_directory(candidate, ec)) return candidate.lexically_normal().string();
    }
    return relative;
}

/// The projector table (sim/projector_eval.hpp): DIR/projector.md and a summary line.
void runProjectorTable(const EvalOptions &o) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto rows = eval::runProjectorEval(o.seed, o.quick);
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec) throw InputError(o.out, "cannot create the directory: " + ec.message());
    const std::string md = eval::projectorEvalMarkdown(rows);
    writeFileAtomic((fs::path(o.out) / "projector.md").string(), md);
    std::printf("%s", md.c_str());
    std::printf("%s (%.0f s); wrote %s/projector.md\n", eval::projectorEvalSummary(rows).c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), o.out.c_str());
}

/// The colour suite's options for these flags: 2 rounds with --quick, else --rounds.
eval::ColourSuiteOptions colourSuiteOptions(const EvalOptions &o) {
    eval::ColourSuiteOptions copt = o.quick ? eval::quickColourSuite() : eval::ColourSuiteOptions{};
    if (!o.quick) copt.rounds = o.rounds;
    copt.seed = o.seed;
    return copt;
}

/// eval's progress bar, drawn on stderr unless --no-progress (a log, too: eval's runs are
/// long), and the callback that moves it (empty without the bar).
struct EvalProgress {
    std::unique_ptr<frontend::ProgressLine> bar;
    eval::Progress progress;
    /// The drawn line ends as it is; the next stage starts a new one.
    void endLine() const {
        if (bar) bar->endLine();
    }
};

EvalProgress evalProgress(const EvalOptions &o, const char *unit) {
    EvalProgress p;
    if (o.no_progress) return p;
    p.bar = std::make_unique<frontend::ProgressLine>("eval", unit, true);
    frontend::ProgressLine *line = p.bar.get();
    p.progress = [line](int done, int total, const std::string &what) { line->update(done, total, what); };
    return p;
}

/// One suite's table alone: DIR/<file> (created with DIR), the table and its summary line on stdout.
void writeSuiteTable(const EvalOptions &o, const std::string &file, const std::string &md, const std::string &summary) {
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec) throw InputError(o.out, "cannot create the directory: " + ec.message());
    writeFileAtomic((fs::path(o.out) / file).string(), md);
    std::printf("%s", md.c_str());
    std::printf("%s; wrote %s/%s\n", summary.c_str(), o.out.c_str(), file.c_str());
}

/// The colour suite alone (detection/colour/surface_suitability.hpp).
void runColourTable(const EvalOptions &o) {
    const eval::ColourSuiteResult colour = eval::runColourSuite(colourSuiteOptions(o), eval::defaultVariant().config);
    writeSuiteTable(o, "colour.md", eval::colourSuiteMarkdown(colour), eval::colourSuiteSummary(colour));
}

/// The realistic suite alone (realistic sensors and scenes).
void runRealisticTable(const EvalOptions &o) {
    eval::RealisticSuiteOptions ropt = o.quick ? eval::quickRealisticSuite() : eval::RealisticSuiteOptions{};
    if (!o.quick) ropt.rounds = o.rounds;
    ropt.seed = o.seed;
    const eval::RealisticSuiteResult realistic = eval::runRealisticSuite(ropt, eval::defaultVariant().config);
    writeSuiteTable(o, "realistic.md", eval::realisticSuiteMarkdown(realistic), eval::realisticSuiteSummary(realistic));
}

/// The plan suite alone (eval/realistic/plan_suite.hpp): DIR/plan.md and its summary line; --quick skips the
/// reference search.
/// Issue 41's oblique wall through the suite's sensor model and each realistic sensor family.
void runObliqueTable(const EvalOptions &o, eval::PlanSuiteOptions popt) {
    std::string md, summary;
    for (const std::string sensor : {"", "kinect1", "tof", "d435"}) {
        popt.sensor = sensor;
        std::vector<eval::PlanSceneResult> rows;
        for (const eval::PlanScene &scene : eval::obliqueWallScenes()) rows.push_back(eval::runPlanScene(scene, popt));
        const std::string name = sensor.empty() ? "the suite's Kinect v1 model" : sensor + " unit 0";
        md += "\n### " + name + "\n\n" + eval::planSuiteMarkdown(rows) + "\n" + eval::planGainSummary(rows);
        summary += name + ": " + eval::planSuiteSummary(rows) + "\n" + eval::planGainSummary(rows);
        if (!o.no_progress) std::fprintf(stderr, "oblique walls: %s done\n", name.c_str());
    }
    writeSuiteTable(o, "plan_oblique.md", md, summary);
}

void runPlanTable(const EvalOptions &o) {
    std::vector<eval::PlanSceneResult> rows;
    eval::PlanSuiteOptions popt;
    popt.reference = !o.quick;
    popt.seed = o.seed;
    if (o.oblique) return runObliqueTable(o, popt);
    for (const eval::PlanScene &scene : eval::planSuiteScenes()) {
        rows.push_back(eval::runPlanScene(scene, popt));
        if (!o.no_progress) std::fprintf(stderr, "plan suite: %zu scenes done\r", rows.size());
    }
    if (!o.no_progress) std::fprintf(stderr, "\n");
    writeSuiteTable(o, "plan.md", eval::planSuiteMarkdown(rows), eval::planSuiteSummary(rows));
}

/// Where a label's frame is: the real-frame folder (--real-dir), else the repository's own
/// data/real (the frames whose licence lets them ship) or data/ (the quick start's two frames);
/// "" when in none.
std::string frameParent(const std::string &frame, const std::string &real_dir, const std::string &repo_frames) {
    std::error_code ec;
    const std::string quick_start = repo_frames.empty() ? "" : fs::path(repo_frames).parent_path().string();
    for (const std::string &dir : {real_dir, repo_frames, quick_start})
        if (!dir.empty() && fs::is_directory(fs::path(dir) / frame, ec)) return dir;
    return "";
}

/// The labelled real frames, each with the label's projector and gravity and again with the
/// example calibration.
std::vector<eval::LabelledFrame> runLabelled(const std::vector<std::string> &labels,
                                             const std::vector<std::string> &label_frames, const std::string &real_dir,
                                             const std::string &repo_frames, bool labels_dir_given,
                                             const eval::Progress &progress) {
    std::vector<eval::LabelledFrame> labelled;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        // The default labels go with the default frames: a frame in neither folder is skipped
        // (a label folder given with --labels must have all of its frames).
        std::string parent = frameParent(label_frames[i], real_dir, repo_frames);
        if (parent.empty() && !labels_dir_given) continue;
        if (parent.empty()) parent = real_dir;
        if (progress)
            progress(static_cast<int>(i), static_cast<int>(labels.size()),
                     "labelled " + fs::path(labels[i]).stem().string());
        labelled.push_back(eval::evaluateLabelledFrame(labels[i], parent, DetectorConfig{}, eval::stabilitySeeds()));
    }
    if (progress && !labelled.empty())
        progress(static_cast<int>(labels.size()), static_cast<int>(labels.size()), "labelled frames");
    return labelled;
}

void printLabelledLines(const std::vector<eval::LabelledFrame> &labelled) {
    if (labelled.empty()) return;
    std::printf("%s\n", eval::labelledSummaryLine(eval::summariseLabelled(labelled)).c_str());
    const eval::ExampleSummary example = eval::summariseExample(labelled);
    std::printf("%s\n", eval::exampleSummaryLine(example).c_str());
    std::printf("%s\n", eval::exampleShownSummaryLine(example).c_str());
    if (eval::summariseColour(labelled).judged > 0)
        std::printf("%s\n", eval::colourSummaryLine(summariseColour(labelled)).c_str());
    std::printf("labelled real frames by half (labels/README.md, \"The two halves\"):\n%s",
                eval::halvesTable(labelled).c_str());
}

/// The labelled real frames alone: DIR/labelled.md, DIR/labels/ and the summary lines.
void runLabelledTable(const EvalOptions &o, const std::vector<std::string> &labels,
                      const std::vector<std::string> &label_frames, const std::string &labels_dir) {
    std::error_code ec;
    const std::string repo_frames = o.real_dir_given ? "" : defaultLabelsDir(kRepoFrames);
    const bool have_real = !o.real_dir.empty() && fs::is_directory(o.real_dir, ec);
    if (!have_real && !fs::is_directory(repo_frames, ec))
        throw InputError(o.real_dir.empty() ? std::string("--real-dir") : o.real_dir,
                         "no folder of real frames (--labelled-only needs them)");
    if (labels.empty()) throw InputError(labels_dir.empty() ? std::string("--labels") : labels_dir, "no label files");
    EvalProgress bar = evalProgress(o, "frames");
    const std::vector<eval::LabelledFrame> labelled =
        runLabelled(labels, label_frames, have_real ? o.real_dir : "", repo_frames, o.labels_dir_given, bar.progress);
    bar.endLine();
    fs::create_directories(o.out, ec);
    if (ec) throw InputError(o.out, "cannot create the directory: " + ec.message());
    eval::writeLabelledPictures((fs::path(o.out) / "labels").string(), labelled);
    writeFileAtomic((fs::path(o.out) / "labelled.md").string(),
                    eval::labelledReportMarkdown(labelled, labels_dir, "labels"));
    printLabelledLines(labelled);
    std::printf("wrote %s/labelled.md\n", o.out.c_str());
}

/// The paper's experiments alone (Tables 1-3, Fig. 15): DIR/report.md without the other
/// suites, its charts, and the headline.
void runPaperTables(const EvalOptions &o, const eval::EvalPlan &plan, const std::string &command) {
    EvalProgress bar = evalProgress(o, "runs");
    const eval::EvalResults results = eval::runEval(plan, bar.progress);
    bar.endLine();
    eval::ReportInfo info;
    info.command = command;
    info.quick = o.quick;
    info.paper_only = true;
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec) throw InputError(o.out, "cannot create the directory: " + ec.message());
    writeEvalReport(o.out, results, {}, info);
    std::printf("eval: %zu detections in %.1f s (%d rounds%s), the paper's experiments only; wrote %s/report.md\n",
                results.trials.size() + results.keystone.size(), results.seconds, results.rounds,
                o.quick ? ", quick" : "", o.out.c_str());
    std::printf("%s\n", evalHeadlineText(results).c_str());
    if (const std::string note = eval::paperCriterionRoundsNote(results.rounds); !note.empty())
        std::printf("  %s\n", note.c_str());
}

/// The label files of the real frames: their folder, each file and each one's frame.
struct EvalLabels {
    std::string dir;
    std::vector<std::string> files, frames;
};

void checkEvalArguments(const EvalOptions &o) {
    if (!o.json.empty()) throw InputError("--json", "only with --procam");
    if (o.out.empty()) throw InputError("--out", "an output directory is required");
    if (o.rounds < 1 || o.rounds > 100) throw InputError("--rounds", "must be between 1 and 100");
    std::error_code ec;
    if (fs::exists(o.out, ec) && !fs::is_directory(o.out, ec)) throw InputError(o.out, "exists and is not a directory");
    if (o.real_dir_given && !o.real_dir.empty() && !fs::is_directory(o.real_dir, ec))
        throw InputError(o.real_dir, "is not a directory (--real-dir)");
    if (o.labels_dir_given && !o.labels_dir.empty() && !fs::is_directory(o.labels_dir, ec))
        throw InputError(o.labels_dir, "is not a directory (--labels)");
}

/// Every label file read: bad label files are reported before the long simulation runs.
EvalLabels readEvalLabels(const EvalOptions &o) {
    EvalLabels labels;
    labels.dir = o.labels_dir_given ? o.labels_dir : defaultLabelsDir(o.labels_dir);
    if (!labels.dir.empty()) labels.files = eval::listLabelFiles(labels.dir);
    for (const std::string &l : labels.files) labels.frames.push_back(eval::readRealLabel(l).frame);
    return labels;
}

/// The default real-frame folder is taken from the working directory, and said (before the
/// long simulation) when it is not there.
void noteMissingRealFrames(const EvalOptions &o) {
    std::error_code ec;
    if (!o.real_dir_given && !fs::is_directory(o.real_dir, ec))
        std::fprintf(stderr,
                     "projsurf: note: %s: no such folder (from %s); the report has no real frames (--real-dir)\n",
                     o.real_dir.c_str(), fs::current_path(ec).string().c_str());
}

/// What the full eval simulates: the paper's experiments (both methods), and the realistic
/// and colour suites with the default method.
struct SimulatedSuites {
    eval::EvalResults results;
    eval::RealisticSuiteResult realistic;
    eval::ColourSuiteResult colour;
};

SimulatedSuites runSimulatedSuites(const EvalOptions &o, const eval::EvalPlan &plan, int rounds,
                                   const eval::Progress &progress) {
    SimulatedSuites s;
    s.results = eval::runEval(plan, progress);
    eval::RealisticSuiteOptions ropt = o.quick ? eval::quickRealisticSuite() : eval::RealisticSuiteOptions{};
    if (!o.quick) ropt.rounds = rounds;
    ropt.seed = o.seed;
    s.realistic = eval::runRealisticSuite(ropt, eval::defaultVariant().config, progress);
    s.colour = eval::runColourSuite(colourSuiteOptions(o), eval::defaultVariant().config, progress);
    return s;
}

/// The real frames' folders: those of `real_dir`, and the repository's own frames
/// (`repo_frames`, data/real) that are not in it.
std::vector<std::string> realFrameFolders(const std::string &real_dir, const std::string &repo_frames) {
    std::error_code ec;
    std::vector<std::string> frames = real_dir.empty() ? std::vector<std::string>{} : eval::listFrameFolders(real_dir);
    if (!repo_frames.empty() && fs::is_directory(repo_frames, ec))
        for (const std::string &f : eval::listFrameFolders(repo_frames))
            if (frameParent(fs::path(f).filename().string(), real_dir, "").empty()) frames.push_back(f);
    return frames;
}

/// Each real frame detected with the default method, the contract's example calibration and
/// the default gravity.
std::vector<eval::GalleryEntry> detectRealFrames(const std::vector<std::string> &frames,
                                                 const eval::Progress &progress) {
    std::vector<eval::GalleryEntry> gallery;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (progress)
            progress(static_cast<int>(i), static_cast<int>(frames.size()),
                     "real frame " + fs::path(frames[i]).filename().string());
        gallery.push_back(eval::detectRealFrame(frames[i], sim::exampleProjector(), DetectorConfig{}));
    }
    if (progress && !frames.empty())
        progress(static_cast<int>(frames.size()), static_cast<int>(frames.size()), "real frames");
    return gallery;
}

/// The machine's load while eval ran, for the report; "" when unknown.
std::string loadLine(double load_before, double load_after) {
    if (std::isnan(load_before) || std::isnan(load_after)) return "";
    char buf[160];
    std::snprintf(buf, sizeof buf, "1-minute load average %.1f at the start, %.1f at the end, %u hardware threads",
                  load_before, load_after, std::thread::hardware_concurrency());
    return buf;
}

/// DIR/report.md with its charts and gallery, the colour suite's table appended.
void writeFullReport(const EvalOptions &o, const SimulatedSuites &suites,
                     const std::vector<eval::GalleryEntry> &gallery, const eval::ReportInfo &info) {
    const fs::path out(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw InputError(o.out, "cannot create the directory: " + ec.message());
    writeEvalReport(o.out, suites.results, gallery, info);
    std::ofstream(out / "report.md", std::ios::app) << "\n## Colour suite: surface suitability\n\n"
                                                    << eval::colourSuiteMarkdown(suites.colour);
}

void printFullSummary(const EvalOptions &o, int rounds, const SimulatedSuites &suites, std::size_t real_frames,
                      const std::vector<eval::LabelledFrame> &labelled) {
    const eval::EvalResults &results = suites.results;
    std::printf("eval: %zu detections in %.1f s (%d rounds%s), %zu real frames; wrote %s/report.md\n",
                results.trials.size() + results.keystone.size(), results.seconds, rounds, o.quick ? ", quick" : "",
                real_frames, o.out.c_str());
    std::printf("%s\n", evalHeadlineText(results).c_str());
    if (const std::string note = eval::paperCriterionRoundsNote(rounds); !note.empty())
        std::printf("  %s\n", note.c_str());
    std::printf("%s\n", eval::realisticSuiteSummary(suites.realistic).c_str());
    std::printf("%s\n", eval::colourSuiteSummary(suites.colour).c_str());
    printLabelledLines(labelled);
}

/// The whole eval: the simulated suites, the real frames and the labelled ones, DIR/report.md
/// and the summary; without --quick, the projector table too.
void runFullEval(const EvalOptions &o, const std::string &command, const EvalLabels &labels, int rounds) {
    noteMissingRealFrames(o);
    const eval::EvalPlan plan = eval::paperEvalPlan(rounds, o.quick, o.seed);
    const double load_before = loadAverage();
    EvalProgress bar = evalProgress(o, "runs");
    const SimulatedSuites suites = runSimulatedSuites(o, plan, rounds, bar.progress);
    eval::ReportInfo info;
    info.command = command;
    info.quick = o.quick;
    info.realistic_markdown = eval::realisticSuiteMarkdown(suites.realistic);
    const auto t0 = std::chrono::steady_clock::now();
    // The repository's own frames (data/real) join the default folder's; a --real-dir stands alone.
    const std::string repo_frames = o.real_dir_given ? "" : defaultLabelsDir(kRepoFrames);
    const std::vector<std::string> frames = realFrameFolders(o.real_dir, repo_frames);
    const std::vector<eval::GalleryEntry> gallery = detectRealFrames(frames, bar.progress);
    bar.endLine();
    info.real_dir = frames.empty() ? "" : o.real_dir;
    // Labelled real frames: each label's projector and gravity, scored against the label.
    const std::vector<eval::LabelledFrame> labelled =
        frames.empty()
            ? std::vector<eval::LabelledFrame>{}
            : runLabelled(labels.files, labels.frames, o.real_dir, repo_frames, o.labels_dir_given, bar.progress);
    if (!labelled.empty()) {
        bar.endLine();
        info.labelled = &labelled;
        info.labels_dir = labels.dir;
    }
    info.load = loadLine(load_before, loadAverage());
    info.real_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    writeFullReport(o, suites, gallery, info);
    printFullSummary(o, rounds, suites, gallery.size(), labelled);
    if (!o.quick) runProjectorTable(o);
}

void run(const EvalOptions &o, const std::string &command) {
    if (!o.procam.empty()) return runProcam(o);
    checkEvalArguments(o);
    const EvalLabels labels = readEvalLabels(o);
    if (o.projector_only) return runProjectorTable(o);
    if (o.colour_only) return runColourTable(o);
    if (o.realistic_only) return runRealisticTable(o);
    if (o.plan_only) return runPlanTable(o);
    if (o.labelled_only) return runLabelledTable(o, labels.files, labels.frames, labels.dir);
    const int rounds = o.quick ? std::min(o.rounds, 2) : o.rounds;
    if (o.paper_only) return runPaperTables(o, eval::paperEvalPlan(rounds, o.quick, o.seed), command);
    runFullEval(o, command, labels, rounds);
}

/// The --procam check's options; those beside it need it (without it they would be ignored
/// and a full eval run).
void addProcamOptions(CLI::App &sub, EvalOptions &o) {
    CLI::Option *procam =
        sub.add_option("--procam", o.procam,
                       "Only the real projector-camera check: calibrate a procam-calibration sample_data folder "
                       "(capture_k/graycode_NN.png, calibration_result.xml) with the chessboard mode and print it "
                       "beside the published method re-run to convergence on the same captures (OpenCV's Gray-code "
                       "decoder) and beside its published calibration (information)");
    sub.add_option("--json", o.json, "with --procam: write the comparison as JSON")->needs(procam);
    sub.add_option("--published", o.published,
                   "with --procam: the published calibration shown for information (OpenCV XML; default "
                   "DIR/calibration_result.xml)")
        ->needs(procam);
    sub.add_option("--square-m", o.square_m, "with --procam: the board's square, m (default 0.075: its README's 75)")
        ->needs(procam);
}

/// The command as the report quotes it.
std::string evalCommandLine(const EvalOptions &o) {
    std::string command = "projsurf eval --out " + o.out;
    if (o.quick) command += " --quick";
    if (o.paper_only) command += " --paper-only";
    if (o.rounds != 10) command += " --rounds " + std::to_string(o.rounds);
    if (o.seed != 1) command += " --seed " + std::to_string(o.seed);
    if (o.real_dir_given) command += " --real-dir '" + o.real_dir + "'";
    if (o.labels_dir_given) command += " --labels '" + o.labels_dir + "'";
    return command;
}

}  // namespace

void addEvalCommand(CLI::App &app) {
    auto o = std::make_shared<EvalOptions>();
    auto *sub =
        app.add_subcommand("eval", "Re-run the paper's experiments in simulation and write a report with charts");
    sub->add_option("--out", o->out,
                    "Output directory for report.md, charts and gallery/ (created); required unless --procam");
    sub->add_option("--rounds", o->rounds, "Noise seeds per pose (default 10, as in the paper)");
    sub->add_flag("--quick", o->quick, "2 rounds and the 2 m poses only (for tests and CI)");
    sub->add_option("--seed", o->seed, "Base seed (default 1)");
    auto *real = sub->add_option("--real-dir", o->real_dir,
                                 "Folder of real frames (sub-folders with depth.png + camera.yaml); default "
                                 "../shared/data/real of the working directory (said when missing); '' to skip");
    auto *labels = sub->add_option("--labels", o->labels_dir,
                                   "Folder of real-frame label files (<frame>.yaml, in it or one sub-folder down); "
                                   "default labels/real of the repository, skipped when missing; '' to skip");
    sub->add_flag("--no-progress", o->no_progress, "No progress bar on stderr");
    sub->add_flag("--projector-only", o->projector_only,
                  "Only the real-projector table (disc vs structured-light calibration on simulated lens-offset "
                  "projectors): DIR/projector.md; with --quick, 3 rigs (the full eval adds it unless --quick)");
    sub->add_flag("--colour-only", o->colour_only,
                  "Only the colour suite (surface suitability on simulated walls with pictures, screens, windows, "
                  "dark panels and plain paints): DIR/colour.md; --rounds per scene, 2 with --quick")
        ->excludes("--projector-only");
    sub->add_flag("--realistic-only", o->realistic_only,
                  "Only the realistic-sensor suite (Kinect v1, ToF and D435 units on plain walls, frames, TVs, "
                  "windows, clutter): DIR/realistic.md; --rounds per scene and sensor, 2 with --quick")
        ->excludes("--projector-only")
        ->excludes("--colour-only");
    addProcamOptions(*sub, *o);
    sub->add_flag("--plan-only", o->plan_only,
                  "Only the plan suite (where to stand: planned, rendered from the moved robot, detected there, "
                  "against an exhaustive reference search): DIR/plan.md; --seed renders the frames, --quick skips the "
                  "reference")
        ->excludes("--projector-only")
        ->excludes("--colour-only")
        ->excludes("--realistic-only");
    sub->add_flag("--oblique", o->oblique,
                  "with --plan-only: a wall seen at 30, 45 and 60 deg from 1.5-3 m instead of the suite, through the "
                  "suite's Kinect v1 model and each realistic sensor (kinect1, tof, d435): DIR/plan_oblique.md, with "
                  "the realised gain against the reference's")
        ->needs("--plan-only");
    sub->add_flag("--labelled-only", o->labelled_only,
                  "Only the labelled real frames (each with its label's projector and with the example calibration, "
                  "scored against the label): DIR/labelled.md and DIR/labels/")
        ->excludes("--projector-only")
        ->excludes("--colour-only")
        ->excludes("--realistic-only")
        ->excludes("--plan-only");
    sub->add_flag("--paper-only", o->paper_only,
                  "Only the paper's experiments (Tables 1-3 and Fig. 15, the paper's and the default method): "
                  "DIR/report.md and its charts, without the realistic and colour suites or the real frames; "
                  "--rounds per pose, 2 and the 2 m poses with --quick")
        ->excludes("--projector-only")
        ->excludes("--colour-only")
        ->excludes("--realistic-only")
        ->excludes("--plan-only")
        ->excludes("--labelled-only");
    sub->callback([o, real, labels] {
        EvalOptions opts = *o;
        opts.real_dir_given = real->count() > 0;
        opts.labels_dir_given = labels->count() > 0;
        run(opts, evalCommandLine(opts));
    });
}

}  // namespace projsurf::cli
