#include "image_array.hpp"

#include <cstdint>
#include <string>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"

namespace py = pybind11;

namespace projsurf::python {
namespace {

int cvDepthOf(const py::dtype &dt) {
    if (dt.is(py::dtype::of<std::uint8_t>())) return CV_8U;
    if (dt.is(py::dtype::of<std::uint16_t>())) return CV_16U;
    if (dt.is(py::dtype::of<float>())) return CV_32F;
    return -1;
}

py::dtype dtypeOf(int depth) {
    switch (depth) {
    case CV_8U: return py::dtype::of<std::uint8_t>();
    case CV_16U: return py::dtype::of<std::uint16_t>();
    case CV_32F: return py::dtype::of<float>();
    default: throw std::invalid_argument("image: unsupported OpenCV depth " + std::to_string(depth));
    }
}

}  // namespace

cv::Mat matFromArray(const py::array &image, const char *name, py::object &keep) {
    const int depth = cvDepthOf(image.dtype());
    if (depth < 0)
        throw InputError(name, "expected an image of dtype uint8, uint16 or float32, got " +
                                   py::str(py::handle(image.dtype())).cast<std::string>());
    if (image.ndim() != 2 && !(image.ndim() == 3 && image.shape(2) >= 1 && image.shape(2) <= 4))
        throw InputError(name, "expected an (H, W) or (H, W, C) image with C = 1..4 channels");
    // The size before any conversion or copy: a broadcast array may announce terabytes.
    if (image.shape(0) < 1 || image.shape(1) < 1) throw InputError(name, "the image is empty");
    const auto pixels = static_cast<std::uint64_t>(image.shape(0)) * static_cast<std::uint64_t>(image.shape(1));
    if (image.shape(0) > limits::kMaxFramebufferSide * 4 || image.shape(1) > limits::kMaxFramebufferSide * 4 ||
        pixels > limits::kMaxImagePixels)
        throw InputError(name, "image of " + std::to_string(image.shape(1)) + " x " + std::to_string(image.shape(0)) +
                                   " pixels exceeds the limit of " + std::to_string(limits::kMaxImagePixels) +
                                   " pixels");
    const int rows = static_cast<int>(image.shape(0)), cols = static_cast<int>(image.shape(1));
    const int channels = image.ndim() == 3 ? static_cast<int>(image.shape(2)) : 1;
    const py::ssize_t elem = image.itemsize();
    const bool packed_rows = image.strides(1) == channels * elem && (channels == 1 || image.strides(2) == elem) &&
                             image.strides(0) >= cols * channels * elem;
    py::array source = image;
    if (!packed_rows) {
        source = py::array::ensure(image, py::array::c_style);
        if (!source) {
            PyErr_Clear();
            throw InputError(name, "cannot make a contiguous copy of the image (out of memory?)");
        }
        keep = source;
    }
    return cv::Mat(rows, cols, CV_MAKETYPE(depth, channels), const_cast<void *>(source.data()),
                   static_cast<std::size_t>(source.strides(0)));
}

py::array arrayFromMat(const cv::Mat &mat) {
    auto *owned = new cv::Mat(mat);  // shares the pixels (reference counted)
    py::capsule release(owned, [](void *p) { delete static_cast<cv::Mat *>(p); });
    const py::ssize_t elem = static_cast<py::ssize_t>(mat.elemSize1());
    const py::ssize_t step = static_cast<py::ssize_t>(mat.step[0]);
    if (mat.channels() == 1)
        return py::array(dtypeOf(mat.depth()), {py::ssize_t(mat.rows), py::ssize_t(mat.cols)}, {step, elem},
                         owned->data, release);
    return py::array(dtypeOf(mat.depth()), {py::ssize_t(mat.rows), py::ssize_t(mat.cols), py::ssize_t(mat.channels())},
                     {step, elem * mat.channels(), elem}, owned->data, release);
}

}  // namespace projsurf::python
