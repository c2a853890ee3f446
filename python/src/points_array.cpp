#include "points_array.hpp"

#include <cstdint>
#include <cstring>
#include <string>

#include "argument_types.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"

namespace py = pybind11;

namespace projsurf::python {
namespace {

static_assert(sizeof(Point) == 3 * sizeof(float), "a Cloud's points are packed x, y, z floats");

std::string shapeText(const py::array &a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

/// Copies rows x cols points whose x, y, z are `T`s at the given byte strides.
template <typename T>
void copyPoints(const py::array &a, py::ssize_t rows, py::ssize_t cols, py::ssize_t row_stride, py::ssize_t col_stride,
                py::ssize_t xyz_stride, Cloud &cloud) {
    const auto *base = static_cast<const char *>(a.data());
    float *out = cloud.points.data()->data();
    if (std::is_same<T, float>::value && xyz_stride == sizeof(float) && col_stride == 3 * sizeof(float) &&
        (rows == 1 || row_stride == cols * col_stride)) {
        std::memcpy(out, base, static_cast<std::size_t>(rows * cols) * 3 * sizeof(float));
        return;
    }
    for (py::ssize_t r = 0; r < rows; ++r)
        for (py::ssize_t c = 0; c < cols; ++c) {
            const char *p = base + r * row_stride + c * col_stride;
            for (int k = 0; k < 3; ++k) {
                T v;
                std::memcpy(&v, p + k * xyz_stride, sizeof(T));
                *out++ = static_cast<float>(v);
            }
        }
}

}  // namespace

Cloud cloudFromPoints(const py::handle &points) {
    py::object source = py::reinterpret_borrow<py::object>(points);
    if (PyUnicode_Check(source.ptr()) || py::hasattr(source, "__fspath__"))
        throw InputError("points", "expected an (N, 3) or (H, W, 3) array, got " + describe(source) +
                                       " (projsurf.read_cloud or read_depth_cloud reads a file)");
    if (!py::isinstance<py::array>(source) && py::hasattr(source, "points")) source = source.attr("points");
    py::array a = py::array::ensure(source);
    if (!a) throw InputError("points", "expected an (N, 3) or (H, W, 3) array, or an object with .points");
    const py::dtype dt = a.dtype();
    if (dt.kind() != 'f' && dt.kind() != 'i' && dt.kind() != 'u')
        throw InputError("points",
                         "expected numbers, got an array of dtype " + py::str(py::handle(dt)).cast<std::string>());
    // The size before any conversion or copy: a broadcast array may announce terabytes.
    const bool shaped = (a.ndim() == 2 && a.shape(1) == 3) || (a.ndim() == 3 && a.shape(2) == 3);
    if (!shaped) throw InputError("points", "expected an (N, 3) or (H, W, 3) array, got shape " + shapeText(a));
    const auto count = static_cast<std::uint64_t>(a.shape(0)) * static_cast<std::uint64_t>(a.ndim() == 3 ? a.shape(1) : 1);
    if (count > limits::kMaxCloudPoints)
        throw InputError("points", "cloud of " + std::to_string(count) + " points exceeds the limit of " +
                                       std::to_string(limits::kMaxCloudPoints) + " points");
    if (!dt.is(py::dtype::of<float>()) && !dt.is(py::dtype::of<double>())) {
        a = py::array_t<double, py::array::forcecast>::ensure(a);  // integers: through double
        if (!a) {
            PyErr_Clear();
            throw InputError("points", "cannot convert the points to floating point (out of memory?)");
        }
    }

    Cloud cloud;
    py::ssize_t rows = 1, cols = 0, row_stride = 0, col_stride = 0, xyz_stride = 0;
    if (a.ndim() == 2 && a.shape(1) == 3) {
        cols = a.shape(0);
        col_stride = a.strides(0);
        xyz_stride = a.strides(1);
    } else if (a.ndim() == 3 && a.shape(2) == 3) {
        rows = a.shape(0);
        cols = a.shape(1);
        row_stride = a.strides(0);
        col_stride = a.strides(1);
        xyz_stride = a.strides(2);
    } else {
        throw InputError("points", "expected an (N, 3) or (H, W, 3) array, got shape " + shapeText(a));
    }
    if (rows * cols == 0) throw InputError("points", "the cloud has no points");
    cloud.points.resize(static_cast<std::size_t>(rows * cols));
    cloud.width = static_cast<int>(cols);
    cloud.height = static_cast<int>(rows);
    if (a.dtype().is(py::dtype::of<float>()))
        copyPoints<float>(a, rows, cols, row_stride, col_stride, xyz_stride, cloud);
    else
        copyPoints<double>(a, rows, cols, row_stride, col_stride, xyz_stride, cloud);
    // A cloud of NaN points only is a valid frame (docs/limits.md): found False with a reason, as
    // the CLI answers it, not an error.
    return cloud;
}

py::array arrayFromCloud(Cloud cloud) {
    auto *owned = new Cloud(std::move(cloud));
    py::capsule free_when_done(owned, [](void *p) { delete static_cast<Cloud *>(p); });
    const py::ssize_t n = static_cast<py::ssize_t>(owned->points.size());
    const py::ssize_t f = sizeof(float);
    float *data = owned->points.data()->data();
    if (owned->organized())
        return py::array_t<float>({py::ssize_t(owned->height), py::ssize_t(owned->width), py::ssize_t(3)},
                                  {owned->width * 3 * f, 3 * f, f}, data, free_when_done);
    return py::array_t<float>({n, py::ssize_t(3)}, {3 * f, f}, data, free_when_done);
}

}  // namespace projsurf::python
