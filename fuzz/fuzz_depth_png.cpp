// libFuzzer harness: readDepthCloud on a depth PNG, with the seeds' camera (64 x 48).
#include "fuzz_common.hpp"
#include "projsurf/io/formats/cloud_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    static const std::string camera = [] {
        const std::string yaml =
            "camera: {width: 64, height: 48, fx: 52.5, fy: 52.5, cx: 31.5, cy: 23.5, depth_scale: 1000}\n";
        return fuzz::writeInput("camera.yaml", reinterpret_cast<const std::uint8_t *>(yaml.data()), yaml.size());
    }();
    const std::string path = fuzz::writeInput("depth.png", data, size);
    fuzz::expectOnlyInputErrors([&] { (void)readDepthCloud(path, camera); });
    return 0;
}
