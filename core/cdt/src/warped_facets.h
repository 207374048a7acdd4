#pragma once

// Surface meshes exported by CAD tools and scanners have polygon faces whose corners are not
// exactly coplanar: a planar quad whose coordinates were rounded to doubles, or a face that was
// never planar. A PLC facet must be planar, so the reader cuts such a face into triangles, as
// TetGen triangulates a facet and CGAL users run triangulate_faces before meshing.

#include <cstddef>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// Replaces each one-loop facet whose corners are not exactly coplanar by triangles of its corners,
/// in the projection along the largest component of its Newell normal: the triangulation with the
/// shortest diagonals in total (ear clipping's for loops over kMinimumWeightCorners corners);
/// every triangle keeps the face's number, line and marker, so defects are still named as the
/// file numbers its faces. A face whose projection is no simple polygon is left whole (the surface
/// check reports it as degenerate). Returns how many faces were cut.
std::size_t split_warped_facets(Plc& plc);

}  // namespace cavity::core
