#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cavity/core/input/plc.h"

namespace cavity::core {

struct CdtValidation {
    std::vector<std::string> problems;  ///< the first few, each naming tetrahedra, edges or facets
    std::size_t problem_count = 0;
    std::size_t polygon_triangles = 0;

    bool ok() const { return problem_count == 0; }
};

/// Checks, exactly and independently of how the mesh was built, that `tets` (0-based indices into
/// plc.points) is a constrained Delaunay tetrahedralization of `plc` under cavity's symbolic
/// perturbation (keyed on the input index):
///  - the tetrahedra form a complex (positive right-hand volume, each triangle on at most two
///    tetrahedra, on opposite sides) whose boundary is the convex hull, and every point is a
///    vertex;
///  - every PLC edge is an edge of the mesh;
///  - no tetrahedron crosses a polygon, and each polygon's area equals the area of the mesh
///    triangles inside it: every polygon is a union of faces;
///  - every interior triangle not in a polygon is locally Delaunay (the apex across it is not in
///  the
///    perturbed circumball), which by the Constrained Delaunay Lemma makes the mesh a CDT.
CdtValidation validate_cdt(const Plc& plc, std::span<const std::array<std::uint32_t, 4>> tets);

}  // namespace cavity::core
