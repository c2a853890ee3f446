#pragma once
// How the node says what is wrong with its input: it cannot stop on a stream, so a problem
// (colour of another size, a camera the floor says is tilted) is a ROS warning, each text at
// most once every kWarningRepeatS while it lasts: seen when the node starts or the problem
// begins, never one per frame.
#include <map>
#include <string>

namespace projsurf::ros_node {

/// s: the same warning text is logged again after this long, not before.
constexpr double kWarningRepeatS = 30.0;

struct WarningThrottle {
    std::map<std::string, double> last_s;  ///< each text logged, and when (s)
};

/// True when `text` is due at `now_s` (never logged, or kWarningRepeatS ago), and then
/// remembered as logged now; texts last logged long ago are forgotten.
bool warningDue(WarningThrottle &throttle, const std::string &text, double now_s);

/// ROS_WARN("projsurf_node: <text>") when warningDue at the wall clock's now. `key`, when not
/// empty, is throttled instead of the text (a text with a measurement in it that changes a
/// little from frame to frame).
void warnThrottled(WarningThrottle &throttle, const std::string &text, const std::string &key = "");

}  // namespace projsurf::ros_node
