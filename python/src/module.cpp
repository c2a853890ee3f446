// The Python module `projsurf`: a thin layer over the C++ library (python/README.md).
// Frames and units as everywhere in projsurf: camera optical frame (x right, y down,
// z forward), metres, radians except where a name says _deg.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <optional>

#include "argument_cast.hpp"
#include "detection_dict.hpp"
#include "detector_options.hpp"
#include "image_array.hpp"
#include "plan_function.hpp"
#include "points_array.hpp"
#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/detection/detector.hpp"
#include "projsurf/frontend/depth_image_cloud.hpp"
#include "projsurf/frontend/framebuffer_render.hpp"
#include "projsurf/io/cloud_io.hpp"
#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"
#include "projsurf/io/limits.hpp"
#include "projsurf/io/yaml_files.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/lens_model_check.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// The contract's projector, from keyword arguments with the example calibration's defaults.
Projector makeProjector(const py::object &resolution_arg, const py::object &fov_arg, const py::object &origin_arg,
                        const py::object &direction_arg) {
    const auto resolution = argumentAs<std::pair<int, int>>(resolution_arg, "resolution", "(width, height) in px");
    const auto fov_deg = argumentAs<std::pair<double, double>>(fov_arg, "fov_deg", "(horizontal, vertical) in deg");
    const auto origin = argumentAs<Eigen::Vector3d>(origin_arg, "origin", "three numbers (m)");
    const auto direction = argumentAs<Eigen::Vector3d>(direction_arg, "direction", "three numbers");
    Projector p;
    p.width = resolution.first;
    p.height = resolution.second;
    if (p.width < 2 || p.height < 2 || p.width > limits::kMaxFramebufferSide || p.height > limits::kMaxFramebufferSide)
        throw InputError("resolution", "must be two whole numbers between 2 and 16384");
    if (static_cast<std::uint64_t>(p.width) * p.height > limits::kMaxFramebufferPixels)
        throw InputError("resolution", "exceeds the limit of " + std::to_string(limits::kMaxFramebufferPixels) +
                                           " framebuffer pixels (as a calibration file)");
    if (!(fov_deg.first > 0 && fov_deg.first < 170 && fov_deg.second > 0 && fov_deg.second < 170))
        throw InputError("fov_deg", "angles must be between 0 and 170 degrees");
    p.fov_h = fov_deg.first * kDeg;
    p.fov_v = fov_deg.second * kDeg;
    if (!origin.allFinite()) throw InputError("origin", "is not finite");
    p.origin = origin;
    p.direction = direction.norm() > 0 ? direction.normalized() : direction;
    if (const std::string problem = lensModelProblem(p); !problem.empty()) throw InputError("Projector", problem);
    if (!isValidProjector(p))
        throw InputError("direction", "the axis must be finite, non-zero and not parallel to the camera's y axis");
    return p;
}

/// One picture -> framebuffer with a detection: what `projsurf correct` does for an image.
Keystone keystoneFor(const Projector &projector, const py::object &detection, cv::Size picture,
                     const py::object &tolerance) {
    const double tolerance_px = numberArgument(tolerance, "tolerance_px", "a number of px");
    const Rectangle rect = rectangleFromDetection(detection);
    frontend::FramebufferRender r = frontend::keystoneFor(projector, rect, picture, tolerance_px);
    if (!r.keystone) throw InputError(r.tolerance_refused ? "tolerance_px" : "detection", r.problem);
    return *r.keystone;
}

py::array corners2(const Corners2 &c) {
    py::array_t<double> a({4, 2});
    auto w = a.mutable_unchecked<2>();
    for (int i = 0; i < 4; ++i) w(i, 0) = c[i].x(), w(i, 1) = c[i].y();
    return a;
}

/// Registered colour into the cloud (surface suitability, issue 15); colour that the edge check
/// finds not registered is not used, with a UserWarning (the CLI's warning line).
void attachChecked(Cloud &cloud, const py::object &colour) {
    py::object keep;
    const cv::Mat bgr = matFromArray(colour.cast<py::array>(), "colour", keep);
    if (bgr.type() != CV_8UC3 || !cloud.organized() || bgr.cols != cloud.width || bgr.rows != cloud.height)
        throw InputError("colour", "must be an (H, W, 3) uint8 array (B, G, R) of the points' (H, W)");
    const RegistrationResult r = checkColourRegistration(cloud, bgr);
    if (r.checked && !r.registered) {
        const std::string message = "colour is not registered to the depth (" + r.summary() + "); not used";
        if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) < 0) throw py::error_already_set();
        return;
    }
    attachColour(cloud, bgr);
}

/// A detector for a stream of clouds: keeps the C++ SurfaceDetector (and its buffers).
class Detector {
public:
    Detector(const Projector &projector, DetectorOptions options)
        : options_(std::move(options)), detector_(projector, options_.config) {}

    py::dict detect(const py::object &points, const py::object &colour) {
        Cloud cloud = cloudFromPoints(points);
        if (!colour.is_none()) attachChecked(cloud, colour);
        Detection det;
        {
            py::gil_scoped_release unlocked;
            det = detector_.detect(cloud, gravityFor(options_, cloud));
        }
        frontend::enforceMinimumSize(det, options_.minimum, "min_width", "min_area");
        return detectionToDict(det, options_.config);
    }
    const Projector &projector() const { return detector_.projector(); }

private:
    DetectorOptions options_;
    SurfaceDetector detector_;
};

}  // namespace
}  // namespace projsurf::python

PYBIND11_MODULE(projsurf, m) {
    using namespace projsurf;
    using namespace projsurf::python;
    m.doc() =
        "projsurf: where a robot's projector can show a picture on a wall, and its keystone correction.\n"
        "Camera optical frame (x right, y down, z forward), metres; degrees only where a name says _deg.";

    // Same one-line messages as the CLI's "projsurf: error: <file>: <problem>" (without the prefix).
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

    py::class_<Projector>(m, "Projector",
                          "The contract's projector: a pinhole, principal point at the framebuffer centre, zero roll.")
        .def(py::init(&makeProjector), "resolution"_a = std::make_pair(1280, 800),
             "fov_deg"_a = std::make_pair(39.3, 24.0), "origin"_a = Eigen::Vector3d(0.0, 0.12, 0.0),
             "direction"_a = Eigen::Vector3d(0.0, -0.05, 1.0),
             "Defaults: the example calibration (examples/calib/example_calib.yaml).")
        .def_readonly("width", &Projector::width, "framebuffer width, px")
        .def_readonly("height", &Projector::height, "framebuffer height, px")
        .def_property_readonly(
            "fov_deg", [](const Projector &p) { return std::make_pair(p.fov_h / kDeg, p.fov_v / kDeg); },
            "full horizontal, vertical field of view, deg")
        .def_property_readonly(
            "origin", [](const Projector &p) { return p.origin; }, "lens centre, camera frame, m")
        .def_property_readonly(
            "direction", [](const Projector &p) { return p.direction; }, "central axis, unit")
        .def(
            "to_pixel", [](const Projector &p, const Eigen::Vector3d &point) { return p.toPixel(point); }, "point"_a,
            "framebuffer pixel (u, v) that lights a camera-frame point; None behind the lens")
        .def("__repr__", [](const Projector &p) {
            return py::str("Projector(resolution=({}, {}), fov_deg=({:.3f}, {:.3f}), origin={}, direction={})")
                .format(p.width, p.height, p.fov_h / kDeg, p.fov_v / kDeg,
                        py::str(py::cast(std::vector<double>{p.origin.x(), p.origin.y(), p.origin.z()})),
                        py::str(py::cast(std::vector<double>{p.direction.x(), p.direction.y(), p.direction.z()})));
        });

    m.def("read_calibration", &readCalibration, "path"_a,
          "Reads a calibration YAML (the contract's keys; others are ignored). Raises InputError.");
    m.def("write_calibration", &writeCalibration, "path"_a, "projector"_a,
          "Writes a calibration YAML with the contract's keys (atomically). Raises InputError.");
    m.def(
        "read_cloud", [](const std::string &path) { return arrayFromCloud(readCloud(path)); }, "path"_a,
        "Reads a PCD or PLY file: float32 (H, W, 3) when organized, else (N, 3). Raises InputError.");
    m.def(
        "read_depth_cloud",
        [](const std::string &depth_png, const std::string &camera_yaml) {
            return arrayFromCloud(readDepthCloud(depth_png, camera_yaml));
        },
        "depth_png"_a, "camera_yaml"_a,
        "A 16-bit depth PNG and the camera YAML as an organized (H, W, 3) float32 cloud. Raises InputError.");

    m.def(
        "depth_to_cloud",
        [](const py::object &depth, const py::object &fx, const py::object &fy, const py::object &cx,
           const py::object &cy, const py::object &depth_scale) {
            py::object keep;
            const cv::Mat d = matFromArray(argumentAs<py::array>(depth, "depth", "a numpy array"), "depth", keep);
            if (d.type() != CV_16UC1)
                throw InputError("depth", "expected an (H, W) uint16 depth image (0 = no reading)");
            const CameraIntrinsics camera = frontend::pinholeCamera(
                "camera", d.cols, d.rows, numberArgument(fx, "fx", "a number of px"),
                numberArgument(fy, "fy", "a number of px"), numberArgument(cx, "cx", "a number of px"),
                numberArgument(cy, "cy", "a number of px"),
                numberArgument(depth_scale, "depth_scale", "a number of units per metre"));
            return arrayFromCloud(frontend::depthImageToCloud("depth", d, camera));
        },
        "depth"_a, py::kw_only(), "fx"_a, "fy"_a, "cx"_a, "cy"_a, "depth_scale"_a = 1000.0,
        "An (H, W) uint16 depth image (depth_scale units per metre, 0 = no reading) and its pinhole\n"
        "(px) as an organized (H, W, 3) float32 cloud, NaN where there is no reading. Raises InputError.");
    m.def(
        "read_image",
        [](const py::object &path) {
            return arrayFromMat(readImage(textArgument(path, "path"), cv::IMREAD_UNCHANGED));
        },
        "path"_a, "Reads an image file as OpenCV does (channels in B, G, R order; 8 or 16 bits). Raises InputError.");
    m.def(
        "write_image",
        [](const py::object &path, const py::object &image) {
            py::object keep;
            writeImageAtomic(textArgument(path, "path"),
                             matFromArray(argumentAs<py::array>(image, "image", "a numpy array"), "image", keep));
        },
        "path"_a, "image"_a,
        "Writes an image by the path's extension (channels taken as B, G, R), atomically. Raises InputError.");

    py::class_<Detector>(m, "Detector", "Detection over a stream of clouds (reuses its buffers from frame to frame).")
        .def(py::init([](const py::object &projector, const py::object &aspect, const py::object &gravity,
                         const py::object &method, const py::object &hull, const py::object &seed,
                         const py::object &min_width, const py::object &min_area) {
                 return Detector(projectorArgument(projector),
                                 detectorOptions(aspect, gravity, textArgument(method, "method"),
                                                 textArgument(hull, "hull"), seedArgument(seed), min_width, min_area));
             }),
             "projector"_a, py::kw_only(), "aspect"_a = py::none(), "gravity"_a = py::none(), "method"_a = "default",
             "hull"_a = "concave", "seed"_a = 42u, "min_width"_a = py::none(), "min_area"_a = py::none())
        .def("detect", &Detector::detect, "points"_a, py::kw_only(), "colour"_a = py::none(),
             "points: (H, W, 3) or (N, 3) array (camera frame, m; NaN = no reading) or an object with .points.\n"
             "colour: optional (H, W, 3) uint8 B, G, R image registered to (H, W) points: the surface's suitability\n"
             "(docs/suitability.md); not used, with a UserWarning, when its edges do not fit the depth's.\n"
             "Returns the detection as a dict with the keys of the detection JSON.")
        .def_property_readonly("projector", &Detector::projector);

    m.def(
        "detect",
        [](const py::object &points, const py::object &projector, const py::object &aspect, const py::object &gravity,
           const py::object &method, const py::object &hull, const py::object &seed, const py::object &min_width,
           const py::object &min_area, const py::object &colour) {
            Detector detector(projectorArgument(projector),
                              detectorOptions(aspect, gravity, textArgument(method, "method"),
                                              textArgument(hull, "hull"), seedArgument(seed), min_width, min_area));
            return detector.detect(points, colour);
        },
        "points"_a, "projector"_a, py::kw_only(), "aspect"_a = py::none(), "gravity"_a = py::none(),
        "method"_a = "default", "hull"_a = "concave", "seed"_a = 42u, "min_width"_a = py::none(),
        "min_area"_a = py::none(), "colour"_a = py::none(),
        "The biggest upright rectangle of the aspect ratio (None: the framebuffer's, a number, or 'W:H') that the\n"
        "projector can light on a vertical surface. gravity: camera frame, pointing down (None: a level camera\n"
        "[0, 1, 0]; 'auto': from the floor). min_width (m), min_area (m^2): smaller rectangles are not found\n"
        "(None: 0.15 m and 0.012 m^2, as `projsurf detect`; 0 with method='paper'). Returns a dict: found, reason, "
        "method, plane, rectangle,\n"
        "surface_check, timing_ms, gravity (numpy arrays for vectors). Raises InputError for bad points or options.");

    m.def(
        "keystone",
        [](const py::object &projector, const py::object &detection, const py::object &size,
           const py::object &tolerance_px) {
            const auto picture_size = argumentAs<std::pair<int, int>>(size, "picture_size", "(width, height) in px");
            const Keystone k = keystoneFor(projectorArgument(projector), detection,
                                           {picture_size.first, picture_size.second}, tolerance_px);
            Eigen::Matrix3d h;
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) h(r, c) = k.homography(r, c);
            return py::dict("homography"_a = h, "rectangle_px"_a = corners2(k.rectangle_px),
                            "picture_px"_a = corners2(k.picture_px),
                            "framebuffer_size"_a = std::make_pair(k.framebuffer.width, k.framebuffer.height));
        },
        "projector"_a, "detection"_a, "picture_size"_a, "tolerance_px"_a = kKeystoneTolerancePx,
        "picture_size: (width, height) px. homography maps picture pixels to framebuffer pixels (centres at\n"
        "integers); rectangle_px / picture_px: (4, 2) framebuffer positions (TL, TR, BR, BL). Raises InputError\n"
        "when the detection found nothing or its rectangle cannot be shown.");

    m.def(
        "correct",
        [](const py::object &image, const py::object &projector, const py::object &detection,
           const py::object &tolerance_px) {
            py::object keep;
            const cv::Mat picture = matFromArray(argumentAs<py::array>(image, "image", "a numpy array"), "image", keep);
            const Keystone k = keystoneFor(projectorArgument(projector), detection, picture.size(), tolerance_px);
            cv::Mat framebuffer;
            {
                py::gil_scoped_release unlocked;
                framebuffer = warpToFramebuffer(picture, k);
            }
            return arrayFromMat(framebuffer);
        },
        "image"_a, "projector"_a, "detection"_a, "tolerance_px"_a = kKeystoneTolerancePx,
        "Keystone correction: the projector framebuffer (the calibration's resolution, black around) showing\n"
        "`image` ((H, W) or (H, W, C), uint8, uint16 or float32; channels kept in their order) whole and\n"
        "undistorted in the detected rectangle (letterboxed, never stretched). The image is read in place.\n"
        "detection: the dict of detect(), or (4, 3) corners. Raises InputError.");

    addPlanFunction(m);

    m.attr("__version__") = PROJSURF_VERSION;
}
