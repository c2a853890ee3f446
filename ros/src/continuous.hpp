#pragma once
// Continuous mode's ROS side: carries the steady tracker's rectangle between the camera frame
// of each cloud and the fixed frame (odom/map, from tf2; types/rigid_transform.hpp), and tells
// the tracker whether the held rectangle can still be shown from where the robot is now
// (tracking/held_rectangle.hpp).
#include <Eigen/Geometry>

#include "params.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/tracking/steady_tracker.hpp"
#include "projsurf/detector/detector.hpp"

namespace projsurf::ros_node {

class ContinuousMode {
public:
    explicit ContinuousMode(const NodeParams &params) : params_(params), tracker_(params.steady) {}

    struct Output {
        SteadyEvent event = SteadyEvent::None;
        bool has_target = false;
        Rectangle shown;  ///< what to show, in the camera frame of this cloud
    };

    /// One frame: `det` was detected in `cloud` (camera frame); `fixed_from_camera` is the
    /// camera's pose in the fixed frame at the cloud's stamp (identity without a fixed frame).
    Output update(const Detection &det, const Cloud &cloud, const Eigen::Isometry3d &fixed_from_camera,
                  const DetectorConfig &config);
    void reset() { tracker_.reset(); }
    const SteadyTracker &tracker() const { return tracker_; }

private:
    const NodeParams &params_;
    SteadyTracker tracker_;
};

}  // namespace projsurf::ros_node
