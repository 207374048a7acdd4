#include <pybind11/pybind11.h>

#include "bindings.h"
#include "cavity/core/base/error.h"

namespace cavity::python {

void bind_errors(py::module_& m) {
    // Every core::Error is about the input (a malformed value, too few distinct points, coplanar
    // input with its affine dimension, an unknown option name): Python's ValueError.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const core::Error& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    py::register_exception<ValidationFailure>(m, "ValidationError", PyExc_RuntimeError);
}

}  // namespace cavity::python
