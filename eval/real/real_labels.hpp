#pragma once
// Hand-made labels of a real RGB-D frame (labels/real/<half>/<frame>.yaml): the gravity and the
// virtual projector to test it with, the surfaces a projector could use and the obstacles on
// them as polygons in depth-image pixels, and the reference best rectangle.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::eval {

/// A simple polygon in depth-image pixel coordinates (x right, y down; pixel centres are
/// whole numbers, as in CameraIntrinsics::backProject).
struct LabelPolygon {
    std::string name;
    std::vector<Eigen::Vector2d> pixels;
};

/// One flat vertical surface: the union of its polygons is where a picture may go.
struct LabelSurface {
    std::string name;
    std::vector<LabelPolygon> regions;
    bool has_plane = false;  ///< plane fitted by the reference (stored for checking)
    Plane plane;             ///< camera frame, m
};

/// The reference's best upright rectangle for the label's projector and gravity.
struct LabelBest {
    bool found = false;
    std::string surface;                       ///< name of the surface it lies on
    double width = 0, height = 0;              ///< m
    std::array<Eigen::Vector3d, 4> corners{};  ///< camera frame, TL, TR, BR, BL facing the wall
    double area() const { return width * height; }
};

/// Something depth calls free that the picture should not be shown on, judged on the registered
/// colour: a framed print, a poster, a screen, a window, a dark panel, a glare spot.
struct LabelUnsuitable {
    LabelPolygon polygon;  ///< depth-image pixels, as the obstacles
    std::string why;  ///< "textured", "dark", "saturated" or "glare" (detection/colour/surface_suitability's Unfit)
};

/// The optional `colour:` section (frames with a registered rgb.png): judged = the section is
/// there (an empty list then means "looked at, nothing unsuitable").
struct LabelColour {
    bool judged = false;
    std::string note;  ///< what was judged on the colour image, and why
    std::vector<LabelUnsuitable> unsuitable;
    LabelBest best;  ///< the reference with the unsuitable polygons as further obstacles
};

struct RealLabel {
    std::string frame;                 ///< folder name under the real-frame directory
    std::string note;                  ///< what was judged and why
    /// "tune" or "check" (labels/README.md, "The two halves"): a detection change is chosen on the
    /// tune half and kept only if the check half does not get worse. Empty: not assigned.
    std::string split;
    /// The scene or recorded sequence the frame comes from ("7scenes/redkitchen"): every frame of
    /// one scene is on the same side of the split. Empty: not stated.
    std::string scene;
    /// The depth sensor's family: "structured_light" (Kinect v1, Xtion, Structure), "time_of_flight"
    /// (Kinect v2, Azure Kinect) or "stereo" (RealSense D4xx). Empty: not stated.
    std::string sensor;
    std::string gravity_source;        ///< "auto" (the floor, as --gravity auto) or "stated"
    Eigen::Vector3d gravity{0, 1, 0};  ///< unit, camera frame, down
    /// Gravity from a source independent of the detector (labels/floor_gravity.py): "floor_fit"
    /// (the floor fitted by that script), "walls" (two labelled walls' normals), empty: none.
    std::string reference_gravity_source;
    Eigen::Vector3d reference_gravity{0, 1, 0};  ///< unit, camera frame, down
    Projector projector;                         ///< `projector:` block in the calibration file's format
    std::vector<LabelSurface> surfaces;          ///< empty: no usable wall in this frame
    std::vector<LabelPolygon> obstacles;         ///< in front of / proud of the surfaces, or no reading
    LabelBest best;
    LabelColour colour;  ///< not judged when the file has no `colour:` section
};

/// The sides a label's `split` may name: "tune" and "check".
const std::vector<std::string> &splitSides();
/// The families a label's `sensor` may name.
const std::vector<std::string> &sensorFamilies();

/// The reasons a `colour.unsuitable[].why` may give.
const std::vector<std::string> &unsuitableReasons();

/// Reads a label file; throws InputError naming the file and the key on any problem.
RealLabel readRealLabel(const std::string &path);
/// Writes a label file (atomically) that readRealLabel reads back unchanged.
void writeRealLabel(const std::string &path, const RealLabel &label);
/// The label files (*.yaml) of a directory and of its sub-folders one level down (tune/, check/),
/// sorted by file name; empty when it is not a directory.
std::vector<std::string> listLabelFiles(const std::string &dir);

}  // namespace projsurf::eval
