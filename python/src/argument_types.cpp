#include "argument_types.hpp"

#include <pybind11/numpy.h>

#include <cmath>

#include "projsurf/io/files/errors.hpp"

namespace py = pybind11;

namespace projsurf::python {
namespace {

constexpr std::size_t kShownChars = 40;  ///< characters of a str or number shown in a message

std::string article(const std::string &word) {
    return (!word.empty() && std::string("aeiou").find(word[0]) != std::string::npos ? "an " : "a ") + word;
}

std::string typeName(const py::handle &value) { return Py_TYPE(value.ptr())->tp_name; }

std::string shortened(std::string text) {
    if (text.size() > kShownChars) text = text.substr(0, kShownChars) + "...";
    return text;
}

bool isText(const py::handle &value) { return PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()); }

/// Length-`n` sequence (tuple, list, 1-D array) -> numbers; InputError otherwise.
std::vector<double> numbers(const py::handle &value, const char *name, std::size_t n, const char *expected) {
    const bool sequence = !isText(value) && PySequence_Check(value.ptr()) &&
                          !(py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).ndim() != 1);
    const Py_ssize_t size = sequence ? PySequence_Size(value.ptr()) : -1;
    if (size < 0) PyErr_Clear();
    if (size != static_cast<Py_ssize_t>(n))
        throw InputError(name, std::string("expected ") + expected + ", got " + describe(value));
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) {
        const py::object item = py::reinterpret_steal<py::object>(PySequence_GetItem(value.ptr(), Py_ssize_t(i)));
        if (!item) {
            PyErr_Clear();
            throw InputError(name, std::string("expected ") + expected + ", got " + describe(value));
        }
        try {
            out.push_back(numberArgument(item, name));
        } catch (const InputError &) {
            throw InputError(name, std::string("expected ") + expected + ", got " + describe(value) + " whose item " +
                                       std::to_string(i) + " is " + describe(item));
        }
    }
    return out;
}

}  // namespace

std::string describe(const py::handle &value) {
    if (value.is_none()) return "None";
    if (py::isinstance<py::array>(value)) {
        const auto a = py::reinterpret_borrow<py::array>(value);
        std::string shape = "(";
        for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
        shape += a.ndim() == 1 ? ",)" : ")";
        return "an array of shape " + shape + " and dtype " + py::str(py::handle(a.dtype())).cast<std::string>();
    }
    if (PyUnicode_Check(value.ptr())) return "a str " + shortened(py::repr(value).cast<std::string>());
    if (PyBool_Check(value.ptr())) return py::str(value).cast<std::string>();
    if (PyLong_Check(value.ptr()) || PyFloat_Check(value.ptr()))
        return article(typeName(value)) + " " + shortened(py::str(value).cast<std::string>());
    if (PyList_Check(value.ptr()) || PyTuple_Check(value.ptr()) || PyDict_Check(value.ptr())) {
        const Py_ssize_t n = PyObject_Length(value.ptr());
        return article(typeName(value)) + " of " + std::to_string(n) + (n == 1 ? " item" : " items");
    }
    return article(typeName(value));
}

std::string pathArgument(const py::handle &value, const char *name) {
    std::string path;
    if (PyUnicode_Check(value.ptr())) {
        path = value.cast<std::string>();
    } else if (py::hasattr(value, "__fspath__") && PyUnicode_Check(value.attr("__fspath__")().ptr())) {
        path = value.attr("__fspath__")().cast<std::string>();
    } else {
        throw InputError(name, "expected a file path (str or pathlib.Path), got " + describe(value));
    }
    // The C library would end the name at a NUL ('a\0b.png' wrote 'a'), as Python's open() refuses it.
    if (path.find('\0') != std::string::npos) throw InputError(name, "a file path must not hold a NUL character");
    return path;
}

const Projector &projectorArgument(const py::handle &value, const char *name) {
    if (py::isinstance<Projector>(value)) return value.cast<const Projector &>();
    const bool path = PyUnicode_Check(value.ptr()) || py::hasattr(value, "__fspath__");
    throw InputError(name, "expected a projsurf.Projector, got " + describe(value) +
                               (path ? " (projsurf.read_calibration(path) reads a calibration file)" : ""));
}

py::array arrayArgument(const py::handle &value, const char *name) {
    if (py::isinstance<py::array>(value)) return py::reinterpret_borrow<py::array>(value);
    throw InputError(name, "expected a numpy array, got " + describe(value) +
                               (PyList_Check(value.ptr()) ? " (numpy.asarray makes one)" : ""));
}

double numberArgument(const py::handle &value, const char *name) {
    const bool scalar_array = py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).ndim() == 0;
    const bool array = py::isinstance<py::array>(value) && !scalar_array;
    if (!PyBool_Check(value.ptr()) && !array && !isText(value) && PyNumber_Check(value.ptr())) {
        const double v = PyFloat_AsDouble(value.ptr());
        if (!(v == -1.0 && PyErr_Occurred())) return v;
        PyErr_Clear();
    }
    throw InputError(name, "expected a number, got " + describe(value));
}

long long wholeArgument(const py::handle &value, const char *name, long long lo, long long hi) {
    const std::string range = std::to_string(lo) + " and " + std::to_string(hi);
    if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
        throw InputError(name, "expected a whole number between " + range + ", got " + describe(value));
    int overflow = 0;
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    const long long v = index ? PyLong_AsLongLongAndOverflow(index.ptr(), &overflow) : 0;
    if (!index || PyErr_Occurred()) PyErr_Clear();
    if (!index || overflow != 0 || v < lo || v > hi)
        throw InputError(name, "expected a whole number between " + range + ", got " + describe(value));
    return v;
}

std::string wordArgument(const py::handle &value, const char *name) {
    if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
    throw InputError(name, "expected a str, got " + describe(value));
}

std::pair<double, double> pairArgument(const py::handle &value, const char *name) {
    const std::vector<double> v = numbers(value, name, 2, "two numbers");
    return {v[0], v[1]};
}

Eigen::Vector3d vectorArgument(const py::handle &value, const char *name) {
    const std::vector<double> v = numbers(value, name, 3, "three numbers x, y, z");
    return {v[0], v[1], v[2]};
}

}  // namespace projsurf::python
