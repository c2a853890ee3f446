#include "camera_pose.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <string>

#include "argument_types.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/limits.hpp"

namespace py = pybind11;

namespace projsurf::python {

namespace {

constexpr double kRotationTolerance = 1e-6;  ///< |R^T R - I| and |det R - 1| allowed: float64 round-off of a pose

Eigen::Matrix4d matrixArgument(const py::handle &value, const char *name) {
    const auto a = py::array_t<double, py::array::forcecast>::ensure(value);  // null when numpy cannot
    if (!a || a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4 || py::isinstance<py::str>(value))
        throw InputError(name, "expected a 4x4 array (fixed-from-camera pose) or None, got " + describe(value));
    Eigen::Matrix4d m;
    const auto r = a.unchecked<2>();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m(i, j) = r(i, j);
    return m;
}

}  // namespace

Eigen::Isometry3d cameraPoseArgument(const py::handle &value, const char *name) {
    if (value.is_none()) return Eigen::Isometry3d::Identity();
    const Eigen::Matrix4d m = matrixArgument(value, name);
    if (!m.allFinite()) throw InputError(name, "holds a value that is not finite");
    if (!(m.topRightCorner<3, 1>().norm() <= limits::kMaxPoseTranslationM))
        throw InputError(name, "puts the camera more than " + std::to_string(static_cast<int>(limits::kMaxPoseTranslationM)) +
                                   " m from the fixed frame's origin (metres expected)");
    if (m.row(3) != Eigen::RowVector4d(0, 0, 0, 1))
        throw InputError(name, "its last row must be 0 0 0 1 (a rigid transform)");
    const Eigen::Matrix3d R = m.topLeftCorner<3, 3>();
    if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > kRotationTolerance ||
        std::abs(R.determinant() - 1.0) > kRotationTolerance)
        throw InputError(name, "its top-left 3x3 is not a rotation (orthonormal, determinant 1)");
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = R;
    pose.translation() = m.topRightCorner<3, 1>();
    return pose;
}

}  // namespace projsurf::python
