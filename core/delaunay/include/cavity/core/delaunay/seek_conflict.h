#pragma once

#include <algorithm>
#include <vector>

#include "cavity/core/delaunay/bowyer_watson.h"

namespace cavity::core {

/// What point location found for a new vertex u.
struct ConflictSeed {
    TetId tet = kNoTet;              ///< a tetrahedron in conflict with u: where the cavity starts
    VertexId duplicate = kNoVertex;  ///< u repeats this vertex (same coordinates, same weight)
};

/// From a cell whose closure contains u (a solid tetrahedron, or a ghost whose hull triangle u is
/// on or in front of), finds where the cavity starts. Unweighted, that cell is always in conflict
/// unless u repeats one of its vertices: a point of a closed tetrahedron other than its vertices is
/// strictly inside the circumball. Weighted, u may be redundant (submerged: its lifted point is
/// above the lower hull), and the cell holding u may not conflict while a neighbour around a face,
/// edge or vertex through u does; so every cell whose closure contains u is tried. No conflicting
/// cell at all means u is redundant: `tet` stays kNoTet.
///
/// An implicit u (geometry.h) was located by its rounded coordinates, which may lie in a cell
/// next to the ones its exact point conflicts with; its search crosses every face, nearest cells
/// first, and stops at the first conflict (there is one: u is not a vertex). It never repeats a
/// vertex: an implicit point is distinct from every other point by construction.
template <class Storage, class Observer>
ConflictSeed seek_conflict(BowyerWatson<Storage, Observer>& engine,
                           VertexId u,
                           TetId located,
                           std::vector<TetId>& scratch) {
    Storage& storage = engine.storage();
    const Geometry& geometry = engine.geometry();
    const Point3& p = geometry.point(u);
    const bool implicit = geometry.implicit(u);
    const auto repeats = [&](VertexId w) {
        if (w == kGhostVertex || implicit || geometry.implicit(w)) {
            return false;
        }
        const Point3& q = geometry.point(w);
        if (q.x != p.x || q.y != p.y || q.z != p.z) {
            return false;
        }
        return !geometry.weighted() || geometry.weighted_point(w).w == geometry.weighted_point(u).w;
    };
    for (VertexId w : storage.vertices(located)) {
        if (repeats(w)) {
            return {kNoTet, w};
        }
    }
    if (engine.conflicts(located, u)) {
        return {located, kNoVertex};
    }
    scratch.assign(1, located);
    for (std::size_t i = 0; i < scratch.size(); ++i) {
        const TetId t = scratch[i];
        const TetVertices v = storage.vertices(t);
        for (int f = 0; f < 4; ++f) {
            if (is_ghost(v) && f != 3) {
                continue;  // only the hull triangle of a ghost is a real face
            }
            const auto tri = facet_vertices(v, f);
            if (!implicit && engine.geometry().orient3d(
                                 tri[0], tri[1], tri[2], u, engine.tally()) != Sign::kZero) {
                continue;
            }
            const TetId next = tet_of(storage.adjacent(t, f));
            if (std::find(scratch.begin(), scratch.end(), next) != scratch.end()) {
                continue;
            }
            for (VertexId w : storage.vertices(next)) {
                if (repeats(w)) {
                    return {kNoTet, w};
                }
            }
            if (engine.conflicts(next, u)) {
                return {next, kNoVertex};
            }
            scratch.push_back(next);
        }
    }
    return {};
}

}  // namespace cavity::core
