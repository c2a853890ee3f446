#pragma once
// What the depth camera sees just beyond the edges of a vertical face, and whether the face
// stands free in the room: furniture, a box or a person is bounded by open space (the camera
// sees past the face's plane above it and beside it), while a wall meets a ceiling, another
// wall or the edge of the view, all in front of its plane or beyond the image.
#include <Eigen/Core>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// The readings looked at beyond one edge of a face, one per position along it.
struct EdgeView {
    int past = 0;    ///< the ray beyond the edge ends behind the face's plane: open space there
    int front = 0;   ///< it ends in front of the plane (a ceiling, a wall at a corner, an obstacle)
    int on = 0;      ///< on the plane: the face goes on (or a surface in line with it)
    int unseen = 0;  ///< beyond the image, behind the camera, or no reading
    int seen() const { return past + front + on; }
    int positions() const { return seen() + unseen; }
    /// Of the positions that tell open space from a bounding surface (past or front), the share open.
    double pastShare() const { return past + front > 0 ? static_cast<double>(past) / (past + front) : 0.0; }
};

struct FaceSurround {
    EdgeView top, left, right;         ///< as seen facing the face (left and right on the viewer's side)
    double width = 0.0, height = 0.0;  ///< m, the face's size: the median unbroken stretch per row / column
};

/// What the camera sees beyond the top, left and right edges of the face made of `points`
/// (indices into the organized `cloud`) on the plane of the upright `frame`. `camera` maps the
/// cloud's points to their pixels.
FaceSurround faceSurround(const Cloud &cloud, const CameraIntrinsics &camera, const PlaneFrame &frame,
                          const std::vector<int> &points, const DepthTolerance &tolerance,
                          const FaceSurroundOptions &options = {});

/// A face stands free (an object on the scene, not a wall) when the camera sees past its plane
/// above its top edge and beside at least one side: bounded by open space, not by a ceiling,
/// walls or the view's border. Built-in fronts running to the ceiling or wall to wall do not,
/// nor does a face of a wall's size (FreeStandingRule::wall_height, wall_width).
bool standsFree(const FaceSurround &surround, const FreeStandingRule &rule = {});

/// The face's top is open (the camera sees past its plane above it), and it is no wall-sized
/// face: with a wall seen behind it (the caller checks), an object standing before that wall
/// (a bin, a sofa's front between its arms, a cabinet below a counter).
bool openAbove(const FaceSurround &surround, const FreeStandingRule &rule = {});

/// The face is bounded in front of its plane above it and on both sides (a recess, or what is
/// seen through a window or a door): each edge seen as FreeStandingRule::min_seen asks, and
/// open behind on at most 1 - min_past of it.
bool enclosedInFront(const FaceSurround &surround, const FreeStandingRule &rule = {});

}  // namespace projsurf
