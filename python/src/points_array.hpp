#pragma once
// Points between numpy and the detector's Cloud (camera frame: x right, y down, z forward;
// metres; NaN marks a missing reading).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "projsurf/types/cloud.hpp"

namespace projsurf::python {

/// `points`: an (H, W, 3) array (an organized cloud: W x H, the sensor's pixel grid) or an
/// (N, 3) array, of any real or integer type and any strides; or any object with a `.points`
/// attribute that numpy reads (an Open3D PointCloud's Vector3dVector). The points are
/// converted in one pass straight into the Cloud's storage: the Cloud owns a std::vector, so it
/// cannot borrow the array (a C-contiguous float32 array is a single memcpy).
/// Throws InputError("points", problem) for another shape, or no points (all-NaN points are a valid, empty frame).
Cloud cloudFromPoints(const pybind11::handle &points);

/// The cloud as an (H, W, 3) float32 array when organized, else (N, 3); the array takes the
/// cloud's storage over (no copy).
pybind11::array arrayFromCloud(Cloud cloud);

}  // namespace projsurf::python
