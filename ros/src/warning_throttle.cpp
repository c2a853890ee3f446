#include "warning_throttle.hpp"

#include <ros/console.h>
#include <ros/time.h>

namespace projsurf::ros_node {

bool warningDue(WarningThrottle &throttle, const std::string &text, double now_s) {
    const auto at = throttle.last_s.find(text);
    if (at != throttle.last_s.end() && now_s - at->second < kWarningRepeatS) return false;
    // Texts that change from frame to frame (a stamp in them) must not pile up.
    for (auto it = throttle.last_s.begin(); it != throttle.last_s.end();)
        it = now_s - it->second >= kWarningRepeatS ? throttle.last_s.erase(it) : std::next(it);
    throttle.last_s[text] = now_s;
    return true;
}

void warnThrottled(WarningThrottle &throttle, const std::string &text, const std::string &key) {
    if (warningDue(throttle, key.empty() ? text : key, ros::WallTime::now().toSec()))
        ROS_WARN("projsurf_node: %s", text.c_str());
}

}  // namespace projsurf::ros_node
