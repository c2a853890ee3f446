#include "projsurf/frontend/render/progress.hpp"

#include <unistd.h>
#include <algorithm>

namespace projsurf::frontend {

namespace {
constexpr int kBarWidth = 25;  ///< characters of the bar
}  // namespace

bool stderrIsTerminal() { return ::isatty(2) != 0; }

ProgressLine::ProgressLine(std::string label, std::string unit, bool redraw, std::FILE *log)
    : label_(std::move(label)), unit_(std::move(unit)), redraw_(redraw), log_(log) {}

ProgressLine::~ProgressLine() {
    if (redraw_ && drawn_) std::fprintf(stderr, "\r%78s\r", ""), std::fflush(stderr);
}

void ProgressLine::update(long done, long total, const std::string &what) {
    const int pct = total > 0 ? static_cast<int>(std::clamp<long>(100 * done / total, 0, 100)) : -1;
    if (!redraw_) {
        if (pct < 0 || (last_pct_ >= 0 && pct / 10 == last_pct_ / 10)) return;
        std::fprintf(log_, "%s: %d%% (%ld/%ld %s)\n", label_.c_str(), pct, done, total, unit_.c_str());
        std::fflush(log_);
        last_pct_ = pct;
        return;
    }
    drawn_ = true;
    if (pct < 0) {
        std::fprintf(stderr, "\r%s: %ld %s %-30.30s", label_.c_str(), done, unit_.c_str(), what.c_str());
    } else {
        const int filled = pct * kBarWidth / 100;
        const std::string bar = std::string(filled, '#') + std::string(kBarWidth - filled, '.');
        std::fprintf(stderr, "\r%s: [%s] %3d%% %ld/%ld %s %-30.30s", label_.c_str(), bar.c_str(), pct, done, total,
                     unit_.c_str(), what.c_str());
    }
    std::fflush(stderr);
    last_pct_ = pct;
}

void ProgressLine::finish(long done) {
    if (redraw_ && drawn_) std::fprintf(stderr, "\r%s: %ld %s done%60s\n", label_.c_str(), done, unit_.c_str(), "");
    drawn_ = false;
}

void ProgressLine::endLine() {
    if (redraw_ && drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
}

}  // namespace projsurf::frontend
