#include "cavity/core/check/complex_from_tets.h"

#include <algorithm>
#include <map>
#include <numeric>

#include "cavity/core/base/error.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/mesh/star.h"

namespace cavity::core {

namespace {

using Triangle = std::array<VertexId, 3>;

Triangle sorted(Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
}

std::string name(VertexId v) {
    return v == kGhostVertex ? "g" : std::to_string(v);
}

std::string tet_name(const TetVertices& t) {
    return "(" + name(t[0]) + " " + name(t[1]) + " " + name(t[2]) + " " + name(t[3]) + ")";
}

}  // namespace

ArrayStorage complex_from_tets(std::span<const std::array<std::uint32_t, 4>> tets) {
    std::size_t point_count = 0;
    for (const auto& t : tets) {
        point_count = std::max(point_count, std::size_t{*std::max_element(t.begin(), t.end())} + 1);
    }
    // The one facet matcher (io/tet_adjacency.h) pairs the solid facets. Mirroring a tetrahedron
    // keeps its triangles, so the pairing of the tetrahedra as given is the stored ones'.
    return complex_from_tets(tets, match_facets(tets, point_count));
}

ArrayStorage complex_from_tets(std::span<const std::array<std::uint32_t, 4>> tets,
                               std::span<const std::int32_t> across) {
    ArrayStorage storage;
    std::vector<Tet> stored;
    stored.reserve(tets.size());
    for (const auto& t : tets) {
        stored.push_back({t[1], t[0], t[2], t[3]});  // positive volume → orient3d > 0
        storage.add_tetrahedron(stored.back());
    }
    // Slots 0 and 1 swap places in the stored order, and with them the facets opposite them.
    constexpr std::array<std::size_t, 4> kGivenSlot{1, 0, 2, 3};
    std::vector<HalfFacet> boundary;
    for (TetId t = 0; t < stored.size(); ++t) {
        for (int f = 0; f < 4; ++f) {
            const std::int32_t other =
                across[4 * std::size_t{t} + kGivenSlot[static_cast<std::size_t>(f)]];
            if (other < 0) {
                boundary.push_back(half_facet(t, f));
                continue;
            }
            const auto n = static_cast<TetId>(other);
            if (n < t) {
                continue;  // glued from n's side
            }
            // n's facet on this triangle is the one opposite its vertex not in t.
            int g = 0;
            while (g < 4 && slot_of(stored[t], stored[n][static_cast<std::size_t>(g)]) >= 0) {
                ++g;
            }
            if (g == 4) {
                throw Error("tetrahedron " + tet_name(tets[t]) + " is listed twice");
            }
            storage.glue(half_facet(t, f), half_facet(n, g));
        }
    }
    // Ghosts in the order of their sorted triangles, whatever the input's order of tetrahedra.
    std::sort(boundary.begin(), boundary.end(), [&](HalfFacet a, HalfFacet b) {
        return sorted(facet_vertices(storage.vertices(tet_of(a)), facet_of(a))) <
               sorted(facet_vertices(storage.vertices(tet_of(b)), facet_of(b)));
    });
    // A ghost over each boundary triangle, facing out: the triangle reversed, ghost in front.
    for (HalfFacet h : boundary) {
        const Triangle tri = facet_vertices(storage.vertices(tet_of(h)), facet_of(h));
        const TetId g = storage.add_tetrahedron({tri[1], tri[0], tri[2], kGhostVertex});
        storage.glue(half_facet(g, 3), h);
    }
    // The ghosts' own facets (a hull edge and the ghost vertex) pair up among the ghosts, by
    // their hull edge.
    std::map<Triangle, HalfFacet> open;
    for (auto g = static_cast<TetId>(stored.size()); g < storage.capacity(); ++g) {
        for (int f = 0; f < 3; ++f) {
            const Triangle key = sorted(facet_vertices(storage.vertices(g), f));
            const auto [it, inserted] = open.emplace(key, half_facet(g, f));
            if (inserted) {
                continue;
            }
            if (it->second == kNoHalfFacet) {
                throw Error("hull edge " + name(key[0]) + " " + name(key[1]) +
                            " belongs to more than two hull triangles");
            }
            storage.glue(it->second, half_facet(g, f));
            it->second = kNoHalfFacet;
        }
    }
    for (const auto& [key, h] : open) {
        if (h != kNoHalfFacet) {
            throw Error("the boundary of the tetrahedra is not closed at edge " + name(key[0]) +
                        " " + name(key[1]));
        }
    }
    return storage;
}

std::vector<std::array<std::uint32_t, 4>> solid_tets(const ArrayStorage& storage) {
    std::vector<std::array<std::uint32_t, 4>> out;
    for (TetId t = 0; t < storage.capacity(); ++t) {
        if (storage.alive(t) && !is_ghost(storage.vertices(t))) {
            const TetVertices& v = storage.vertices(t);
            out.push_back({v[1], v[0], v[2], v[3]});  // orient3d > 0 → positive volume
        }
    }
    return out;
}

std::vector<std::string> check_complex(const ArrayStorage& storage, const Geometry& geometry) {
    std::vector<std::string> problems;
    for (TetId t = 0; t < storage.capacity(); ++t) {
        if (!storage.alive(t)) {
            continue;
        }
        const TetVertices& v = storage.vertices(t);
        for (int s = 0; s < 3; ++s) {
            if (v[static_cast<std::size_t>(s)] == kGhostVertex) {
                problems.push_back("tetrahedron " + tet_name(v) + ": ghost vertex not in slot 3");
            }
        }
        if (!is_ghost(v) && geometry.orient3d(v[0], v[1], v[2], v[3]) != Sign::kPos) {
            // Named as the API lists it (positive right-hand volume), the stored order mirrored.
            problems.push_back("tetrahedron " + tet_name({v[1], v[0], v[2], v[3]}) +
                               ": volume not positive (right-hand rule)");
        }
        for (int f = 0; f < 4; ++f) {
            const HalfFacet h = storage.adjacent(t, f);
            if (h == kNoHalfFacet) {
                problems.push_back("facet " + std::to_string(f) + " of " + tet_name(v) +
                                   " is not glued");
                continue;
            }
            if (storage.adjacent(tet_of(h), facet_of(h)) != half_facet(t, f)) {
                problems.push_back("adjacency across facet " + std::to_string(f) + " of " +
                                   tet_name(v) + " is not symmetric");
            }
            const Triangle mine = facet_vertices(v, f);
            const TetVertices& w = storage.vertices(tet_of(h));
            const Triangle theirs = facet_vertices(w, facet_of(h));
            const bool opposite = (theirs == Triangle{mine[1], mine[0], mine[2]}) ||
                                  (theirs == Triangle{mine[0], mine[2], mine[1]}) ||
                                  (theirs == Triangle{mine[2], mine[1], mine[0]});
            if (!opposite) {
                problems.push_back("facet " + std::to_string(f) + " of " + tet_name(v) +
                                   " is glued to a different or equally oriented triangle of " +
                                   tet_name(w));
            }
            // Hull convexity: the apex across each facet of a ghost is not in front of its hull
            // triangle (facet 3: the solid apex behind; facets 0-2: the neighbouring hull
            // triangles' third vertices).
            const VertexId apex = w[static_cast<std::size_t>(facet_of(h))];
            if (is_ghost(v) && apex != kGhostVertex &&
                geometry.orient3d(v[0], v[1], v[2], apex) == Sign::kPos) {
                problems.push_back("hull triangle of " + tet_name(v) + " has vertex " + name(apex) +
                                   " in front: the hull is not convex");
            }
        }
    }
    return problems;
}

Geometry geometry_by_index(const PointSet& points) {
    std::vector<std::uint32_t> keys(points.size());
    std::iota(keys.begin(), keys.end(), 0u);
    return Geometry(points.points, std::move(keys), points.weights, points.exact);
}

}  // namespace cavity::core
