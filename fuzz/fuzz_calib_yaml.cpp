// libFuzzer harness: readCalibration on a projector calibration YAML.
#include "fuzz_common.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("calib.yaml", data, size);
    fuzz::expectOnlyInputErrors([&] { (void)readCalibration(path); });
    return 0;
}
