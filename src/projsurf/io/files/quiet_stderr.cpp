#include "projsurf/io/files/quiet_stderr.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <cstdio>
#include <mutex>

namespace projsurf {
namespace {
// Nested or concurrent QuietStderr share one redirection.
std::mutex g_mutex;
int g_depth = 0;
int g_saved = -1;
}  // namespace

QuietStderr::QuietStderr() {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (g_depth++ > 0) return;
    std::fflush(stderr);
    g_saved = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (g_saved >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
    saved_ = g_saved;
}

QuietStderr::~QuietStderr() {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (--g_depth > 0) return;
    std::fflush(stderr);
    if (g_saved >= 0) {
        ::dup2(g_saved, 2);
        ::close(g_saved);
    }
    g_saved = -1;
}

}  // namespace projsurf
