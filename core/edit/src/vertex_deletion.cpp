#include "cavity/core/edit/vertex_deletion.h"

#include <algorithm>
#include <string>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/edit/gift_wrap.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/mesh/replace_tetrahedra.h"
#include "cavity/core/mesh/star.h"

namespace cavity::core {

std::vector<TetId> delete_vertex(ArrayStorage& storage,
                                 const Geometry& geometry,
                                 VertexId v,
                                 std::span<const VertexId> submerged,
                                 RetriangulationCounters* counters) {
    const std::vector<TetId> star = vertex_star(storage, v);
    if (v == kGhostVertex || star.empty()) {
        throw Error("point " + std::to_string(v) + " is not a vertex of the triangulation");
    }
    std::vector<TetVertices> boundary;
    std::vector<VertexId> candidates(submerged.begin(), submerged.end());
    bool on_hull = false;
    for (TetId t : star) {
        const TetVertices& w = storage.vertices(t);
        on_hull = on_hull || is_ghost(w);
        const HalfFacet h = storage.adjacent(t, slot_of(w, v));
        // The tetrahedron outside, rotated so that its facet on the cavity is facet 3.
        const TetVertices& o = storage.vertices(tet_of(h));
        const auto tri = facet_vertices(o, facet_of(h));
        boundary.push_back({tri[0], tri[1], tri[2], o[static_cast<std::size_t>(facet_of(h))]});
        for (VertexId x : w) {
            if (x != v && x != kGhostVertex &&
                std::find(candidates.begin(), candidates.end(), x) == candidates.end()) {
                candidates.push_back(x);
            }
        }
    }
    const std::vector<TetVertices> fresh =
        gift_wrap_cavity(geometry, boundary, candidates, on_hull, counters);
    std::vector<TetId> ids = replace_tetrahedra(storage, star, fresh);
    if (ids.empty()) {
        throw Error("deleting point " + std::to_string(v) +
                    ": the gift-wrapped cavity does not match its boundary");
    }
    CAVITY_EXPENSIVE_CHECK(check_complex(storage, geometry), "the complex after a deletion");
    if (counters != nullptr) {
        ++counters->vertices_deleted;
        counters->tets_deleted += star.size();
    }
    return ids;
}

Triangulation delete_vertices(const PointSet& points,
                              const Triangulation& triangulation,
                              std::span<const std::uint32_t> ids,
                              RetriangulationCounters* counters) {
    // Messages number points as the input file does.
    const auto numbered = [&](std::uint32_t id) {
        return std::to_string(std::uint64_t{id} + static_cast<std::uint64_t>(points.index_base));
    };
    std::vector<bool> gone(points.size(), false);
    for (std::uint32_t id : ids) {
        if (id >= points.size()) {
            throw Error("cannot delete point " + numbered(id) + ": there are only " +
                        std::to_string(points.size()) + " points");
        }
        if (gone[id]) {
            throw Error("point " + numbered(id) + " is listed twice for deletion");
        }
        gone[id] = true;
    }
    Triangulation out;
    for (const auto& d : triangulation.duplicates) {
        if (!gone[d[0]] && gone[d[1]]) {
            throw Error("cannot delete point " + numbered(d[1]) + ": point " + numbered(d[0]) +
                        " repeats it and is kept (delete the repeats too, or keep both)");
        }
        if (!gone[d[0]]) {
            out.duplicates.push_back(d);
        }
    }
    // The remaining points must still span 3D.
    std::vector<std::uint32_t> remaining;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        if (!gone[i]) {
            remaining.push_back(i);
        }
    }
    find_bootstrap(points.points, remaining);

    const Geometry geometry = geometry_by_index(points);
    ArrayStorage storage = complex_from_tets(triangulation.tets);
    std::vector<VertexId> submerged;
    for (std::uint32_t r : triangulation.redundant) {
        if (!gone[r]) {
            submerged.push_back(r);
        }
    }
    std::vector<bool> is_duplicate(points.size(), false);
    for (const auto& d : triangulation.duplicates) {
        is_duplicate[d[0]] = true;
    }
    for (std::uint32_t id : ids) {
        const bool redundant =
            std::binary_search(triangulation.redundant.begin(), triangulation.redundant.end(), id);
        if (is_duplicate[id] || redundant) {
            continue;
        }
        const std::vector<TetId> fresh = delete_vertex(storage, geometry, id, submerged, counters);
        // Submerged points that the deletion uncovered are vertices now.
        std::erase_if(submerged, [&](VertexId s) {
            return std::any_of(fresh.begin(), fresh.end(), [&](TetId t) {
                return slot_of(storage.vertices(t), s) >= 0;
            });
        });
    }
    out.tets = solid_tets(storage);
    out.redundant = std::move(submerged);
    std::sort(out.redundant.begin(), out.redundant.end());
    for (TetId t = 0; t < storage.capacity(); ++t) {
        if (storage.alive(t) && is_ghost(storage.vertices(t))) {
            ++out.hull_triangles;
        }
    }
    out.storage_bytes = storage.bytes();
    return out;
}

}  // namespace cavity::core
