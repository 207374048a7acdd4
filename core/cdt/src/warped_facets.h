#pragma once

// Surface meshes exported by CAD tools and scanners have polygon faces whose corners are not
// exactly coplanar: a planar quad whose coordinates were rounded to doubles, or a face that was
// never planar. A PLC facet must be planar, so the reader cuts such a face into triangles, as
// TetGen triangulates a facet and CGAL users run triangulate_faces before meshing.

#include <cstddef>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// Replaces each one-loop facet whose corners are not exactly coplanar by the triangles ear
/// clipping cuts it into, in the projection along the largest component of its Newell normal;
/// every triangle keeps the face's number, line and marker, so defects are still named as the
/// file numbers its faces. A face whose projection is no simple polygon is left whole (the surface
/// check reports it as degenerate). Returns how many faces were cut.
std::size_t split_warped_facets(Plc& plc);

}  // namespace cavity::core
