// libFuzzer harness: readDetectionJson on a detection JSON (projsurf detect --json).
#include "fuzz_common.hpp"
#include "projsurf/io/formats/detection_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("det.json", data, size);
    fuzz::expectOnlyInputErrors([&] { (void)readDetectionJson(path); });
    return 0;
}
