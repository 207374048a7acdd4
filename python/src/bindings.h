#pragma once

#include <pybind11/pybind11.h>

/// One registration function per part of the `cavity` Python module (module.cpp calls them).
namespace cavity::python {

namespace py = pybind11;

/// cavity::core::Error -> ValueError; cavity.ValidationError for check().
void bind_errors(py::module_& m);
/// cavity.Delaunay.
void bind_delaunay(py::module_& m);
/// cavity.cdt and cavity.CDT.
void bind_cdt(py::module_& m);
/// cavity.orient3d, cavity.insphere, cavity.orient4d over arrays of queries.
void bind_predicates(py::module_& m);

/// Thrown by Delaunay.check() when the exact validator finds problems.
class ValidationFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace cavity::python
