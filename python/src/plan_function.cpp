#include "plan_function.hpp"

#include <pybind11/stl.h>

#include "argument_types.hpp"
#include "colour_argument.hpp"
#include "detector_options.hpp"
#include "image_array.hpp"
#include "json_values.hpp"
#include "points_array.hpp"
#include "projsurf/frontend/answer/detect_answer.hpp"
#include "projsurf/frontend/answer/plan_json.hpp"
#include "projsurf/frontend/render/plan_overlay.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/planning/stand_planner.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {

void addPlanFunction(py::module_ &m) {
    m.def(
        "plan",
        [](const py::object &points, const py::object &projector_arg, const py::object &aspect,
           const py::object &gravity, const py::object &width_arg, const py::object &max_move_arg,
           const py::object &min_width, const py::object &min_area, const py::object &config, const py::object &colour,
           const py::object &overlay) {
            if (!py::isinstance<py::bool_>(overlay)) throw InputError("overlay", "must be True or False");
            const bool want_overlay = overlay.cast<bool>();
            const Projector &projector = projectorArgument(projector_arg, "projector");
            const double width = numberArgument(width_arg, "width"),
                         max_move = numberArgument(max_move_arg, "max_move");
            if (!(width >= 0.0 && width <= 50.0)) throw InputError("width", "must be between 0 and 50 m");
            if (!(max_move >= 0.0 && max_move <= 10.0)) throw InputError("max_move", "must be between 0 and 10 m");
            const DetectorOptions options = detectorOptions({aspect, gravity, py::none(), py::none(), py::none(),
                                                             min_width, min_area, py::none(), config, py::dict()});
            Cloud cloud = cloudFromPoints(points);
            std::vector<std::string> warnings;
            if (!colour.is_none()) warnings = attachColourArgument(cloud, colour, options.config.suitability.registration);
            py::object keep;
            const cv::Mat background = want_overlay ? overlayBackground(cloud, colour, keep) : cv::Mat();
            PlanOptions plan;
            plan.width = width;
            plan.max_move = max_move;
            nlohmann::json answer;
            cv::Mat picture;
            {
                py::gil_scoped_release unlocked;
                // Today's answer is detect()'s, by the same call.
                SurfaceDetector detector(projector, options.config);
                const CheckedDetection input = detectChecked(detector, options, cloud);
                warnings.insert(warnings.end(), input.warnings.begin(), input.warnings.end());
                const Eigen::Vector3d &down = input.gravity;
                const Detection &today = input.detection;
                const PlanResult r = planStand(cloud, projector, options.config, down, plan, today);
                answer = frontend::planToJson(r);
                if (want_overlay)
                    picture = renderPlanOverlay(cloud, r, options.config, nullptr, down, plan.robot_radius, background);
            }
            warnAll(warnings);
            py::object d = pythonFromJson(answer);
            if (!picture.empty()) d["overlay"] = arrayFromMat(picture);
            return d;
        },
        "points"_a, "projector"_a, py::kw_only(), "aspect"_a = py::none(), "gravity"_a = py::none(), "width"_a = 0.0,
        "max_move"_a = 2.0, "min_width"_a = py::none(), "min_area"_a = py::none(), "config"_a = py::none(),
        "colour"_a = py::none(), "overlay"_a = false,
        "Where the robot should stand for the largest picture (width > 0: the shortest move showing at least\n"
        "that width, m), moving at most max_move m on the floor. points, projector, aspect, gravity, min_width,\n"
        "min_area, config, colour as for detect() (colour: `plan --rgb`). Returns the dict of\n"
        "`projsurf plan --json`: found, reason, camera_pose\n"
        "(rotation, translation: P_today = R P_moved + t), predicted, move (forward_m, left_m, turn_left_deg,\n"
        "words: the gravity-levelled robot frame), today (detect()'s rectangle where the robot stands, or None),\n"
        "today_reason, limit, search; with overlay=True also overlay, `plan --overlay`'s picture ((H, W, 3) uint8\n"
        "B, G, R). Raises InputError for bad points or options.");
}

}  // namespace projsurf::python
