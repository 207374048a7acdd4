#include <pybind11/pybind11.h>

#include "bindings.h"
#include "cavity/core/base/error.h"

namespace cavity::python {

void bind_errors(py::module_& m) {
    // By the error's kind: the input's fault (a malformed value, too few distinct points, coplanar
    // input with its affine dimension, an unknown option name) is Python's ValueError; a refusal
    // of the system (a failed write) is OSError; a broken invariant of cavity is RuntimeError,
    // so that a script catching ValueError for bad data never swallows a bug.
    // pybind11 takes a translator of exactly this signature (by value).
    py::register_exception_translator(
        [](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
            try {
                if (p) {
                    std::rethrow_exception(p);
                }
            } catch (const core::Error& e) {
                switch (e.kind()) {
                    case core::ErrorKind::kInput:
                        PyErr_SetString(PyExc_ValueError, e.what());
                        break;
                    case core::ErrorKind::kSystem:
                        PyErr_SetString(PyExc_OSError, e.what());
                        break;
                    case core::ErrorKind::kInternal:
                        PyErr_SetString(PyExc_RuntimeError, e.what());
                        break;
                }
            }
        });
    py::register_exception<ValidationFailure>(m, "ValidationError", PyExc_RuntimeError);
}

}  // namespace cavity::python
