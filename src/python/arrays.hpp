#pragma once
// Numbers handed to Python as NumPy arrays where NumPy is present, else as nested lists of the
// same shape: the module works without NumPy, and is fastest with it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <vector>

namespace termpool::python {

/// True when `import numpy` works (asked once).
bool numpy_present();

/// A row-major block of doubles of `shape` as an ndarray (float64), or nested lists.
pybind11::object double_array(std::vector<double> values, std::vector<std::size_t> shape);

/// The same for ints (int64 arrays).
pybind11::object int_array(std::vector<long long> values, std::vector<std::size_t> shape);

} // namespace termpool::python
