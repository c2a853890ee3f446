#pragma once
// Running the projsurf CLI from a test: exit status, stdout and stderr; a folder to run it in.
#include <sys/wait.h>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace projsurf::test {

struct CliRun {
    int status = -1;  ///< exit status, -1 when it did not exit (killed by the time limit)
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path &path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// `projsurf ARGS` run in a shell with a hang guard of `timeout_s`; its output is captured in
/// `dir` and the capture files are removed again (tests check what the command leaves behind).
inline CliRun cli(const std::string &args, const std::filesystem::path &dir, int timeout_s = 120) {
    const std::filesystem::path o = dir / "cli_stdout.log", e = dir / "cli_stderr.log";
    const std::string cmd = "timeout " + std::to_string(timeout_s) + " " + std::string(PROJSURF_CLI) + " " + args +
                            " >" + o.string() + " 2>" + e.string();
    const int s = std::system(cmd.c_str());
    CliRun r{WIFEXITED(s) ? WEXITSTATUS(s) : -1, slurp(o), slurp(e)};
    std::filesystem::remove(o);
    std::filesystem::remove(e);
    return r;
}

/// An empty folder for one test: the temporary directory's projsurf_<name>_<pid>.
inline std::filesystem::path freshDir(const std::string &name) {
    const std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("projsurf_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

}  // namespace projsurf::test
