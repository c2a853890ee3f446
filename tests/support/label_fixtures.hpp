#pragma once
// Shared by the label tests (test_real_labels.cpp, test_colour_labels.cpp): a label file
// written to a folder, the reader's error for a text, a one-place text edit, a frontal
// synthetic wall, and where a labelled real frame is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "eval/real/real_labels.hpp"
#include "projsurf/io/files/errors.hpp"

using namespace projsurf::eval;  // the evaluation under test

namespace projsurf::test {

inline std::string writeLabel(const std::filesystem::path &dir, const std::string &name, const std::string &text) {
    const std::filesystem::path p = dir / name;
    std::ofstream(p) << text;
    return p.string();
}

/// The message readRealLabel throws for `text`, or "" when it reads.
inline std::string readError(const std::filesystem::path &dir, const std::string &text) {
    const std::string path = writeLabel(dir, "bad.yaml", text);
    try {
        readRealLabel(path);
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

/// `s` with its first `from` replaced by `to` (a test failure when there is none).
inline std::string replaced(std::string s, const std::string &from, const std::string &to) {
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

/// A frontal wall at `z` metres filling a 640x480 pinhole image (525 px focal length).
struct SyntheticWall {
    CameraIntrinsics camera;
    Cloud cloud;
    explicit SyntheticWall(double z) {
        cloud.width = camera.width;
        cloud.height = camera.height;
        for (int v = 0; v < camera.height; ++v)
            for (int u = 0; u < camera.width; ++u) cloud.points.push_back(camera.backProject(u, v, z).cast<float>());
    }
};

/// Where a labelled real frame is: ../shared/data/real/<frame>, else the repository's
/// data/real/<frame> (the frames that ship) or data/<frame> (the quick start's); "" when in none.
inline std::string labelledFrameDir(const std::string &frame) {
    for (const std::string &root : {std::string(PROJSURF_SHARED_DIR) + "/data/real",
                                     std::string(PROJSURF_SOURCE_DIR) + "/data/real", std::string(PROJSURF_SOURCE_DIR) + "/data"})
        if (std::filesystem::is_directory(root + "/" + frame)) return root + "/" + frame;
    return "";
}

}  // namespace projsurf::test
