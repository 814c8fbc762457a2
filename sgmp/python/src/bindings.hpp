#pragma once
// Shared pieces of the Python module: the pack object and the conversions of its arrays,
// the pack request built from keyword arguments, the measurement as a dict.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "sgmp/pack/pack.hpp"

namespace sgmp::python {

namespace py = pybind11;

/// Binds the `Pack` class (pack_object.cpp).
void bind_pack(py::module_& m);
/// The pack a Python object stands for: a bound Pack (pack_object.cpp).
const Pack& pack_of(const py::handle& object);

/// `sgmp.pack(...)` and `sgmp.arrange(...)` (request.cpp).
void bind_making(py::module_& m);
/// `sgmp.measure(...)` (measure_object.cpp).
void bind_measure(py::module_& m);

}  // namespace sgmp::python
