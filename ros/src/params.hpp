#pragma once
// The node's parameters (contract, "ROS node"): ~calib, ~aspect, ~image, ~continuous,
// ~gravity and every pipeline setting under the CLI's name with '-' written '_'
// (ROS names allow no '-'), plus the node's own: input, frames and continuous-mode settings.
#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/planning/stand_planner.hpp"
#include "projsurf/tracking/continuous_tracker.hpp"
#include "projsurf/tracking/steady_tracker.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::ros_node {

struct NodeParams {
    std::string calib;                        ///< ~calib: projector calibration YAML (required)
    std::vector<std::string> calib_warnings;  ///< unknown keys in ~calib's `projector:` (the node logs them)
    std::string image;                        ///< ~image: picture to show (optional; the `image` topic overrides it)
    bool continuous = false;                  ///< ~continuous: detect on every cloud and keep the picture steady
    /// ~use_colour: pair each cloud with the registered colour image of its stamp (topic
    /// `rgb/image_rect_color`) for the surface suitability; false = depth only.
    bool use_colour = false;
    bool explain = false;  ///< ~explain: ~result carries `candidates`, every plane considered and why it lost
    /// ~suitability was given (off | avoid | prefer, the CLI's --suitability; stored in
    /// detector.suitability.mode, default avoid).
    bool suitability_given = false;
    bool blank = true;    ///< ~blank: continuous mode blacks out what stands in the beam (contract "Blanking")
    PlanOptions plan;     ///< ~plan_width, ~plan_max_move: the ~plan service (contract "Where to stand")
    Projector projector;  ///< read from ~calib
    /// ~config (a detector settings YAML, as `detect --config`), then over it ~aspect,
    /// ~gravity, ~method, ~hull and the CLI's pipeline options: ~max_tilt, ~seed, ~voxel_leaf,
    /// ~ransac_distance, ~max_outliers, ~cell, ~max_planes, ~max_outlier_fraction (defaults:
    /// DetectorConfig's).
    DetectorConfig detector;
    /// ~min_width (m), ~min_area (m^2): smaller rectangles are "not found", as `detect
    /// --min-width/--min-area` (defaults: frontend/settings/minimum_size.hpp's for ~method).
    frontend::MinimumSize minimum;

    /// ~gravity_frame: a frame whose -z is gravity (e.g. base_link or odom); when set, gravity
    /// in the camera frame comes from tf2 for every cloud and ~gravity is the fallback.
    std::string gravity_frame;
    /// ~gravity: down in the camera frame (3 numbers; default a level camera), or auto -> down
    /// from the floor in each cloud (no IMU, no tf), as `detect --gravity auto`.
    frontend::GravityChoice gravity;
    /// ~fixed_frame: a frame that does not move with the robot (odom, map); continuous mode
    /// keeps the picture put in it. Empty: the camera frame (a robot standing still).
    std::string fixed_frame;
    double tf_timeout = 0.1;  ///< ~tf_timeout, s: wait for a transform at a cloud's stamp
    SteadyConfig steady;      ///< ~steady_scale, ~switch_frames, ~hold_frames, ~plane_smoothing, ...
    /// ~keystone_tolerance_px: a rectangle may leave the framebuffer by this much and still be
    /// shown (its edge clipped); the detector's raster puts corners up to a few px outside.
    double keystone_tolerance_px = 4.0;
    /// ~fit_margin_px: the held picture must stay this far inside the framebuffer (px)
    double fit_margin_px = ContinuousSettings{}.fit_margin_px;
    std::string
        framebuffer_file;  ///< ~framebuffer_file: also write each new framebuffer PNG here (for `projsurf show`)
    std::string marker_ns = "projsurf";  ///< ~marker_ns: namespace of the RViz markers
};

/// Reads every parameter from the private handle `pnh`; throws InputError naming the
/// parameter (or the calibration file) and the problem.
NodeParams loadParams(const ros::NodeHandle &pnh);

/// One of the settings the front ends share by name (frontend/settings/shared_settings.hpp), ~max_tilt
/// and the like, from its parameter value (an int, a double, or a string for a seed beyond an
/// XML-RPC int): the key table's check, as `detect --max-tilt` and Python's max_tilt=; throws
/// InputError(what, ...).
void setSharedParam(DetectorConfig &config, const std::string &setting, const XmlRpc::XmlRpcValue &value,
                    const std::string &what);

}  // namespace projsurf::ros_node
