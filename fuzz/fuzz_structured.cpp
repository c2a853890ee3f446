// libFuzzer harness: a structured-light capture folder, read and decoded as calibrate does
// (patterns.yaml, camera.yaml, the pose folders, each pose's depth and captures, the decoding,
// the lift to 3-D, the fit). A valid folder is made once (a 16 x 8 framebuffer seen by a
// 64 x 48 camera on a tilted wall with a box before its right half: it calibrates); the input
// replaces one of its files: the first byte says which (patterns.yaml, camera.yaml,
// pose_0/depth.png, then the captures in list order), the rest is the file. PROJSURF_FUZZ_WRITE_SEEDS=DIR writes the
// valid files as seeds there.
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fuzz_common.hpp"
#include "projsurf/calibration/decoded_points.hpp"
#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/projector_fit.hpp"
#include "projsurf/io/formats/pattern_files.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kFbW = 16, kFbH = 8, kCamW = 64, kCamH = 48;

struct ValidFolder {
    std::vector<std::string> names;  ///< relative paths, in the order the first byte selects
    std::vector<std::string> bytes;  ///< their valid contents
};

std::string encodePng(const cv::Mat &m) {
    std::vector<uchar> buf;
    cv::imencode(".png", m, buf);
    return std::string(buf.begin(), buf.end());
}

const ValidFolder &validFolder() {
    static const ValidFolder v = [] {
        ValidFolder f;
        const auto patterns = projsurf::grayPatterns(kFbW, kFbH);
        std::string yaml = "patterns:\n  resolution: [16, 8]\n  coding: gray_code_inverse\n  order:\n";
        for (const auto &p : patterns) yaml += "    - " + p.name + "\n";
        f.names.push_back("patterns.yaml");
        f.bytes.push_back(yaml);
        f.names.push_back("camera.yaml");
        f.bytes.push_back(
            "camera:\n  width: 64\n  height: 48\n  fx: 52\n  fy: 52\n  cx: 31.5\n  cy: 23.5\n"
            "  depth_scale: 1000\n");
        cv::Mat depth(kCamH, kCamW, CV_16UC1);
        for (int y = 0; y < kCamH; ++y)
            for (int x = 0; x < kCamW; ++x)
                depth.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>((x < 32 ? 1500 : 1200) + 4 * x);
        f.names.push_back("pose_0/depth.png");
        f.bytes.push_back(encodePng(depth));
        for (const auto &p : patterns) {
            cv::Mat seen;
            cv::resize(projsurf::grayPatternImage(p, kFbW, kFbH), seen, {kCamW, kCamH}, 0, 0, cv::INTER_NEAREST);
            f.names.push_back("pose_0/" + p.name + ".png");
            f.bytes.push_back(encodePng(seen));
        }
        return f;
    }();
    return v;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    if (const char *dir = std::getenv("PROJSURF_FUZZ_WRITE_SEEDS")) {
        const ValidFolder &f = validFolder();
        fs::create_directories(dir);
        for (std::size_t i = 0; i < f.names.size(); ++i) {
            const std::string seed = std::string(1, static_cast<char>(i)) + f.bytes[i];
            projsurf::fuzz::writeInput("seed", reinterpret_cast<const std::uint8_t *>(seed.data()), seed.size());
            fs::copy_file(projsurf::fuzz::workDir() + "/seed", fs::path(dir) / ("seed_" + std::to_string(i)),
                          fs::copy_options::overwrite_existing);
        }
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    if (size < 1) return 0;
    const ValidFolder &f = validFolder();
    const std::size_t which = data[0] % f.names.size();
    const fs::path dir = fs::path(fuzz::workDir()) / "captures";
    fs::create_directories(dir / "pose_0");
    for (std::size_t i = 0; i < f.names.size(); ++i) {
        if (i == which)
            fuzz::writeInput("captures/" + f.names[i], data + 1, size - 1);
        else
            fuzz::writeInput("captures/" + f.names[i], reinterpret_cast<const std::uint8_t *>(f.bytes[i].data()),
                             f.bytes[i].size());
    }
    fuzz::expectOnlyInputErrors([&] {
        const PatternList list = readPatternList((dir / "patterns.yaml").string());
        const CameraIntrinsics camera = readCamera((dir / "camera.yaml").string());
        std::vector<ProjectorCorrespondence> pairs;
        for (const auto &pose_dir : listPoseFolders(dir.string(), list, camera.width, camera.height)) {
            PoseCaptures pose = readPoseCaptures(pose_dir, list, camera.width, camera.height);
            const GrayDecoding d = decodeGray(pose.colour, list.width, list.height);
            liftDecoding(d, pose.depth, camera, pairs);
        }
        ProjectorFitConfig cfg;
        cfg.width = list.width;
        cfg.height = list.height;
        cfg.min_points = 500;
        (void)fitProjector(pairs, cfg);
    });
    return 0;
}
