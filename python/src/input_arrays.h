#pragma once

#include <cstddef>
#include <vector>

#include <pybind11/numpy.h>

#include "cavity/core/input/point_set.h"

/// Checks on the arrays Python hands in, so that every bad input becomes a ValueError naming the
/// offending row before any C++ work starts.
namespace cavity::python {

namespace py = pybind11;

/// A C-contiguous float64 copy-or-view of `array` (ints and float32 are converted).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Reads an (n, width) array of finite numbers. \throws py::value_error naming `name`, the shape
/// or the first row holding a NaN or an infinity.
DoubleArray require_rows(const py::handle& array, const char* name, py::ssize_t width);

/// The PointSet of an (n, 3) `points` array and optional (n,) `weights` (None: unweighted).
/// \throws py::value_error for a wrong shape, a non-finite value (naming the row) or more points
/// than a 32-bit signed index can number.
core::PointSet to_point_set(const py::handle& points, const py::handle& weights);

}  // namespace cavity::python
