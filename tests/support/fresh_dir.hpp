#pragma once
// An empty scratch folder for a test: <tmp>/projsurf_test_<suite>_<name>_<pid>, made anew.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace projsurf::test {

inline std::filesystem::path freshDir(const std::string &suite, const std::string &name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("projsurf_test_" + suite + "_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace projsurf::test
