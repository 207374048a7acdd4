#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/base/handedness.h"
#include "cavity/core/cdt/cdt.h"

/// Carving the domain a PLC bounds out of its CDT, as TetGen does with -p: the CDT covers the
/// convex hull of the points, and the domain is what remains after removing
///  - the exterior: every tetrahedron reachable from a convex-hull triangle that is not a polygon
///    triangle, without crossing a polygon triangle;
///  - each volume hole (Plc::volume_holes): every tetrahedron reachable, without crossing a
///    polygon triangle, from the tetrahedron holding the hole point (exact location). A hole
///    point on a face, edge or vertex of the mesh that is in no polygon may lie in several
///    tetrahedra; they are all connected across triangles in no polygon, so the choice does not
///    matter. A hole point in a polygon's closure is refused, since it does not say which side to
///    remove; so is one outside the hull. A hole point in the exterior removes nothing more.
/// With `convex_hull` nothing is removed: the whole hull, as `cavity cdt --convex-hull` writes it
/// (TetGen's -c keeps the exterior but still carves holes; here the hull stays whole so that it
/// is validated as the hull). Hole points are checked all the same.
namespace cavity::core {

struct CarvedCdt {
    std::vector<Tet> tets;  ///< the kept tetrahedra, in the CDT's order (positive volume)
    /// TetGen's region attribute of each kept tetrahedron (region_markers; 0: no region)
    std::vector<std::int32_t> regions;
    std::size_t removed = 0;  ///< tetrahedra of the CDT carved away
};

/// Carves `cdt` (its plc, tets and faces). O(T) with hashing, plus O(T) exact orientation tests
/// per hole and region point.
/// \throws Error naming the .poly line of a hole point outside the tetrahedralization or on a
/// polygon, or of a region point outside it (region_markers).
CarvedCdt carve_cdt(const Cdt& cdt, bool convex_hull);

}  // namespace cavity::core
