#include "python/arrays.hpp"

namespace py = pybind11;

namespace termpool::python {

namespace {

/// Nested lists of `shape` from `values` starting at `offset` (advanced past what was used).
template <class T>
py::object nested(const std::vector<T>& values, const std::vector<std::size_t>& shape,
                  std::size_t depth, std::size_t& offset) {
    py::list out;
    for (std::size_t i = 0; i < shape[depth]; ++i) {
        if (depth + 1 == shape.size())
            out.append(values[offset++]);
        else
            out.append(nested(values, shape, depth + 1, offset));
    }
    return out;
}

template <class T> py::object array_of(std::vector<T> values, std::vector<std::size_t> shape) {
    if (!numpy_present()) {
        std::size_t offset = 0;
        return shape.empty() ? py::object(py::list()) : nested(values, shape, 0, offset);
    }
    py::array_t<T> array(std::vector<py::ssize_t>(shape.begin(), shape.end()));
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
}

} // namespace

bool numpy_present() {
    static const bool present = [] {
        try {
            py::module_::import("numpy");
            return true;
        } catch (const py::error_already_set&) {
            return false;
        }
    }();
    return present;
}

py::object double_array(std::vector<double> values, std::vector<std::size_t> shape) {
    return array_of(std::move(values), std::move(shape));
}

py::object int_array(std::vector<long long> values, std::vector<std::size_t> shape) {
    return array_of(std::move(values), std::move(shape));
}

} // namespace termpool::python
