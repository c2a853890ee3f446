#include "colour_argument.hpp"

#include "argument_types.hpp"
#include "image_array.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"

namespace py = pybind11;

namespace projsurf::python {

std::vector<std::string> attachColourArgument(Cloud &cloud, const py::object &colour,
                                              const RegistrationOptions &options) {
    py::object keep;
    const cv::Mat bgr = matFromArray(arrayArgument(colour, "colour"), "colour", keep);
    return frontend::attachRegisteredColour(cloud, bgr, "colour", options).warnings;
}

cv::Mat overlayBackground(const Cloud &cloud, const py::object &colour, py::object &keep) {
    if (colour.is_none() || !cloud.hasColour()) return cv::Mat();
    return matFromArray(arrayArgument(colour, "colour"), "colour", keep);
}

}  // namespace projsurf::python
