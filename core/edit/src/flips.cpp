#include "cavity/core/edit/flips.h"

#include <algorithm>

#include "cavity/core/base/assert.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/mesh/replace_tetrahedra.h"
#include "cavity/core/mesh/star.h"

namespace cavity::core {

namespace {

/// Tetrahedron t with vertex `drop` replaced by `apex`, ghost moved to slot 3. The orientation is
/// kept because apex lies on the same side of the facet opposite `drop` as drop did (the new
/// tetrahedron is inside the flipped region and shares that facet with its boundary).
TetVertices replaced(const TetVertices& t, VertexId drop, VertexId apex) {
    TetVertices v = t;
    v[static_cast<std::size_t>(slot_of(t, drop))] = apex;
    const int g = slot_of(v, kGhostVertex);
    return g >= 0 ? rotate_to_last(v, g) : v;
}

/// The exact validity test described in flips.h.
bool valid_replacement(const ArrayStorage& storage,
                       const Geometry& geometry,
                       const std::vector<TetId>& old_tets,
                       const std::vector<TetVertices>& new_tets) {
    std::vector<VertexId> witnesses;
    const auto add = [&](VertexId v) {
        if (v != kGhostVertex &&
            std::find(witnesses.begin(), witnesses.end(), v) == witnesses.end()) {
            witnesses.push_back(v);
        }
    };
    for (const TetVertices& t : new_tets) {
        for (VertexId v : t) {
            add(v);
        }
    }
    for (TetId t : old_tets) {
        for (int f = 0; f < 4; ++f) {
            const HalfFacet h = storage.adjacent(t, f);
            if (h != kNoHalfFacet &&
                std::find(old_tets.begin(), old_tets.end(), tet_of(h)) == old_tets.end()) {
                add(storage.vertices(tet_of(h))[static_cast<std::size_t>(facet_of(h))]);
            }
        }
    }
    for (const TetVertices& t : new_tets) {
        if (!is_ghost(t)) {
            if (geometry.orient3d(t[0], t[1], t[2], t[3]) != Sign::kPos) {
                return false;
            }
            continue;
        }
        for (VertexId x : witnesses) {
            if (x != t[0] && x != t[1] && x != t[2] &&
                geometry.orient3d(t[0], t[1], t[2], x) == Sign::kPos) {
                return false;
            }
        }
    }
    return true;
}

/// True when vertex v has a ghost tetrahedron around it (v is on the hull).
bool on_hull(const ArrayStorage& storage, VertexId v) {
    for (TetId t : vertex_star(storage, v)) {
        if (is_ghost(storage.vertices(t))) {
            return true;
        }
    }
    return false;
}

std::vector<TetId> apply(ArrayStorage& storage,
                         const Geometry& geometry,
                         const std::vector<TetId>& old_tets,
                         const std::vector<TetVertices>& new_tets,
                         FlipKind kind,
                         RetriangulationCounters& counters) {
    std::vector<TetId> ids;
    if (valid_replacement(storage, geometry, old_tets, new_tets)) {
        ids = replace_tetrahedra(storage, old_tets, new_tets);
        CAVITY_EXPENSIVE_CHECK(check_complex(storage, geometry), "the complex after a flip");
    }
    if (ids.empty()) {
        ++counters.flips_refused;
    } else {
        ++counters.flips[static_cast<std::size_t>(kind)];
        counters.tets_created += new_tets.size();
        counters.tets_deleted += old_tets.size();
    }
    return ids;
}

std::vector<TetId> refuse(RetriangulationCounters& counters) {
    ++counters.flips_refused;
    return {};
}

}  // namespace

std::vector<TetId> flip23(ArrayStorage& storage,
                          const Geometry& geometry,
                          HalfFacet h,
                          RetriangulationCounters& counters) {
    const TetId t1 = tet_of(h);
    const int f1 = facet_of(h);
    const HalfFacet across = storage.adjacent(t1, f1);
    if (!storage.alive(t1) || across == kNoHalfFacet) {
        return refuse(counters);
    }
    const TetVertices& a = storage.vertices(t1);
    const VertexId d = a[static_cast<std::size_t>(f1)];
    const VertexId e = storage.vertices(tet_of(across))[static_cast<std::size_t>(facet_of(across))];
    // The new edge d e must not exist yet. Through the interior it cannot (it would cross the
    // shared triangle); to the ghost vertex it exists exactly when the other end is on the hull.
    if ((d == kGhostVertex && on_hull(storage, e)) || (e == kGhostVertex && on_hull(storage, d))) {
        return refuse(counters);
    }
    std::vector<TetVertices> fresh;
    for (int j = 0; j < 4; ++j) {
        if (j != f1) {
            fresh.push_back(replaced(a, a[static_cast<std::size_t>(j)], e));
        }
    }
    return apply(storage, geometry, {t1, tet_of(across)}, fresh, FlipKind::k23, counters);
}

std::vector<TetId> flip32(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          int i,
                          int j,
                          RetriangulationCounters& counters) {
    const EdgeRing ring = edge_ring(storage, t, i, j);
    if (ring.tets.size() != 3) {
        return refuse(counters);
    }
    const TetVertices& first = storage.vertices(ring.tets[0]);
    const std::vector<TetVertices> fresh{replaced(first, ring.v, ring.ring[2]),
                                         replaced(first, ring.u, ring.ring[2])};
    return apply(storage, geometry, ring.tets, fresh, FlipKind::k32, counters);
}

std::vector<TetId> flip14(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          VertexId p,
                          RetriangulationCounters& counters) {
    if (!storage.alive(t)) {
        return refuse(counters);
    }
    const TetVertices& a = storage.vertices(t);
    std::vector<TetVertices> fresh;
    for (VertexId x : a) {
        fresh.push_back(replaced(a, x, p));
    }
    return apply(storage, geometry, {t}, fresh, FlipKind::k14, counters);
}

std::vector<TetId> flip41(ArrayStorage& storage,
                          const Geometry& geometry,
                          VertexId p,
                          RetriangulationCounters& counters) {
    const std::vector<TetId> star = vertex_star(storage, p);
    if (p == kGhostVertex || star.size() != 4) {
        return refuse(counters);
    }
    const TetVertices& a = storage.vertices(star[0]);
    // The link vertex missing from the first tetrahedron takes p's place in it.
    VertexId missing = kNoVertex;
    for (VertexId x : storage.vertices(star[1])) {
        if (x != p && slot_of(a, x) < 0) {
            missing = x;
        }
    }
    if (missing == kNoVertex) {
        return refuse(counters);
    }
    return apply(storage, geometry, star, {replaced(a, p, missing)}, FlipKind::k41, counters);
}

namespace {

std::vector<TetId> flip_ring4(ArrayStorage& storage,
                              const Geometry& geometry,
                              const EdgeRing& ring,
                              int diagonal,
                              FlipKind kind,
                              RetriangulationCounters& counters) {
    const auto at = [&](int k) { return ring.ring[static_cast<std::size_t>(k % 4)]; };
    const VertexId wb = at(diagonal + 2);
    if (at(diagonal) == kGhostVertex || wb == kGhostVertex) {
        return refuse(counters);
    }
    // tets[diagonal] holds (w_a, ring[diagonal+1]) and tets[diagonal+3] holds (ring[diagonal+3],
    // w_a): in each, w_b takes the place of either end of the old edge.
    std::vector<TetVertices> fresh;
    for (int k : {diagonal, diagonal + 3}) {
        const TetVertices& old = storage.vertices(ring.tets[static_cast<std::size_t>(k % 4)]);
        fresh.push_back(replaced(old, ring.v, wb));
        fresh.push_back(replaced(old, ring.u, wb));
    }
    return apply(storage, geometry, ring.tets, fresh, kind, counters);
}

}  // namespace

std::vector<TetId> flip44(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          int i,
                          int j,
                          int diagonal,
                          RetriangulationCounters& counters) {
    const EdgeRing ring = edge_ring(storage, t, i, j);
    if (ring.tets.size() != 4 || (diagonal != 0 && diagonal != 1)) {
        return refuse(counters);
    }
    return flip_ring4(storage, geometry, ring, diagonal, FlipKind::k44, counters);
}

std::vector<TetId> flip22(ArrayStorage& storage,
                          const Geometry& geometry,
                          TetId t,
                          int i,
                          int j,
                          RetriangulationCounters& counters) {
    const EdgeRing ring = edge_ring(storage, t, i, j);
    const auto g = std::find(ring.ring.begin(), ring.ring.end(), kGhostVertex);
    if (ring.tets.size() != 4 || g == ring.ring.end() || ring.u == kGhostVertex ||
        ring.v == kGhostVertex) {
        return refuse(counters);
    }
    // The four ring vertices other than the ghost's opposite must be coplanar with the edge: the
    // two solid tetrahedra stand on a flat quadrilateral.
    const int m = static_cast<int>(g - ring.ring.begin());
    const VertexId wa = ring.ring[static_cast<std::size_t>((m + 1) % 4)];
    const VertexId wb = ring.ring[static_cast<std::size_t>((m + 3) % 4)];
    if (geometry.orient3d(ring.u, ring.v, wa, wb) != Sign::kZero) {
        return refuse(counters);
    }
    return flip_ring4(storage, geometry, ring, (m + 1) % 2, FlipKind::k22, counters);
}

}  // namespace cavity::core
