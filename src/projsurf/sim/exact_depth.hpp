#pragma once
// The exact geometry a depth sensor looks at, before any sensor effect: per pixel the depth of
// the surface seen (bowed walls included, Quad::bow), which quad it is, and what lies behind
// glass. The sensor models (kinect1_model, tof_model, d435_model) start from this.
#include <opencv2/core.hpp>

#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/types/camera.hpp"

namespace projsurf::sim {

struct ExactDepth {
    CameraIntrinsics camera;
    cv::Mat z;              ///< CV_64F, m along the optical axis of the first surface (glass included); 0 = nothing
    cv::Mat quad;           ///< CV_32S, its quad index, -1 = nothing
    cv::Mat on_glass;       ///< CV_8U, 1 where `quad` is glass (set when any_glass)
    cv::Mat behind_z;       ///< CV_64F, where `quad` is glass: the first non-glass surface behind it (0 = nothing)
    cv::Mat behind_quad;    ///< CV_32S, its quad, -1 = nothing (or not behind glass)
    cv::Mat cos_incidence;  ///< CV_32F, |cos| of the angle between the ray and the seen surface's normal
    bool any_glass = false;
};

/// Ray-casts the scene from the camera at the origin; hits nearer than 5 cm are ignored.
ExactDepth castExactDepth(const Scene &scene, const CameraIntrinsics &camera);

/// The depth and quad a sensor that reads through glass would see at (u, v): the first
/// non-glass surface (0 / -1 when none).
inline void opaqueAt(const ExactDepth &e, int u, int v, double &z, int &quad) {
    quad = e.quad.at<int>(v, u);
    z = e.z.at<double>(v, u);
    if (e.any_glass && e.on_glass.at<uchar>(v, u)) {
        quad = e.behind_quad.at<int>(v, u);
        z = e.behind_z.at<double>(v, u);
    }
}

/// CV_8U, 1 within `radius` px of a depth edge: a 4-neighbour whose depth differs by more
/// than `jump` m, or which has no surface.
cv::Mat depthEdgeMask(const cv::Mat &z, double jump, int radius);

/// CV_8U, 1 where the surface point seen at a pixel cannot be reached from `origin` (camera
/// frame): the IR emitter's shadow (Kinect) or what the second imager cannot see (stereo).
/// Points outside that view (it has the camera's intrinsics widened by `pad_px` each side)
/// count as not reached.
cv::Mat occlusionFrom(const Scene &scene, const ExactDepth &exact, const Eigen::Vector3d &origin, int pad_px);

}  // namespace projsurf::sim
