// libFuzzer harness: readCamera on a camera intrinsics YAML.
#include "fuzz_common.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("camera.yaml", data, size);
    fuzz::expectOnlyInputErrors([&] { (void)readCamera(path); });
    return 0;
}
