#pragma once
// Continuous mode on a moving robot, whatever the front end (the ROS node, Python's Tracker,
// `projsurf detect --bag --steady`): each frame's detection carried into a fixed frame (the
// camera's pose there: odom, map, or the camera itself for a robot standing still), the steady
// tracker updated with it (tracking/steady_tracker.hpp), told whether the rectangle it holds can
// still be shown from where the camera is now (tracking/held_rectangle.hpp), and the rectangle
// to show carried back into this frame's camera frame.
#include <Eigen/Geometry>
#include <utility>

#include "projsurf/detection/detection.hpp"
#include "projsurf/detection/detector_config.hpp"
#include "projsurf/tracking/steady_tracker.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct ContinuousSettings {
    Projector projector;      ///< the projector the picture is shown with
    DetectorConfig detector;  ///< the detector's settings: its tolerance and surface check judge the held rectangle
    SteadyConfig steady;      ///< when the picture stays, moves or switches walls
    /// px: every corner of the held picture stays this far inside the framebuffer, or it is not
    /// shown from here (a little room for the keystone warp's rounding).
    double fit_margin_px = 2.0;
};

/// The settings for `projector` and `detector`, with the steady options and the fit margin at
/// their defaults (what Python's Tracker and `detect --bag --steady` run with).
ContinuousSettings continuousSettings(const Projector &projector, const DetectorConfig &detector);

/// What to show after one frame.
struct ContinuousFrame {
    SteadyEvent event = SteadyEvent::None;
    bool has_target = false;  ///< a rectangle is held: `shown` is valid
    Rectangle shown;          ///< the rectangle to show, in the camera frame of this frame's cloud
};

class ContinuousTracker {
public:
    explicit ContinuousTracker(ContinuousSettings settings)
        : settings_(std::move(settings)), tracker_(settings_.steady) {}

    /// One frame: `det` was detected in `cloud` (camera frame); `fixed_from_camera` is the
    /// camera's pose in the fixed frame at the cloud's time (identity: a robot standing still).
    ContinuousFrame update(const Detection &det, const Cloud &cloud, const Eigen::Isometry3d &fixed_from_camera);
    void reset() { tracker_.reset(); }
    const SteadyTracker &tracker() const { return tracker_; }
    const ContinuousSettings &settings() const { return settings_; }

private:
    ContinuousSettings settings_;
    SteadyTracker tracker_;
};

}  // namespace projsurf
