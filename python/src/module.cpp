#include <pybind11/pybind11.h>

#include "bindings.h"
#include "cavity/core/version.h"

// The extension of the `cavity` package (python/cavity/__init__.py re-exports it).
PYBIND11_MODULE(_cavity, m) {
    m.doc() =
        "Exact, instrumented 3D Delaunay triangulation (Bowyer-Watson with exact predicates and "
        "symbolic perturbation): never a flat or inverted tetrahedron, whatever the input.";
    m.attr("__version__") = cavity::core::kVersion;
    cavity::python::bind_errors(m);
    cavity::python::bind_delaunay(m);
    cavity::python::bind_cdt(m);
    cavity::python::bind_predicates(m);
}
