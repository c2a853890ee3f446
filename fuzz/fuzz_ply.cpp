// libFuzzer harness: readCloud on a PLY file (ascii, binary little/big endian).
#include "fuzz_common.hpp"
#include "projsurf/io/formats/cloud_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("in.ply", data, size);
    fuzz::expectOnlyInputErrors([&] { (void)readCloud(path); });
    return 0;
}
