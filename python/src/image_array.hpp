#pragma once
// Images between numpy and OpenCV: (H, W) or (H, W, C) arrays, C = 1..4, of uint8, uint16 or
// float32. Channels are passed through in their order (RGB stays RGB).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <opencv2/core.hpp>

namespace projsurf::python {

/// A cv::Mat over the array's memory (no copy) when each row's pixels are packed; otherwise
/// over a packed copy, which `keep` then holds. Throws InputError(name, problem) for another
/// shape or dtype.
cv::Mat matFromArray(const pybind11::array &image, const char *name, pybind11::object &keep);

/// The image as an (H, W) or (H, W, C) array sharing the Mat's memory (no copy).
pybind11::array arrayFromMat(const cv::Mat &mat);

}  // namespace projsurf::python
