#pragma once
// Calls whose arguments match no signature (an unknown keyword, a positional argument where
// only keywords are taken) as one line of InputError, like every other mistake: pybind11 says
// them with a TypeError of several lines that dumps every signature and the arguments given.
#include <pybind11/pybind11.h>

namespace projsurf::python {

/// Wraps every function of `m` and every method of its classes (constructors included) so
/// that pybind11's "incompatible function arguments" TypeError becomes InputError:
/// "plan: unknown keyword argument 'bogus' (known: points, projector, aspect, ...)". Call last.
void oneLineArgumentErrors(pybind11::module_ &m);

}  // namespace projsurf::python
