#pragma once
// How far a long run is, for a person watching (the CLI's correct and eval).
#include <cstdio>
#include <string>

namespace projsurf::frontend {

/// On a terminal (`redraw`): one stderr line redrawn in place,
///   "<label>: [#########...........]  42% 120/240 <unit> <what>",
/// erased when the object goes away unfinished (so an error is the one line left), ended by
/// finish(). Elsewhere (a log): a line "<label>: 40% (120/240 <unit>)" every 10% on `log`,
/// and nothing on stderr. A total of 0 or less: the count only.
class ProgressLine {
public:
    ProgressLine(std::string label, std::string unit, bool redraw, std::FILE *log = stdout);
    ~ProgressLine();
    ProgressLine(const ProgressLine &) = delete;
    ProgressLine &operator=(const ProgressLine &) = delete;

    void update(long done, long total, const std::string &what = "");
    /// The line ends: "<label>: <done> <unit> done" on a terminal.
    void finish(long done);
    /// The drawn line ends as it is (a run in stages: the next stage starts a new line).
    void endLine();

private:
    std::string label_, unit_;
    bool redraw_;
    std::FILE *log_;
    bool drawn_ = false;
    int last_pct_ = -1;
};

/// Whether stderr is a terminal (a redrawn line makes sense there).
bool stderrIsTerminal();

}  // namespace projsurf::frontend
