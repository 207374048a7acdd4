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

/// Which mesh of the PLC is checked: the CDT of the whole convex hull, or the domain carved out of
/// it (cdt_carve.h).
enum class CdtDomain { kConvexHull, kCarved };

/// Checks, exactly and independently of how the mesh was built, that `tets` (0-based indices into
/// plc.points) is a constrained Delaunay tetrahedralization of `plc` under cavity's symbolic
/// perturbation (keyed on the input index):
///  - the tetrahedra form a complex (positive right-hand volume, each triangle on at most two
///    tetrahedra, on opposite sides);
///  - kConvexHull: its boundary is the convex hull, every point is a vertex and every PLC edge an
///    edge of the mesh;
///  - kCarved: its boundary consists of polygon triangles, no tetrahedron holds (in its closure)
///    a volume hole point or a PLC point that is not a mesh vertex, and every PLC edge whose
///    endpoints are both mesh vertices is an edge of the mesh (points and segments in the removed
///    exterior or holes are gone with it). Its tetrahedra are only checked locally, as a
///    subcomplex: two tetrahedra far apart are not tested for overlap;
///  - no tetrahedron crosses a polygon; for kConvexHull each polygon's area equals the area of the
///    mesh triangles inside it: every polygon is a union of faces. A carved domain holds only the
///    parts of polygons next to its tetrahedra (none of a wall with holes on both sides), so there
///    the polygons are not measured: in a valid PLC (edges meet polygons only at their sides and
///    corners), a part inside the domain but not covered is crossed by a tetrahedron or has a
///    corner inside one, both reported;
///  - every interior triangle not in a polygon is locally Delaunay (the apex across it is not in
///    the perturbed circumball), which by the Constrained Delaunay Lemma makes the mesh (the
///    carved one: a subcomplex of one) a CDT.
CdtValidation validate_cdt(const Plc& plc,
                           std::span<const std::array<std::uint32_t, 4>> tets,
                           CdtDomain domain = CdtDomain::kConvexHull);

}  // namespace cavity::core
