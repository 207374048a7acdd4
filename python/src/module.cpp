#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(cavity, m) {
    m.doc() =
        "Exact, instrumented 3D Delaunay triangulation (Bowyer-Watson with exact predicates and "
        "symbolic perturbation): never a flat or inverted tetrahedron, whatever the input.";
    m.attr("__version__") = CAVITY_VERSION;
    cavity::python::bind_errors(m);
    cavity::python::bind_delaunay(m);
    cavity::python::bind_predicates(m);
}
