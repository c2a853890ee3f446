#include "argument_errors.hpp"

#include <pybind11/eval.h>

namespace py = pybind11;

namespace projsurf::python {

void oneLineArgumentErrors(py::module_ &m) {
    py::dict scope;
    scope["module"] = m;
    py::exec(R"PY(
import functools as _functools
import re as _re

def _install(module):
    InputError = module.InputError

    def explain(name, text, args, kwargs):
        # pybind11's first signature: "1. (points: object, projector: ..., *, aspect: object = None) -> dict"
        sig = _re.search(r"^\s*1\. [\w.]*\((.*)\)", text, _re.M)
        params = sig.group(1) if sig else ""
        names, positional, star = [], 0, False
        for part in _re.split(r",\s*(?![^\[\(]*[\]\)])", params):
            part = part.strip()
            if part == "*":
                star = True
                continue
            word = _re.match(r"(\w+)", part)
            if not word or word.group(1) == "self":
                continue
            names.append(word.group(1))
            if not star:
                positional += 1
        unknown = [k for k in kwargs if k not in names]
        known = ", ".join(names) if names else "none"
        if len(known) > 200:
            known = known[:200].rsplit(", ", 1)[0] + ", ..."
        if unknown:
            return "unknown keyword argument %r (known: %s)" % (unknown[0][:40], known)
        if len(args) > positional:
            return "takes %d positional argument(s), got %d; the others are keywords (known: %s)" % (
                positional, len(args), known)
        return "the arguments match none of its parameters (%s)" % known

    def wrap(f, name, skip_self):
        @_functools.wraps(f)
        def call(*args, **kwargs):
            try:
                return f(*args, **kwargs)
            except TypeError as e:
                text = str(e)
                if "incompatible function arguments" not in text and "incompatible constructor arguments" not in text:
                    raise
                shown = args[1:] if skip_self else args
                raise InputError("%s: %s" % (name, explain(name, text, shown, kwargs))) from None
        return call

    for attr in dir(module):
        value = getattr(module, attr)
        if attr.startswith("_"):
            continue
        if isinstance(value, type):
            if issubclass(value, BaseException):
                continue
            for method in list(vars(value)):
                if method.startswith("__") and method != "__init__":
                    continue
                member = vars(value)[method]
                if callable(member) and not isinstance(member, (property, staticmethod, classmethod)):
                    title = attr if method == "__init__" else attr + "." + method
                    setattr(value, method, wrap(member, title, True))
        elif callable(value):
            setattr(module, attr, wrap(value, attr, False))

_install(module)
)PY",
             scope);
}

}  // namespace projsurf::python
