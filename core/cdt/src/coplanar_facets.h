#pragma once

// A surface mesh describes a flat face of a solid as many triangles: a CAD plate with holes comes
// as long thin triangles fanned across it. As PLC facets, every side of those triangles is a
// segment that edge protection must make a union of Delaunay edges, and the long, nearly parallel
// sides of a fan need hundreds of splits each (the oblong model: 9129 Steiner points). The face
// itself is one polygon of the solid's boundary, so the reader merges exactly coplanar
// neighbouring faces into it, as TetGen does unless -M is given; its CDT conforms to the same
// surface and needs none of those splits (oblong: 16).

#include <cstddef>

#include "cavity/core/input/plc.h"

namespace cavity::core {

struct CoplanarMerge {
    std::size_t faces = 0;     ///< faces that became part of a larger polygon
    std::size_t polygons = 0;  ///< the polygons they became
};

/// Merges each edge-connected group of one-loop facets without holes, whose neighbours across
/// their shared sides are exactly coplanar (every corner on the other's plane, by the exact
/// orient3d) and carry the same marker, into one facet: the group's boundary as its loops, the
/// outer loop first, and a hole point strictly inside each inner loop. A side is shared when
/// exactly two facets have it. Corners inside the group stay points of the PLC (the CDT keeps
/// every point) and lie inside the polygon. A group is left as it is when its boundary passes
/// through a corner twice (a pinch) or no hole point with double coordinates is found; the merged
/// facet keeps the marker, line and number of the group's first facet. Meant for a surface mesh
/// that passed require_valid_surface: no two of its facets overlap.
CoplanarMerge merge_coplanar_facets(Plc& plc);

}  // namespace cavity::core
