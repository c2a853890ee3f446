// libFuzzer harness: the detector settings file (detect --config, the node's ~config, Python's
// config=), read as every front end reads it, and, when it is accepted, a detection run with
// it on a small organized frame (a wall and a floor, 64 x 48): a value inside its documented
// range must never end in an OpenCV assertion or a crash (wall.shape.relief.node_px: 1e-300
// did). PROJSURF_FUZZ_WRITE_SEEDS=DIR writes the seeds there: a valid file, and the hostile
// cases of issue 39 (an alias cycle, aliases nested deep, keys given twice, a second document,
// values at the ends of their ranges, a Latin-1 key, a key holding a newline, 1000 unknown keys).
#include <cstdlib>
#include <filesystem>

#include "fuzz_common.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/settings/detector_config_file.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

namespace fs = std::filesystem;

namespace {

const projsurf::Projector &exampleProjector() {
    static const projsurf::Projector p = [] {
        const char yaml[] =
            "projector:\n  resolution: [1280, 800]\n  fov_deg: [39.3, 24.0]\n  axis:\n"
            "    origin: [0, 0.12, 0]\n    direction: [0, -0.05, 0.9987]\n";
        const std::string path =
            projsurf::fuzz::writeInput("calib.yaml", reinterpret_cast<const std::uint8_t *>(yaml), sizeof yaml - 1);
        return projsurf::readCalibration(path);
    }();
    return p;
}

/// A camera 0.8 m above the floor, 2.5 m from a wall, 64 x 48 px (f = 52.5 px).
const projsurf::Cloud &frame() {
    static const projsurf::Cloud c = [] {
        projsurf::Cloud cloud;
        cloud.width = 64;
        cloud.height = 48;
        for (int v = 0; v < cloud.height; ++v)
            for (int u = 0; u < cloud.width; ++u) {
                const double x = (u - 31.5) / 52.5, y = (v - 23.5) / 52.5;
                double t = 2.5;
                if (y > 0 && 0.8 / y < t) t = 0.8 / y;
                cloud.points.emplace_back(static_cast<float>(x * t), static_cast<float>(y * t), static_cast<float>(t));
            }
        return cloud;
    }();
    return c;
}

std::vector<std::string> seeds() {
    std::string many;
    for (int i = 0; i < 1000; ++i) many += "bogus_" + std::to_string(i) + ": 1\n";
    std::string deep = "a0: &a0 {x: 1}\n";
    for (int i = 1; i < 70; ++i)
        deep += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " {x: *a" + std::to_string(i - 1) + "}\n";
    return {
        "planes:\n  max_planes: 6\nwall:\n  shape:\n    relief:\n      node_px: 12\n      sigma_px: 20\n",
        "planes: &p {max_planes: 4, sub: *p}\n",
        deep,
        "planes:\n  max_planes: 4\nplanes:\n  min_plane_points: 50\n",
        "planes.max_planes: 4\nplanes: {max_planes: 5}\n",
        "planes: {max_planes: 4}\n---\nplanes: {max_planes: 5}\n",
        "wall.shape.relief.node_px: 1e-300\n",
        "wall.shape.relief.sigma_px: 1e300\n",
        "wall.shape.relief.node_px: 1\nwall.shape.relief.sigma_px: 10\nwall.shape.relief.max_nodes: 1024\n",
        "tolerance.noise_k: 1\ntolerance.min_band: 10\ntolerance.max_band: 10\n",
        "plan\xe9s: 4\n",
        "\"planes\\nprojsurf: error: forged\": 4\n",
        many,
        "objects.surround.offsets: [0.0001, 10, 10, 10]\nfree_space.proud.window: 10\nfree_space.cell: 0.002\n",
    };
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    if (const char *dir = std::getenv("PROJSURF_FUZZ_WRITE_SEEDS")) {
        fs::create_directories(dir);
        const auto all = seeds();
        for (std::size_t i = 0; i < all.size(); ++i) {
            projsurf::fuzz::writeInput("seed", reinterpret_cast<const std::uint8_t *>(all[i].data()), all[i].size());
            fs::copy_file(projsurf::fuzz::workDir() + "/seed", fs::path(dir) / ("seed_" + std::to_string(i)),
                          fs::copy_options::overwrite_existing);
        }
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("settings.yaml", data, size);
    fuzz::expectOnlyInputErrors([&] {
        DetectorConfig cfg;
        frontend::readDetectorConfig(path, cfg);
        (void)frontend::detectorConfigYaml(cfg);  // --print-config
        SurfaceDetector detector(exampleProjector(), cfg);
        (void)frontend::detectAnswer(detector, frame(), SurfaceDetector::levelGravity(),
                                     frontend::defaultMinimumSize(cfg.method), path);
    });
    return 0;
}
