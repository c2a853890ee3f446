#pragma once
// A camera pose from Python: None (the identity: a robot standing still) or a 4x4 rigid
// transform, fixed-from-camera (the camera's pose in odom or map), as a numpy array or nested
// lists.
#include <Eigen/Geometry>

#include <pybind11/pybind11.h>

namespace projsurf::python {

/// Throws InputError(name, problem) for another shape, a non-number, a non-finite value, a
/// last row other than 0 0 0 1, or a rotation part that is not a rotation (within 1e-6).
Eigen::Isometry3d cameraPoseArgument(const pybind11::handle &value, const char *name);

}  // namespace projsurf::python
