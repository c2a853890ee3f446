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

#include "argument_errors.hpp"
#include "argument_types.hpp"
#include "bag_function.hpp"
#include "colour_argument.hpp"
#include "detection_dict.hpp"
#include "detector_options.hpp"
#include "image_array.hpp"
#include "options_constructor.hpp"
#include "plan_function.hpp"
#include "points_array.hpp"
#include "print_config_function.hpp"
#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/inputs/depth_image_cloud.hpp"
#include "projsurf/frontend/inputs/registered_colour.hpp"
#include "projsurf/frontend/render/framebuffer_render.hpp"
#include "projsurf/frontend/render/overlay.hpp"
#include "projsurf/frontend/render/rectangle_blanking.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/utf8_text.hpp"
#include "projsurf/io/formats/cloud_io.hpp"
#include "projsurf/io/yaml/yaml_files.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/people/beam_blanking.hpp"
#include "projsurf/sim/scenes/scenarios.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/lens_model_check.hpp"
#include "tracker_class.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace projsurf::python {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// depth_to_cloud's depth: an (H, W) uint16 array, one message for every other kind.
py::array depthArgument(const py::object &depth) {
    const py::array a = arrayArgument(depth, "depth");
    if (a.ndim() != 2 || a.dtype().kind() != 'u' || a.itemsize() != 2) {
        std::string shape;
        for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
        throw InputError("depth",
                         "expected an (H, W) uint16 depth image (depth_scale units per metre, 0 = no "
                         "reading), got a (" +
                             shape + (a.ndim() == 1 ? "," : "") + ") " +
                             py::str(py::handle(a.dtype())).cast<std::string>() + " array");
    }
    return a;
}

/// A depth given as (W, H), which numpy's (H, W) order makes easy: the principal point lies near
/// the centre of the transposed image and well off the centre of this one. Why, or "".
std::string transposedDepthProblem(int rows, int cols, double cx, double cy) {
    auto off = [](double c, int size) { return std::abs(c - 0.5 * (size - 1)) / size; };
    const double here = std::max(off(cx, cols), off(cy, rows)), swapped = std::max(off(cx, rows), off(cy, cols));
    if (rows == cols || !(here > 0.1 && swapped < 0.05)) return "";
    return "is (" + std::to_string(rows) + ", " + std::to_string(cols) + "): " + std::to_string(cols) + " wide, " +
           std::to_string(rows) + " high, but cx and cy lie at the centre of a " + std::to_string(rows) + " x " +
           std::to_string(cols) + " image: transposed? numpy images are (H, W), depth.T undoes it";
}

/// An angle in degrees to 1e-3 deg, as a calibration file states it (39.3, not 39.300000000000004).
double wholeMilliDegrees(double radians) { return std::round(radians / kDeg * 1000.0) / 1000.0; }

/// The contract's projector, from keyword arguments with the example calibration's defaults.
Projector makeProjector(const py::object &resolution, const py::object &fov_deg, const py::object &origin,
                        const py::object &direction) {
    const std::pair<double, double> size = pairArgument(resolution, "resolution");
    const std::pair<double, double> fov = pairArgument(fov_deg, "fov_deg");
    Projector p;
    constexpr double kSide = limits::kMaxFramebufferSide;
    if (!(size.first >= 2 && size.second >= 2 && size.first <= kSide && size.second <= kSide &&
          size.first == std::floor(size.first) && size.second == std::floor(size.second)))
        throw InputError("resolution",
                         "must be two whole numbers between 2 and " + std::to_string(limits::kMaxFramebufferSide));
    p.width = static_cast<int>(size.first);
    p.height = static_cast<int>(size.second);
    if (static_cast<std::uint64_t>(p.width) * p.height > limits::kMaxFramebufferPixels)
        throw InputError("resolution", "exceeds the limit of " + std::to_string(limits::kMaxFramebufferPixels) +
                                           " framebuffer pixels (as a calibration file)");
    if (!(fov.first > 0 && fov.first < kMaxLensFovDeg && fov.second > 0 && fov.second < kMaxLensFovDeg))
        throw InputError("fov_deg", "angles must be between 0 and " + std::to_string(int(kMaxLensFovDeg)) + " degrees");
    p.fov_h = fov.first * kDeg;
    p.fov_v = fov.second * kDeg;
    p.origin = vectorArgument(origin, "origin");
    if (!p.origin.allFinite()) throw InputError("origin", "is not finite");
    const Eigen::Vector3d axis = vectorArgument(direction, "direction");
    p.direction = axis.norm() > 0 ? axis.normalized() : axis;
    if (const std::string problem = lensModelProblem(p); !problem.empty()) throw InputError("Projector", problem);
    if (!isValidProjector(p))
        throw InputError("direction", "the axis must be finite, non-zero and not parallel to the camera's y axis");
    return p;
}

/// One picture -> framebuffer with a detection: what `projsurf correct` does for an image.
Keystone keystoneFor(const Projector &projector, const py::object &detection, cv::Size picture,
                     const py::object &tolerance) {
    const double tolerance_px = numberArgument(tolerance, "tolerance_px");
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

/// A detector for a stream of clouds: keeps the C++ SurfaceDetector (and its buffers).
class Detector {
public:
    Detector(const Projector &projector, DetectorOptions options)
        : options_(std::move(options)), detector_(projector, options_.config) {}

    py::dict detect(const py::object &points, const py::object &colour, const py::object &explain,
                    const py::object &overlay) {
        if (!py::isinstance<py::bool_>(explain)) throw InputError("explain", "must be True or False");
        if (!py::isinstance<py::bool_>(overlay)) throw InputError("overlay", "must be True or False");
        Cloud cloud = cloudFromPoints(points);
        std::vector<std::string> warnings;
        if (!colour.is_none()) warnings = attachColourArgument(cloud, colour, options_.config.suitability.registration);
        Detection det;
        {
            py::gil_scoped_release unlocked;
            CheckedDetection input = detectChecked(detector_, options_, cloud, !gravity_checked_);
            gravity_checked_ = true;
            warnings.insert(warnings.end(), input.warnings.begin(), input.warnings.end());
            det = std::move(input.detection);
        }
        warnAll(warnings);
        py::dict d = detectionToDict(det, options_.config, detector_.projector(), explain.cast<bool>());
        if (overlay.cast<bool>()) {  // `detect --overlay`'s picture, colour as its background when it was used
            py::object keep;
            const cv::Mat bgr = overlayBackground(cloud, colour, keep);
            d["overlay"] = arrayFromMat(renderOverlay(cloud, det, options_.config, nullptr, bgr, explain.cast<bool>()));
        }
        return d;
    }
    const Projector &projector() const { return detector_.projector(); }

private:
    DetectorOptions options_;
    SurfaceDetector detector_;
    bool gravity_checked_ = false;  ///< the gravity was checked against the first cloud's floor
};

/// projsurf.InputError (a ValueError): the same one-line messages as the CLI's "projsurf: error: <file>:
/// <problem>" (without the prefix), as UTF-8 on one line whatever file bytes they quote.
void bindInputError(py::module_ &m) {
    static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError &e) {
            std::string text = utf8Escaped(e.what());
            for (std::size_t i; (i = text.find_first_of("\r\n")) != std::string::npos;) text.replace(i, 1, "; ");
            PyErr_SetString(input_error.ptr(), text.c_str());
        }
    });
}

/// Projector: the lens model, built from keywords or read from a calibration.
void bindProjector(py::module_ &m) {
    const Projector example = sim::exampleProjector();  // the keywords' defaults: the example calibration
    py::class_<Projector>(
        m, "Projector",
        "The projector's lens model (docs/interface.md). Projector(...) builds the contract's plain model:\n"
        "a pinhole whose principal point is the framebuffer centre, focal lengths from fov_deg, zero roll.\n"
        "read_calibration() may give the full model: intrinsics (fx, fy, cx, cy in framebuffer px; the\n"
        "principal point is then anywhere, on or beyond the framebuffer's edge for a lens offset), OpenCV\n"
        "distortion (k1, k2, p1, p2, k3) and a rotation of any roll; every function uses all of it.")
        .def(py::init(&makeProjector), "resolution"_a = py::make_tuple(example.width, example.height),
             "fov_deg"_a = py::make_tuple(wholeMilliDegrees(example.fov_h), wholeMilliDegrees(example.fov_v)),
             "origin"_a = py::make_tuple(example.origin.x(), example.origin.y(), example.origin.z()),
             "direction"_a = py::make_tuple(example.direction.x(), example.direction.y(), example.direction.z()),
             "resolution: (width, height) px; fov_deg: full (horizontal, vertical) field of view, deg; origin:\n"
             "lens centre, camera frame, m; direction: central axis (any length). Defaults: the example\n"
             "calibration (examples/calib/example_calib.yaml). Raises InputError.")
        .def_readonly("width", &Projector::width, "framebuffer width, px")
        .def_readonly("height", &Projector::height, "framebuffer height, px")
        .def_property_readonly(
            "fov_deg", [](const Projector &p) { return std::make_pair(p.fov_h / kDeg, p.fov_v / kDeg); },
            "full horizontal, vertical field of view, deg (the calibration's; informative when intrinsics are set)")
        .def_property_readonly(
            "origin", [](const Projector &p) { return p.origin; }, "lens centre, camera frame, m")
        .def_property_readonly(
            "direction", [](const Projector &p) { return p.direction; }, "central (optical) axis, unit")
        .def_property_readonly(
            "intrinsics", [](const Projector &p) { return py::make_tuple(p.fx(), p.fy(), p.cx(), p.cy()); },
            "(fx, fy, cx, cy), framebuffer px, pixel centres at integers: the calibration's intrinsics, or\n"
            "those of the plain model (principal point at the centre, focal lengths from fov_deg)")
        .def_property_readonly(
            "distortion",
            [](const Projector &p) {
                return py::make_tuple(p.distortion[0], p.distortion[1], p.distortion[2], p.distortion[3],
                                      p.distortion[4]);
            },
            "OpenCV k1, k2, p1, p2, k3 on normalised projector coordinates (all zero: none)")
        .def_property_readonly(
            "rotation",
            [](const Projector &p) -> Eigen::Matrix3d {
                Eigen::Matrix3d r;
                r << p.right(), p.down(), p.axis();
                return r;
            },
            "3x3, columns = image right, image down, optical axis in the camera frame (zero roll without a\n"
            "calibrated rotation)")
        .def_property_readonly("full_model", &Projector::fullModel,
                               "True when the calibration set intrinsics, distortion or a rotation")
        .def(
            "to_pixel",
            [](const Projector &p, const py::object &point) { return p.toPixel(vectorArgument(point, "point")); },
            "point"_a,
            "framebuffer pixel (u, v) that lights a camera-frame point (full model, distortion included);\n"
            "None behind the lens")
        .def("__repr__", [](const Projector &p) {
            return py::str("Projector(resolution=({}, {}), fov_deg=({:.3f}, {:.3f}), origin={}, direction={}{})")
                .format(p.width, p.height, p.fov_h / kDeg, p.fov_v / kDeg,
                        py::str(py::cast(std::vector<double>{p.origin.x(), p.origin.y(), p.origin.z()})),
                        py::str(py::cast(std::vector<double>{p.direction.x(), p.direction.y(), p.direction.z()})),
                        p.fullModel() ? ", full model" : "");
        });
}

/// read_calibration and write_calibration.
void bindCalibrationFiles(py::module_ &m) {
    m.def(
        "read_calibration",
        [](const py::object &path) {
            std::vector<std::string> warnings;  // unknown keys under projector: (a typo), as the CLI warns
            Projector projector = readCalibration(pathArgument(path, "path"), &warnings);
            warnAll(warnings);
            return projector;
        },
        "path"_a,
        "Reads a calibration YAML (docs/interface.md): projector.resolution, fov_deg and axis (origin,\n"
        "direction), and the full model's optional intrinsics, distortion and rotation when present.\n"
        "Other keys (calibrate's fit report) are not read; an unknown key under projector: (a typo)\n"
        "gives a UserWarning. Raises InputError.");
    m.def(
        "write_calibration",
        [](const py::object &path, const py::object &projector) {
            writeCalibration(pathArgument(path, "path"), projectorArgument(projector, "projector"));
        },
        "path"_a, "projector"_a,
        "Writes a calibration YAML with the contract's keys, the full model's too when set (atomically).\n"
        "Raises InputError.");
}

/// Clouds from files and from a depth image: read_cloud, read_depth_cloud, depth_to_cloud.
void bindCloudFunctions(py::module_ &m) {
    m.def(
        "read_cloud", [](const py::object &path) { return arrayFromCloud(readCloud(pathArgument(path, "path"))); },
        "path"_a, "Reads a PCD or PLY file: float32 (H, W, 3) when organized, else (N, 3). Raises InputError.");
    m.def(
        "read_depth_cloud",
        [](const py::object &depth_png, const py::object &camera_yaml) {
            const std::string camera = pathArgument(camera_yaml, "camera_yaml");
            std::vector<std::string> warnings;  // unknown keys (a typo), as `detect --camera` warns
            readCamera(camera, &warnings);
            Cloud cloud = readDepthCloud(pathArgument(depth_png, "depth_png"), camera);
            warnAll(warnings);
            return arrayFromCloud(std::move(cloud));
        },
        "depth_png"_a, "camera_yaml"_a,
        "A 16-bit depth PNG and the camera YAML (projsurf's camera: block or a ROS camera_info YAML) as an\n"
        "organized (H, W, 3) float32 cloud. Unknown keys in the camera YAML (a typo) are a UserWarning, as\n"
        "`projsurf detect --camera` warns. Raises InputError.");

    m.def(
        "depth_to_cloud",
        [](const py::object &depth, const py::object &fx, const py::object &fy, const py::object &cx,
           const py::object &cy, const py::object &depth_scale) {
            py::object keep;
            const cv::Mat d = matFromArray(depthArgument(depth), "depth", keep);
            const CameraIntrinsics camera = frontend::pinholeCamera(
                "camera", d.cols, d.rows, numberArgument(fx, "fx"), numberArgument(fy, "fy"), numberArgument(cx, "cx"),
                numberArgument(cy, "cy"), numberArgument(depth_scale, "depth_scale"));
            if (const std::string problem = transposedDepthProblem(d.rows, d.cols, camera.cx, camera.cy);
                !problem.empty())
                throw InputError("depth", problem);
            return arrayFromCloud(frontend::depthImageToCloud("depth", d, camera));
        },
        "depth"_a, py::kw_only(), "fx"_a, "fy"_a, "cx"_a, "cy"_a, "depth_scale"_a = 1000.0,
        "An (H, W) uint16 depth image (depth_scale units per metre, 0 = no reading) and its pinhole\n"
        "(px) as an organized (H, W, 3) float32 cloud, NaN where there is no reading. Raises InputError.");
}

/// read_image and write_image.
void bindImageFiles(py::module_ &m) {
    m.def(
        "read_image",
        [](const py::object &path) {
            return arrayFromMat(readImage(pathArgument(path, "path"), cv::IMREAD_UNCHANGED));
        },
        "path"_a, "Reads an image file as OpenCV does (channels in B, G, R order; 8 or 16 bits). Raises InputError.");
    m.def(
        "write_image",
        [](const py::object &path, const py::object &image) {
            py::object keep;
            const std::string file = pathArgument(path, "path");
            writeImageAtomic(file, matFromArray(arrayArgument(image, "image"), "image", keep));
        },
        "path"_a, "image"_a,
        "Writes an image by the path's extension (channels taken as B, G, R), atomically. Raises InputError.");
}

/// The options of detect() and Detector(...), written once for both docstrings (and the tracker's).
constexpr const char *kOptionsDoc =
    "aspect: None (the framebuffer's), a number, 'W:H' or (W, H); gravity: camera frame, pointing down\n"
    "(None: a level camera [0, 1, 0]; 'auto': from the floor; three numbers or 'gx,gy,gz'); method:\n"
    "'default' | 'paper'; hull: 'concave' | 'convex' (paper); seed: RANSAC seed; min_width (m), min_area\n"
    "(m^2): smaller rectangles are not found (None: 0.15 m and 0.012 m^2, as `projsurf detect`; 0 with\n"
    "method='paper'); suitability: None (avoid), 'off', 'avoid' or 'prefer' with colour (as\n"
    "--suitability). The pipeline settings of `projsurf detect` under the same names and units: max_tilt\n"
    "(rad), voxel_leaf, ransac_distance (m), max_outliers (paper); cell (m), max_planes,\n"
    "max_outlier_fraction (default). hull=None is 'concave'. config: None or the path of a detector settings\n"
    "YAML (`projsurf detect --config`, every key: `projsurf detect --print-config`), read first; any other\n"
    "argument given (not None) overrides it. The CLI's warnings (a gravity the floor contradicts, depths outside "
    "what RGB-D\n"
    "cameras read, colour not registered) come as UserWarnings.";

/// Detector: detection over a stream of clouds.
void bindDetectorClass(py::module_ &m) {
    py::class_<Detector> detector_class(
        m, "Detector",
        (std::string("Detection over a stream of clouds (reuses its buffers from frame to frame).\n") + kOptionsDoc)
            .c_str());
    addOptionsConstructor(detector_class);
    detector_class
        .def(
            "detect",
            [](Detector &d, const py::object &points, const py::object &colour, const py::object &explain,
               const py::object &overlay, const py::kwargs &extra) {
                // Settings belong to the Detector; a keyword here is a mistake, said in one line.
                for (const auto &item : extra)
                    throw InputError(
                        py::str(item.first).cast<std::string>(),
                        "unknown keyword argument (Detector.detect takes points, colour=, explain= and overlay=; the "
                        "settings go to Detector(...))");
                return d.detect(points, colour, explain, overlay);
            },
            "points"_a, py::kw_only(), "colour"_a = py::none(), "explain"_a = false, "overlay"_a = false,
            "points: (H, W, 3) or (N, 3) array (camera frame, m; NaN = no reading) or an object with .points.\n"
            "colour: optional (H, W, 3) uint8 B, G, R image registered to (H, W) points: the surface's suitability\n"
            "(docs/suitability.md); checked as `detect --rgb` checks it: another type or size is an InputError,\n"
            "colour whose edges do not fit the depth's (or with unorganized points) is not used, with a\n"
            "UserWarning. explain: True adds the key candidates, every vertical plane considered with its\n"
            "distance, size and why it lost (`detect --explain`, docs/interface.md); overlay: True adds the key\n"
            "overlay, `detect --overlay`'s picture as an (H, W, 3) uint8 B, G, R array (with explain, the\n"
            "candidates outlined). Returns the detection as a dict with the keys of the detection JSON.")
        .def_property_readonly("projector", &Detector::projector);
}

/// detect(): one cloud, `projsurf detect`.
void bindDetectFunction(py::module_ &m) {
    m.def(
        "detect",
        [](const py::object &points, const py::object &projector, const py::object &aspect, const py::object &gravity,
           const py::object &method, const py::object &hull, const py::object &seed, const py::object &min_width,
           const py::object &min_area, const py::object &colour, const py::object &suitability,
           const py::object &config, const py::object &explain, const py::object &overlay, const py::kwargs &settings) {
            Detector detector(projectorArgument(projector, "projector"),
                              detectorOptions({aspect, gravity, method, hull, seed, min_width, min_area, suitability,
                                               config, settings}));
            return detector.detect(points, colour, explain, overlay);
        },
        "points"_a, "projector"_a, py::kw_only(), "aspect"_a = py::none(), "gravity"_a = py::none(),
        "method"_a = py::none(), "hull"_a = py::none(), "seed"_a = py::none(), "min_width"_a = py::none(),
        "min_area"_a = py::none(), "colour"_a = py::none(), "suitability"_a = py::none(), "config"_a = py::none(),
        "explain"_a = false, "overlay"_a = false,
        (std::string("The biggest upright rectangle of the aspect ratio that the projector can light on a vertical\n"
                     "surface: `projsurf detect`. points and colour as for Detector.detect.\n") +
         kOptionsDoc +
         "\nexplain, overlay: as for Detector.detect. Returns a dict: found, reason, method, plane, rectangle,\n"
         "surface_check, suitability (with colour), timing_ms, gravity (numpy arrays for vectors), candidates\n"
         "(with explain), overlay (with overlay). Raises InputError for bad points or options.")
            .c_str());
}

/// keystone(): the homography and corners of a picture in the detected rectangle.
void bindKeystoneFunction(py::module_ &m) {
    m.def(
        "keystone",
        [](const py::object &projector, const py::object &detection, const py::object &picture_size,
           const py::object &tolerance_px) {
            const std::pair<double, double> size = pairArgument(picture_size, "picture_size");
            if (!(size.first >= 1 && size.second >= 1 && size.first <= 65536 && size.second <= 65536 &&
                  size.first == std::floor(size.first) && size.second == std::floor(size.second)))
                throw InputError("picture_size", "must be two whole numbers (width, height) between 1 and 65536");
            const Keystone k = keystoneFor(projectorArgument(projector, "projector"), detection,
                                           {static_cast<int>(size.first), static_cast<int>(size.second)}, tolerance_px);
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
}

/// correct(): the corrected framebuffer, `projsurf correct`.
void bindCorrectFunction(py::module_ &m) {
    m.def(
        "correct",
        [](const py::object &image, const py::object &projector_arg, const py::object &detection,
           const py::object &tolerance_px, const py::object &cloud_arg) {
            py::object keep;
            const cv::Mat picture = matFromArray(arrayArgument(image, "image"), "image", keep);
            const Projector &projector = projectorArgument(projector_arg, "projector");
            const Keystone k = keystoneFor(projector, detection, picture.size(), tolerance_px);
            const std::optional<Cloud> cloud =
                cloud_arg.is_none() ? std::nullopt : std::optional<Cloud>(cloudFromPoints(cloud_arg));
            const Rectangle rect = rectangleFromDetection(detection);
            cv::Mat framebuffer;
            {
                py::gil_scoped_release unlocked;
                framebuffer = warpToFramebuffer(picture, k);
                if (cloud) applyBlanking(framebuffer, frontend::blankingBefore(projector, rect, *cloud).mask);
            }
            return arrayFromMat(framebuffer);
        },
        "image"_a, "projector"_a, "detection"_a, "tolerance_px"_a = kKeystoneTolerancePx, py::kw_only(),
        "cloud"_a = py::none(),
        "Keystone correction: the projector framebuffer (the calibration's resolution, black around) showing\n"
        "`image` ((H, W) or (H, W, C), uint8, uint16 or float32; channels kept in their order) whole and\n"
        "undistorted in the detected rectangle (letterboxed, never stretched; full lens model). The image is\n"
        "read in place. detection: the dict of detect(), or (4, 3) corners. cloud: None, or the current points\n"
        "(as detect() takes them): the pixels whose rays meet something between the lens and the rectangle's\n"
        "plane (a person walking in) are black, as `projsurf correct --cloud`. Raises InputError.");
}

}  // namespace
}  // namespace projsurf::python

/// numpy for this interpreter, else an ImportError that says which interpreter and what to do
/// (without it pybind11 says only "initialization failed").
void requireNumpy() {
    try {
        py::module_::import("numpy");
    } catch (const py::error_already_set &e) {
        const py::module_ sys = py::module_::import("sys");
        const std::string interpreter = py::str(sys.attr("executable")).cast<std::string>();
        const std::string version = py::str(sys.attr("version")).cast<std::string>().substr(0, 6);
        throw std::runtime_error("projsurf needs numpy, which " + interpreter + " (Python " + version +
                                 ") cannot import: " + std::string(e.what()).substr(0, 80) +
                                 ". Install numpy for that interpreter (Debian: apt-get install python3-numpy) or "
                                 "run the one the module was built for, " PROJSURF_PYTHON_EXECUTABLE);
    }
}

PYBIND11_MODULE(projsurf, m) {
    using namespace projsurf::python;
    requireNumpy();
    m.doc() =
        "projsurf: where a robot's projector can show a picture on a wall, and its keystone correction.\n"
        "Camera optical frame (x right, y down, z forward), metres; degrees only where a name says _deg.\n"
        "Every bad argument (a wrong type, value or file) raises projsurf.InputError with one line.";
    bindInputError(m);
    bindProjector(m);
    bindCalibrationFiles(m);
    bindCloudFunctions(m);
    bindImageFiles(m);
    bindDetectorClass(m);
    bindDetectFunction(m);
    bindKeystoneFunction(m);
    bindCorrectFunction(m);
    addTrackerClass(m, kOptionsDoc);
    addPlanFunction(m);
    addPrintConfigFunction(m);
    addBagFunction(m);

    m.attr("__version__") = PROJSURF_VERSION;
    oneLineArgumentErrors(m);  // last: it wraps every function and method defined above
}
