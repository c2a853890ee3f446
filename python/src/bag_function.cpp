#include "bag_function.hpp"

#include "argument_types.hpp"
#include "detector_options.hpp"
#include "points_array.hpp"
#include "projsurf/frontend/inputs/bag_frames.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {

void addBagFunction(py::module_ &m) {
    m.def(
        "read_bag",
        [](const py::object &path, const py::object &topic, const py::object &camera_info_topic) {
            frontend::BagRequest request;
            request.bag = pathArgument(path, "path");
            if (!topic.is_none()) request.topic = wordArgument(topic, "topic");
            if (!camera_info_topic.is_none()) request.info_topic = wordArgument(camera_info_topic, "camera_info_topic");
            request.topic_option = "topic=";
            request.info_option = "camera_info_topic=";
            py::list frames;
            const frontend::BagFrames read = frontend::forEachBagFrame(
                request, [&](const Cloud &cloud, const BagCloudInfo &info, const std::string &t) {
                    frames.append(py::dict("points"_a = arrayFromCloud(cloud), "index"_a = info.index,
                                           "stamp"_a = info.stamp, "frame_id"_a = info.frame_id, "topic"_a = t));
                });
            if (!read.warning.empty()) warnAll({read.warning});
            return frames;
        },
        "path"_a, py::kw_only(), "topic"_a = py::none(), "camera_info_topic"_a = py::none(),
        "The clouds of a ROS 1 bag's topic, in bag time order, as `projsurf detect --bag --topic\n"
        "--camera-info-topic` reads them: a list of dicts, points ((H, W, 3) or (N, 3) float32, camera frame,\n"
        "m), index, stamp (s), frame_id, topic; detect() or Detector.detect() takes each one's points. topic:\n"
        "None for the bag's one PointCloud2 or depth Image topic; a depth Image (16UC1 mm or 32FC1 m) goes\n"
        "with the camera_info of its stamp on camera_info_topic (None: the one beside it, or the bag's only\n"
        "one); a depth image without one of its stamp takes the nearest, with a UserWarning. Every cloud is\n"
        "held in memory at once. Raises InputError.");
}

}  // namespace projsurf::python
