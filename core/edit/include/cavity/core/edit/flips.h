#pragma once

#include <vector>

#include "cavity/core/edit/retriangulation_counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/array_storage.h"

/// Bistellar flips on the array storage (Cheng, Dey & Shewchuk §4.4, Figure 4.7): each replaces the
/// upper faces of a 4-simplex (five vertices, one of which may be the ghost vertex) by its lower
/// faces, or the reverse. Ghost tetrahedra make the complex a triangulation of the 3-sphere, so a
/// flip that touches the hull is the same combinatorial move with the ghost among the five.
///
/// Every flip checks, exactly, that the new tetrahedra are valid before changing anything: each new
/// solid tetrahedron is positively oriented, and each new hull triangle has every vertex of the
/// flip (and every apex just outside it) behind or on its plane, so the hull stays locally convex.
/// A flip that fails the check returns an empty vector and leaves the storage unchanged. On success
/// the new tetrahedra are glued to each other and to the outside, and their ids are returned.
/// Vertex ids index `geometry`; `counters` receives the flip (or its refusal).
namespace cavity::core {

/// 2-3: the two tetrahedra sharing the triangle of half-facet h become three around the edge
/// joining their apices.
std::vector<TetId> flip23(ArrayStorage& storage,
                          const Geometry& geometry,
                          HalfFacet h,
                          RetriangulationCounters& counters);

/// 3-2: the three tetrahedra around edge (t[i], t[j]) become two sharing the triangle of its ring.
/// Refused unless the edge has degree 3.
std::vector<TetId> flip32(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          int i,
                          int j,
                          RetriangulationCounters& counters);

/// 1-4: inserts the new vertex p (not yet in the triangulation) into tetrahedron t, which must
/// contain it in its interior; for a ghost t, p must lie strictly in front of its hull triangle.
std::vector<TetId> flip14(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          VertexId p,
                          RetriangulationCounters& counters);

/// 4-1: removes vertex p of degree 4 (exactly four tetrahedra around it, ghosts included).
std::vector<TetId> flip41(ArrayStorage& storage,
                          const Geometry& geometry,
                          VertexId p,
                          RetriangulationCounters& counters);

/// 4-4: the four tetrahedra around edge (t[i], t[j]), whose ring is r0 r1 r2 r3, become four around
/// the diagonal r0 r2 (diagonal 0) or r1 r3 (diagonal 1). Refused unless the edge has degree 4 and
/// the diagonal avoids the ghost vertex.
std::vector<TetId> flip44(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          int i,
                          int j,
                          int diagonal,
                          RetriangulationCounters& counters);

/// 2-2: edge (t[i], t[j]) is a diagonal of a flat quadrilateral on the hull, shared by two solid
/// tetrahedra; they become the two over the other diagonal (with the two ghosts behind: a 4-4 flip
/// whose ring holds the ghost vertex). Refused unless the ring is such a quadrilateral.
std::vector<TetId> flip22(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          int i,
                          int j,
                          RetriangulationCounters& counters);

}  // namespace cavity::core
