#include "json_values.hpp"

namespace py = pybind11;

namespace projsurf::python {

py::object pythonFromJson(const nlohmann::json &j) {
    switch (j.type()) {
    case nlohmann::json::value_t::object: {
        py::dict d;
        for (const auto &[key, value] : j.items()) d[py::str(key)] = pythonFromJson(value);
        return std::move(d);
    }
    case nlohmann::json::value_t::array: {
        py::list l;
        for (const auto &value : j) l.append(pythonFromJson(value));
        return std::move(l);
    }
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    case nlohmann::json::value_t::string: return py::str(j.get_ref<const std::string &>());
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    default: return py::none();  // null (and the binary and discarded kinds the writers never make)
    }
}

}  // namespace projsurf::python
