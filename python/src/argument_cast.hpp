#pragma once
// A Python argument as the C++ type it stands for, or a short InputError naming the argument:
// instead of pybind11's TypeError listing every signature of the function.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "projsurf/io/errors.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::python {

template <class T>
T argumentAs(const pybind11::handle &value, const char *name, const char *expected) {
    try {
        return value.cast<T>();
    } catch (const pybind11::cast_error &) {
        throw InputError(name, std::string("expected ") + expected + ", got " +
                                   std::string(pybind11::str(pybind11::type::handle_of(value).attr("__name__"))));
    }
}

inline Projector projectorArgument(const pybind11::handle &value) {
    return argumentAs<Projector>(value, "projector", "a projsurf.Projector (read_calibration or Projector(...))");
}
inline std::string textArgument(const pybind11::handle &value, const char *name) {
    return argumentAs<std::string>(value, name, "a str");
}
inline unsigned seedArgument(const pybind11::handle &value) {
    return argumentAs<unsigned>(value, "seed", "a whole number >= 0");
}
inline double numberArgument(const pybind11::handle &value, const char *name, const char *unit) {
    return argumentAs<double>(value, name, unit);
}

}  // namespace projsurf::python
