#include "projsurf/tracking/steady_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {

const char *toString(SteadyEvent event) {
    switch (event) {
    case SteadyEvent::None: return "none";
    case SteadyEvent::Acquired: return "acquired";
    case SteadyEvent::Kept: return "kept";
    case SteadyEvent::Moved: return "moved";
    case SteadyEvent::Switched: return "switched";
    case SteadyEvent::Held: return "held";
    case SteadyEvent::Lost: return "lost";
    }
    return "?";
}

Rectangle scaleRectangle(const Rectangle &rect, double factor) {
    Rectangle out = rect;
    const Eigen::Vector3d c = rect.center();
    for (auto &p : out.corners) p = c + factor * (p - c);
    out.width = rect.width * factor;
    out.height = rect.height * factor;
    return out;
}

bool fitsProjector(const Projector &projector, const Rectangle &rect, double margin_px) {
    for (const auto &corner : rect.corners) {
        const auto px = projector.toPixel(corner);
        if (!px) return false;
        if (px->x() < -0.5 + margin_px || px->x() > projector.width - 0.5 - margin_px) return false;
        if (px->y() < -0.5 + margin_px || px->y() > projector.height - 0.5 - margin_px) return false;
    }
    return true;
}

bool SteadyTracker::sameWall(const Plane &held, const Eigen::Vector3d &anchor, const Plane &plane) const {
    const double cos_angle = std::clamp(held.normal.dot(plane.normal), -1.0, 1.0);
    if (std::acos(cos_angle) > config_.same_wall_angle) return false;
    return std::abs(plane.signedDistance(anchor)) <= config_.same_wall_distance;
}

void SteadyTracker::reset() {
    has_target_ = false;
    unusable_frames_ = 0;
    has_candidate_ = false;
    candidate_frames_ = 0;
}

void SteadyTracker::adopt(const SteadyMeasurement &m) {
    has_target_ = true;
    plane_ = m.plane;
    target_ = scaleRectangle(m.rectangle, config_.scale);
    unusable_frames_ = 0;
    has_candidate_ = false;
    candidate_frames_ = 0;
}

void SteadyTracker::refinePlane(const Plane &measured) {
    // Running average of the plane; the held corners follow it along the normal only, so the
    // picture keeps its place on the wall and its size, and loses the depth noise.
    const double a = std::clamp(config_.plane_smoothing, 1e-3, 1.0);
    const Eigen::Vector3d n = ((1.0 - a) * plane_.normal + a * measured.normal).normalized();
    const Eigen::Vector3d c = target_.center();
    const double d_held = -plane_.normal.dot(plane_.project(c));
    const double d_meas = -measured.normal.dot(measured.project(c));
    plane_.normal = n;
    plane_.d = (1.0 - a) * d_held + a * d_meas;
    for (auto &p : target_.corners) p = plane_.project(p);
}

bool SteadyTracker::countCandidate(const SteadyMeasurement &m) {
    // A candidate must be the same place frame after frame to win.
    const Eigen::Vector3d center = m.rectangle.center();
    const bool same_as_before = has_candidate_ && sameWall(candidate_plane_, candidate_center_, m.plane) &&
                                (center - candidate_center_).norm() <= 0.5 * std::max(m.rectangle.width, 0.2);
    if (same_as_before) {
        ++candidate_frames_;
    } else {
        has_candidate_ = true;
        candidate_frames_ = 1;
    }
    candidate_plane_ = m.plane;
    candidate_center_ = center;
    return candidate_frames_ >= std::max(1, config_.switch_frames);
}

SteadyEvent SteadyTracker::update(const SteadyMeasurement &m) {
    if (!has_target_) {
        if (!m.found) return SteadyEvent::None;
        adopt(m);
        return SteadyEvent::Acquired;
    }
    const bool same = m.found && sameWall(plane_, target_.center(), m.plane);
    if (m.held_usable) {
        unusable_frames_ = 0;
        if (!m.found) {
            has_candidate_ = false;
            return SteadyEvent::Kept;
        }
        if (same) refinePlane(m.plane);
        // Hysteresis: only a much bigger place, winning several frames in a row, moves a
        // picture that can still be shown where it is.
        const double bigger = m.rectangle.area() * config_.scale * config_.scale;
        if (bigger > config_.grow_ratio * target_.area()) {
            if (countCandidate(m)) {
                adopt(m);
                return same ? SteadyEvent::Moved : SteadyEvent::Switched;
            }
        } else {
            has_candidate_ = false;
            candidate_frames_ = 0;
        }
        return SteadyEvent::Kept;
    }
    // The held rectangle cannot be shown from here (it left the projector's reach or
    // something stands in front of it).
    ++unusable_frames_;
    if (m.found && same) {
        adopt(m);  // the same wall: move along it, no jump to another surface
        return SteadyEvent::Moved;
    }
    if (m.found && countCandidate(m)) {
        adopt(m);
        return SteadyEvent::Switched;
    }
    if (unusable_frames_ > config_.hold_frames) {
        reset();
        return SteadyEvent::Lost;
    }
    return SteadyEvent::Held;
}

}  // namespace projsurf
