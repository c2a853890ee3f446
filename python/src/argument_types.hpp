#pragma once
// Python arguments of the wrong type as InputError("<argument>", one line), never pybind11's
// TypeError with its signature dump and the argument printed whole: every function of the
// module takes plain objects and converts them here.
#include <Eigen/Core>
#include <string>
#include <utility>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "projsurf/types/projector.hpp"

namespace projsurf::python {

/// What a value is, short enough for one line: "a str 'calib.yaml'", "a list of 480 items",
/// "an array of shape (480, 640) and dtype float64"; never the value printed whole.
std::string describe(const pybind11::handle &value);

/// A str or an os.PathLike (pathlib.Path).
std::string pathArgument(const pybind11::handle &value, const char *name);
/// A projsurf.Projector (a path gets the hint to read it with read_calibration).
const Projector &projectorArgument(const pybind11::handle &value, const char *name);
/// A numpy array, used as it is (a list is refused: an image is not converted element by element).
pybind11::array arrayArgument(const pybind11::handle &value, const char *name);
/// A real number (int, float or a numpy scalar; not bool).
double numberArgument(const pybind11::handle &value, const char *name);
/// A whole number in [lo, hi] (int or a numpy integer; not bool).
long long wholeArgument(const pybind11::handle &value, const char *name, long long lo, long long hi);
/// A str.
std::string wordArgument(const pybind11::handle &value, const char *name);
/// Two numbers: a tuple, list or array of length 2.
std::pair<double, double> pairArgument(const pybind11::handle &value, const char *name);
/// Three finite or non-finite numbers: a tuple, list or array of length 3.
Eigen::Vector3d vectorArgument(const pybind11::handle &value, const char *name);

}  // namespace projsurf::python
