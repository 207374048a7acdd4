#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "cavity/core/edit/retriangulation_counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/input/plc.h"
#include "cavity/core/mesh/array_storage.h"

/// Polygon insertion by flips (Cheng, Dey & Shewchuk §5.8, FlipInsertPolygon with Certify).
///
/// Heights: every vertex is lifted to |v|^2, perturbed as everywhere in cavity (point i drops by
/// eps^(i+1)); the right vertices (positive side of the polygon's plane h) then rise as
/// kappa * d(v), with d(v) = n . (v - a) the exact, radical-free offset from h. The lifted
/// determinant of a facet's two tetrahedra is S(kappa) = S0 + kappa S1 + sum_k c_k eps^(k+1), so a
/// facet that becomes reflex (S1 > 0) does so at the exact time -S0/S1 + sum_k (c_k/S1)
/// eps^(k+1): events are ordered by that vector of rationals, lexicographically (GMP), never in
/// floating point. An event whose flip is inadmissible (a 3-2 flip around an edge of degree other
/// than 3, a 4-4 flip around an edge of degree other than 4, or a flip leaving the region R or
/// deleting a constrained facet) is held back and retried after the next flip.
namespace cavity::core {

/// The work of one FlipInsertPolygon call: Proposition 5.5 bounds its flips by m^2 and its events
/// by O(m^2) (so O(m^2 log m) time), m being the number of vertices of the region R.
struct PolygonWork {
    std::uint32_t facet = 0;            ///< 0-based index in Plc::facets
    std::uint64_t region_vertices = 0;  ///< m
    std::uint64_t region_tets = 0;      ///< |R| when the polygon is inserted
    /// Tetrahedra stepped through by step 1: for each loop side, the walk through the star of one
    /// end toward the other to a tetrahedron holding the side, then the ring of tetrahedra around
    /// the side.
    std::uint64_t rotary_steps = 0;
    /// Tetrahedra first tested by step 2's depth-first search (the neighbours of the tetrahedra
    /// that touch the polygon); with the rings of step 1, every tetrahedron steps 1-2 look at.
    std::uint64_t search_visited = 0;
    std::uint64_t flips = 0;  ///< flips performed
    std::uint64_t events_queued = 0;
};

/// Work of polygon insertion, for Propositions 5.5-5.6 (fewer than m^2 flips, O(m^2 log m) events).
struct PolygonInsertionCounters {
    std::uint64_t polygons = 0;
    std::uint64_t region_tets = 0;      ///< tetrahedra crossing a polygon when it is inserted (R)
    std::uint64_t region_vertices = 0;  ///< m summed over polygons: distinct vertices of R
    std::uint64_t rotary_steps = 0;     ///< PolygonWork::rotary_steps summed over polygons
    std::uint64_t search_visited = 0;   ///< PolygonWork::search_visited summed over polygons
    std::uint64_t certify_calls = 0;
    std::uint64_t events_queued = 0;
    std::uint64_t events_stale = 0;  ///< dequeued after their facet had gone
    std::uint64_t events_held = 0;   ///< held back as inadmissible (each time)
    std::uint64_t max_region_vertices = 0;
    RetriangulationCounters flips;
    std::vector<PolygonWork> per_polygon;  ///< one record per inserted polygon, in order
};

/// Triangles of the complex that lie in a polygon, as sorted vertex triples.
using ConstrainedFaces = std::set<std::array<VertexId, 3>>;

/// Inserts facet `facet` of `plc` into the live complex `storage` (vertex id = input index, all of
/// the PLC's points present, every edge of the facet already an edge of the complex), flipping
/// only tetrahedra that cross it. Facets listed in `constrained` are never flipped; the triangles
/// of the inserted polygon are added to it and returned.
/// \throws Error naming the facet when the queue runs dry with inadmissible flips left or a
/// tetrahedron still crosses the polygon (the PLC has no CDT, or is not edge-protected).
std::vector<std::array<VertexId, 3>> insert_polygon(ArrayStorage& storage,
                                                    const Geometry& geometry,
                                                    const Plc& plc,
                                                    std::size_t facet,
                                                    ConstrainedFaces& constrained,
                                                    PolygonInsertionCounters& counters);

/// Steps 1-2 of FlipInsertPolygon alone, leaving the complex unchanged: the region R of facet
/// `facet` (the solid tetrahedra whose interiors meet the polygon), found as insert_polygon finds
/// it, by rotary searches around the polygon's sides and a depth-first search of the tetrahedra
/// touching it. When `work` is given, it receives the facet, m, |R|, rotary_steps and
/// search_visited (flips and events stay 0).
std::vector<TetId> polygon_region(const ArrayStorage& storage,
                                  const Geometry& geometry,
                                  const Plc& plc,
                                  std::size_t facet,
                                  PolygonWork* work = nullptr);

}  // namespace cavity::core
