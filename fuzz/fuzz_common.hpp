#pragma once
// What every libFuzzer harness of projsurf's readers shares: the readers take file names, so
// each input is written to a file of the right extension in a private folder first. An
// InputError is the expected answer to a bad input; anything else escaping (another
// exception, a crash, a sanitizer report) is a finding.
#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "projsurf/io/files/errors.hpp"

namespace projsurf::fuzz {

/// A folder of this process for the inputs' files.
inline const std::string &workDir() {
    static const std::string dir = [] {
        const char *base = std::getenv("PROJSURF_FUZZ_TMP");
        std::string d = std::string(base ? base : "/tmp") + "/projsurf_fuzz_" + std::to_string(::getpid());
        std::system(("mkdir -p '" + d + "'").c_str());
        return d;
    }();
    return dir;
}

/// Writes bytes to workDir()/name and returns the path.
inline std::string writeInput(const std::string &name, const std::uint8_t *data, std::size_t size) {
    const std::string path = workDir() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
    return path;
}

/// Runs `read`; an InputError is a normal answer, other exceptions abort (a finding).
template <class F>
void expectOnlyInputErrors(F &&read) {
    try {
        read();
    } catch (const InputError &) {
    }
}

}  // namespace projsurf::fuzz
