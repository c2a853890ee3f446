#pragma once
// The evaluation report: Markdown tables with the paper's published numbers beside ours, and
// PNG charts (success rates, surface-check outliers, keystone errors, timing), plus the real
// frame gallery.
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "eval/paper/experiments.hpp"
#include "eval/real/labelled_eval.hpp"
#include "eval/real/real_gallery.hpp"

namespace projsurf::eval {

struct ReportInfo {
    std::string command;  ///< the command line that made the report
    bool quick = false;
    bool paper_only = false;         ///< `eval --paper-only`: the other suites and the real frames were not run
    std::string real_dir;            ///< where the real frames came from ("" = none)
    double real_seconds = 0;         ///< time spent on the gallery
    std::string load;                ///< machine load while it ran (e.g. "1-min load average 7.4 -> 6.5 on 2 cores")
    std::string realistic_markdown;  ///< the realistic suite's section body (realisticSuiteMarkdown), "" = none
    const std::vector<LabelledFrame> *labelled = nullptr;  ///< labelled real-frame suite (nullptr = not run)
    std::string labels_dir;                                ///< where its label files came from
};

/// One row of the report's headline: the paper's Tables 1-3 (and Fig 15, timing), published
/// beside ours, as printed (an empty cell where a column does not apply).
struct HeadlineRow {
    std::string experiment, published, paper_criterion, paper_truth, paper_slack, default_truth;
};
std::vector<HeadlineRow> evalHeadline(const EvalResults &results);
/// The same as lines for stdout (eval prints it after its run).
std::string evalHeadlineText(const EvalResults &results);

/// Why the paper's criterion says 100 % when each pose had `rounds` <= 2 (each round is judged
/// against the best round of its pose, one of the two); "" for more rounds.
std::string paperCriterionRoundsNote(int rounds);

/// The report's Markdown (links plots and gallery pictures by relative path).
std::string evalReportMarkdown(const EvalResults &results, const std::vector<GalleryEntry> &gallery,
                               const ReportInfo &info);

/// The charts, as (file name, image).
std::vector<std::pair<std::string, cv::Mat>> evalPlots(const EvalResults &results);

/// Writes dir/report.md, the charts, dir/gallery/<name>.png and dir/gallery/contact_sheet.png,
/// and for the labelled suite dir/labels/<name>.png, contact_sheet.png and results.csv
/// (atomically, each file). `dir` must exist.
void writeEvalReport(const std::string &dir, const EvalResults &results, const std::vector<GalleryEntry> &gallery,
                     const ReportInfo &info);

}  // namespace projsurf::eval
