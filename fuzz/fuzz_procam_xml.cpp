// libFuzzer harness: readProcamXml on a procam calibration_result.xml (eval --procam).
#include "fuzz_common.hpp"
#include "projsurf/io/formats/procam_xml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("calibration_result.xml", data, size);
    fuzz::expectOnlyInputErrors([&] { (void)readProcamXml(path); });
    return 0;
}
