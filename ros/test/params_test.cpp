// The node's shared settings (~max_tilt, ~seed, ...) at the edges of their ranges: accepted and
// refused as the key table says, which `detect --max-tilt` and Python's max_tilt= follow too
// (python/tests/test_cli_parity.py runs the same edges there). No master needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "params.hpp"
#include "projsurf/frontend/settings/shared_settings.hpp"
#include "projsurf/io/files/errors.hpp"

namespace projsurf::ros_node {
namespace {

/// The parameter as rosparam stores a YAML number: an int when it is whole and fits one.
XmlRpc::XmlRpcValue param(double v, bool whole) {
    if (whole && std::abs(v) < 2147483647.0) return XmlRpc::XmlRpcValue(static_cast<int>(v));
    return XmlRpc::XmlRpcValue(v);
}

bool accepted(const std::string &setting, const XmlRpc::XmlRpcValue &value) {
    DetectorConfig c;
    try {
        setSharedParam(c, setting, value, "~" + setting);
        return true;
    } catch (const InputError &) {
        return false;
    }
}

TEST(SharedParams, EverySettingAtItsRangeEdgesAsTheKeyTableSays) {
    for (const std::string &setting : frontend::sharedNumberSettings()) {
        const frontend::ConfigKey &key = frontend::sharedSettingKey(setting);
        const bool whole = key.type != frontend::KeyType::Double;
        const double step = whole ? 1.0 : std::max(1e-3, (key.range.hi - key.range.lo) * 1e-3);
        EXPECT_EQ(accepted(setting, param(key.range.lo, whole)), !key.range.lo_open) << setting << " at its low end";
        EXPECT_TRUE(accepted(setting, param(key.range.hi, whole))) << setting << " at its high end";
        EXPECT_FALSE(accepted(setting, param(key.range.lo - step, whole))) << setting << " below its range";
        EXPECT_FALSE(accepted(setting, param(key.range.hi + step, whole))) << setting << " above its range";
    }
}

TEST(SharedParams, TheNodeTakesWhatTheCliTakes) {
    // Before the table: ~max_tilt 2.0 was accepted, 0 refused, and no seed >= 2^31 could be given.
    EXPECT_FALSE(accepted("max_tilt", XmlRpc::XmlRpcValue(2.0)));
    EXPECT_TRUE(accepted("max_tilt", XmlRpc::XmlRpcValue(0)));
    EXPECT_TRUE(accepted("max_tilt", XmlRpc::XmlRpcValue(0.0)));
    EXPECT_TRUE(accepted("seed", XmlRpc::XmlRpcValue(4294967295.0)));
    EXPECT_TRUE(accepted("seed", XmlRpc::XmlRpcValue(std::string("3000000000"))));
    EXPECT_FALSE(accepted("seed", XmlRpc::XmlRpcValue(-1)));
    EXPECT_FALSE(accepted("max_planes", XmlRpc::XmlRpcValue(2.5)));
    EXPECT_FALSE(accepted("cell", XmlRpc::XmlRpcValue(true)));
    DetectorConfig c;
    setSharedParam(c, "seed", XmlRpc::XmlRpcValue(3000000000.0), "~seed");
    EXPECT_EQ(c.seed, 3000000000u);
    try {
        setSharedParam(c, "max_tilt", XmlRpc::XmlRpcValue(2.0), "/projsurf/max_tilt");
        FAIL();
    } catch (const InputError &e) {
        EXPECT_STREQ(e.what(), "/projsurf/max_tilt: must be a number from 0 to 1.5, got '2'");
    }
}

}  // namespace
}  // namespace projsurf::ros_node
