#include "input_arrays.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace cavity::python {

namespace {

std::string shape_text(const py::array& a) {
    std::string text = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) {
        text += (i ? ", " : "") + std::to_string(a.shape(i));
    }
    return text + (a.ndim() == 1 ? ",)" : ")");
}

/// numpy's own conversion, in two steps so that each failure keeps its meaning: numpy.asarray
/// first (its MemoryError, or its error for ragged input, reaches the caller unchanged), then a
/// check of the element kind (numpy would silently drop the imaginary part of complex numbers and
/// parse strings), then the cast to contiguous doubles (again with numpy's own errors).
DoubleArray as_doubles(const py::handle& array, const char* name) {
    const py::array raw = py::module_::import("numpy").attr("asarray")(array);
    const char kind = raw.dtype().kind();
    if (kind == 'c') {
        throw py::value_error(std::string(name) + " must be real numbers, got complex values (" +
                              py::str(raw.dtype()).cast<std::string>() + ")");
    }
    if (kind != 'f' && kind != 'i' && kind != 'u') {
        throw py::value_error(std::string(name) + " must be an array of numbers, got dtype " +
                              py::str(raw.dtype()).cast<std::string>());
    }
    return DoubleArray(raw);
}

}  // namespace

DoubleArray require_rows(const py::handle& array, const char* name, py::ssize_t width) {
    DoubleArray a = as_doubles(array, name);
    if (a.ndim() != 2 || a.shape(1) != width) {
        throw py::value_error(std::string(name) + " must have shape (n, " + std::to_string(width) +
                              "), got " + shape_text(a));
    }
    const double* data = a.data();
    for (py::ssize_t row = 0; row < a.shape(0); ++row) {
        for (py::ssize_t col = 0; col < width; ++col) {
            const double x = data[row * width + col];
            if (!std::isfinite(x)) {
                throw py::value_error(std::string(name) + " row " + std::to_string(row) +
                                      " has a non-finite value (" +
                                      (std::isnan(x) ? "nan" : "inf") + ") in column " +
                                      std::to_string(col));
            }
        }
    }
    return a;
}

core::PointSet to_point_set(const py::handle& points, const py::handle& weights) {
    const DoubleArray p = require_rows(points, "points", 3);
    const auto n = static_cast<std::size_t>(p.shape(0));
    if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        throw py::value_error("more than 2^31-1 points cannot be numbered by int32 indices");
    }
    core::PointSet set;
    set.source = "points";
    set.points.resize(n);
    const double* data = p.data();
    for (std::size_t i = 0; i < n; ++i) {
        set.points[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    }
    if (weights.is_none()) {
        return set;
    }
    const DoubleArray w = as_doubles(weights, "weights");
    if (w.ndim() != 1 || static_cast<std::size_t>(w.shape(0)) != n) {
        throw py::value_error("weights must have shape (" + std::to_string(n) + ",), got " +
                              shape_text(w));
    }
    set.weights.assign(w.data(), w.data() + n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(set.weights[i])) {
            throw py::value_error("weights row " + std::to_string(i) + " is not finite (" +
                                  (std::isnan(set.weights[i]) ? "nan" : "inf") + ")");
        }
    }
    return set;
}

}  // namespace cavity::python
