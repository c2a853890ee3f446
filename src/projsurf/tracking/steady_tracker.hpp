#pragma once
// Continuous mode (the paper's future work, section 6: "adapting the algorithms to work on a
// moving robot"): decides, frame by frame, where the picture is shown so that it stays put on
// the wall while the robot moves, does not jitter with the sensor noise, and does not jump
// between surfaces when two are about as good. Pure logic over planes and rectangles given in
// one fixed (world) frame; the caller transforms in and out and says whether the rectangle it
// holds can still be shown from where the robot is now.
#include <Eigen/Core>

#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf {

struct SteadyConfig {
    double same_wall_angle = 0.1745;   ///< rad (10 deg): planes closer in normal may be one wall
    double same_wall_distance = 0.10;  ///< m: ... when the held centre is this close to the new plane
    int switch_frames = 5;             ///< frames in a row another place must win before the picture moves there
    int hold_frames = 10;              ///< frames the picture stays when it cannot be shown and nothing replaces it
    double plane_smoothing = 0.2;      ///< weight of a new plane estimate in the running average, (0, 1]
    double scale = 0.85;               ///< share of the detected rectangle's width/height that is used,
                                       ///< leaving room for the robot to move before the picture must
    double grow_ratio = 1.5;           ///< a place this many times bigger in area (for switch_frames) moves the picture
};

/// One frame's evidence, in the fixed frame.
struct SteadyMeasurement {
    bool found = false;        ///< the detector found a rectangle in this frame
    Plane plane;               ///< its plane
    Rectangle rectangle;       ///< its rectangle (full size, before `scale`)
    bool held_usable = false;  ///< the held rectangle still fits the projector and its surface is clear
};

enum class SteadyEvent {
    None,      ///< nothing held, nothing found
    Acquired,  ///< first rectangle taken
    Kept,      ///< the held rectangle stays (plane refined)
    Moved,     ///< a new place on the same wall (the old one could not be shown, or a much bigger one)
    Switched,  ///< another wall, after it won switch_frames frames in a row
    Held,      ///< the held rectangle cannot be shown right now but is kept for a while
    Lost,      ///< given up: nothing is shown
};
const char *toString(SteadyEvent event);

class SteadyTracker {
public:
    explicit SteadyTracker(const SteadyConfig &config = {}) : config_(config) {}

    SteadyEvent update(const SteadyMeasurement &m);
    void reset();

    bool hasTarget() const { return has_target_; }
    /// The rectangle to show (fixed frame); valid when hasTarget().
    const Rectangle &target() const { return target_; }
    const Plane &plane() const { return plane_; }
    const SteadyConfig &config() const { return config_; }

    /// True when `plane` (with a point `anchor` of the held surface) is the same wall as `held`.
    bool sameWall(const Plane &held, const Eigen::Vector3d &anchor, const Plane &plane) const;

private:
    void adopt(const SteadyMeasurement &m);
    void refinePlane(const Plane &measured);
    bool countCandidate(const SteadyMeasurement &m);

    SteadyConfig config_;
    bool has_target_ = false;
    Rectangle target_;
    Plane plane_;
    int unusable_frames_ = 0;
    bool has_candidate_ = false;
    Plane candidate_plane_;
    Eigen::Vector3d candidate_center_ = Eigen::Vector3d::Zero();
    int candidate_frames_ = 0;
};

/// `rect` shrunk (or grown) about its centre by `factor` in width and height.
Rectangle scaleRectangle(const Rectangle &rect, double factor);

/// True when every corner of `rect` (camera frame) is lit by the projector, at least
/// `margin_px` inside the framebuffer's outer edges.
bool fitsProjector(const Projector &projector, const Rectangle &rect, double margin_px = 0.0);

}  // namespace projsurf
