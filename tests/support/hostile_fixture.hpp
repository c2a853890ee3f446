#pragma once
// The fixture of the CLI's hostile-input tests: a simulated frame (cloud, depth, camera,
// calibration, three structured-light captures) made once per suite, a fresh folder per case,
// and `refused`, the contract for an input the CLI must refuse (docs/limits.md).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace projsurf::test {

inline void writeBytes(const std::filesystem::path &path, const std::string &bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

/// Files under `dir` with ".tmp" in their name (an output half written).
inline int tmpLeftovers(const std::filesystem::path &dir) {
    int n = 0;
    for (const auto &e : std::filesystem::recursive_directory_iterator(dir))
        if (e.path().filename().string().find(".tmp") != std::string::npos) ++n;
    return n;
}

class HostileCli : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        sim_ = std::filesystem::temp_directory_path() / ("projsurf_hostile_sim_" + std::to_string(::getpid()));
        std::filesystem::remove_all(sim_);
        const std::string cmd = std::string(PROJSURF_CLI) + " simulate --scenario wall --captures 3 --out " +
                                sim_.string() + " >/dev/null 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0);
    }
    static void TearDownTestSuite() { std::filesystem::remove_all(sim_); }
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("projsurf_hostile_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override {
        // Every child so far stayed under the memory target (ru_maxrss: KiB, the largest child).
        rusage ru{};
        getrusage(RUSAGE_CHILDREN, &ru);
        EXPECT_LT(ru.ru_maxrss, 2L * 1024 * 1024) << "a projsurf run took more than 2 GiB";
        if (!HasFailure()) std::filesystem::remove_all(dir_);
    }
    std::string sim(const char *name) const { return (sim_ / name).string(); }
    std::string at(const std::string &name) const { return (dir_ / name).string(); }
    /// detect on the simulated calibration and `cloud` (the simulated one when empty).
    std::string detectArgs(const std::string &cloud = "") const {
        return "detect --calib " + sim("calib.yaml") + " --cloud " + (cloud.empty() ? sim("cloud.pcd") : cloud);
    }

    /// Exit 2, one stderr line "projsurf: error: " naming `file` and saying `problem`, none of
    /// `outputs` written, no temporary left.
    void refused(const std::string &args, const std::string &file, const std::string &problem,
                 const std::vector<std::string> &outputs = {}) {
        const CliRun r = cli(args, dir_);
        EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one stderr line expected:\n" << r.err;
        EXPECT_EQ(r.err.rfind("projsurf: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(file), std::string::npos) << "should name " << file << ": " << r.err;
        EXPECT_NE(r.err.find(problem), std::string::npos) << "should say '" << problem << "': " << r.err;
        for (const auto &o : outputs) EXPECT_FALSE(std::filesystem::exists(o)) << o << " was written";
        EXPECT_EQ(tmpLeftovers(dir_), 0);
    }

    static inline std::filesystem::path sim_;
    std::filesystem::path dir_;
};

}  // namespace projsurf::test
