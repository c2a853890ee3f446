#include "tracker_class.hpp"

#include <utility>

#include "argument_types.hpp"
#include "camera_pose.hpp"
#include "detection_dict.hpp"
#include "detector_options.hpp"
#include "options_constructor.hpp"
#include "points_array.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/tracking/continuous_tracker.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {

namespace {

/// A detector and a steady tracker over a stream of clouds: each update detects as detect()
/// does and says what to show so that the picture stays put.
class Tracker {
public:
    Tracker(const Projector &projector, DetectorOptions options)
        : options_(std::move(options)),
          detector_(projector, options_.config),
          steady_(continuousSettings(projector, options_.config)) {}

    py::dict update(const py::object &points, const py::object &camera_pose) {
        const Cloud cloud = cloudFromPoints(points);
        const Eigen::Isometry3d fixed_from_camera = cameraPoseArgument(camera_pose, "camera_pose");
        CheckedDetection input;
        ContinuousFrame frame;
        {
            py::gil_scoped_release unlocked;
            input = detectChecked(detector_, options_, cloud, !gravity_checked_);
            gravity_checked_ = true;
            frame = steady_.update(input.detection, cloud, fixed_from_camera);
        }
        warnAll(input.warnings);
        return continuousFrameToDict(input.detection, frame, options_.config, detector_.projector());
    }
    void reset() { steady_.reset(); }
    const Projector &projector() const { return detector_.projector(); }

private:
    DetectorOptions options_;
    SurfaceDetector detector_;
    ContinuousTracker steady_;
    bool gravity_checked_ = false;  ///< the gravity was checked against the first cloud's floor
};

}  // namespace

void addTrackerClass(py::module_ &m, const std::string &options_doc) {
    py::class_<Tracker> tracker_class(
        m, "Tracker",
        ("Continuous mode, as the ROS node's ~continuous: detects on each cloud given to update() and keeps\n"
         "the picture put on the wall (it moves only when the held place cannot be shown or another wins\n"
         "for several frames in a row). The detector options are Detector's:\n" +
         options_doc)
            .c_str());
    addOptionsConstructor(tracker_class);
    tracker_class
        .def(
            "update",
            [](Tracker &t, const py::object &points, const py::object &camera_pose, const py::kwargs &extra) {
                // Settings belong to the Tracker; a keyword here is a mistake, said in one line.
                for (const auto &item : extra)
                    throw InputError(py::str(item.first).cast<std::string>(),
                                     "unknown keyword argument (Tracker.update takes points and camera_pose=; the "
                                     "settings go to Tracker(...))");
                return t.update(points, camera_pose);
            },
            "points"_a, "camera_pose"_a = py::none(),
            "points: as for detect(). camera_pose: None (a robot standing still) or a 4x4 array, the camera's\n"
            "pose in a frame that does not move with the robot (odom, map: P_fixed = T P_camera), at the\n"
            "time of the cloud. Returns detect()'s dict for this cloud plus shown (the rectangle to show,\n"
            "in this cloud's camera frame, as `rectangle`; None when nothing is held) and event (what\n"
            "happened: 'none', 'acquired', 'kept', 'moved', 'switched', 'held' or 'lost'). Raises\n"
            "InputError for bad points or a camera_pose that is not a rigid transform.")
        .def("reset", &Tracker::reset, "Forget the held picture: the next found rectangle is taken at once.")
        .def_property_readonly("projector", &Tracker::projector);
}

}  // namespace projsurf::python
