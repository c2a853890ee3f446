// libFuzzer harness: forEachBagCloud on a ROS 1 bag (the topic /points, as the seeds have it).
#include "fuzz_common.hpp"
#include "projsurf/io/rosbag/rosbag_clouds.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace projsurf;
    const std::string path = fuzz::writeInput("in.bag", data, size);
    fuzz::expectOnlyInputErrors([&] { forEachBagCloud(path, "/points", [](const Cloud &, const BagCloudInfo &) {}); });
    return 0;
}
