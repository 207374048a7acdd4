#include "cavity/core/edit/gift_wrap.h"

#include <algorithm>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/geometry/duplicates.h"
#include "gift_wrap_engine.h"

namespace cavity::core {

namespace {

/// x in the closed tetrahedron t: no facet has x strictly on its outer side.
bool contains(const Geometry& g, const TetVertices& t, const Point3& x) {
    for (std::size_t k = 0; k < 4; ++k) {
        std::array<Point3, 4> p{g.point(t[0]), g.point(t[1]), g.point(t[2]), g.point(t[3])};
        p[k] = x;
        if (Geometry::orient3d(p[0], p[1], p[2], p[3]) == Sign::kNeg) {
            return false;
        }
    }
    return true;
}

bool strictly_contains(const Geometry& g, const TetVertices& t, const Point3& x) {
    for (std::size_t k = 0; k < 4; ++k) {
        std::array<Point3, 4> p{g.point(t[0]), g.point(t[1]), g.point(t[2]), g.point(t[3])};
        p[k] = x;
        if (Geometry::orient3d(p[0], p[1], p[2], p[3]) != Sign::kPos) {
            return false;
        }
    }
    return true;
}

/// A point strictly inside t (a weighted mean with arbitrary weights, checked exactly).
Point3 interior_point(const Geometry& g, const TetVertices& t) {
    Random random(0x5eed);
    for (int attempt = 0; attempt < 64; ++attempt) {
        Point3 x{0, 0, 0};
        double total = 0;
        for (VertexId v : t) {
            const double w = 0.5 + random.uniform01();
            x.x += w * g.point(v).x;
            x.y += w * g.point(v).y;
            x.z += w * g.point(v).z;
            total += w;
        }
        x = {x.x / total, x.y / total, x.z / total};
        if (strictly_contains(g, t, x)) {
            return x;
        }
    }
    throw Error("gift-wrapping: no interior point found in the starting tetrahedron");
}

/// The seed walk of gift_wrap.h: returns a tetrahedron with no candidate in its perturbed
/// circumball, hence a tetrahedron of the perturbed Delaunay triangulation.
TetVertices seed_tetrahedron(const Geometry& g,
                             std::span<const VertexId> candidates,
                             TetVertices t,
                             RetriangulationCounters& counters) {
    const Point3 x = interior_point(g, t);
    const std::uint64_t limit = 16 * std::uint64_t{candidates.size()} + 1024;
    while (true) {
        if (++counters.seed_steps > limit) {
            throw Error("gift-wrapping: the seed walk did not settle");
        }
        VertexId e = kNoVertex;
        for (VertexId c : candidates) {
            if (std::find(t.begin(), t.end(), c) != t.end()) {
                continue;
            }
            ++counters.insphere_calls;
            if (g.conflicts_solid(t, c)) {
                e = c;
                break;
            }
        }
        if (e == kNoVertex) {
            return t;
        }
        // The lower faces of the lifted 5-point simplex are the positively oriented tetrahedra
        // with e in place of one vertex; they cover t, so one contains x.
        bool moved = false;
        for (std::size_t i = 0; i < 4 && !moved; ++i) {
            TetVertices n = t;
            n[i] = e;
            if (g.orient3d(n[0], n[1], n[2], n[3]) == Sign::kPos && contains(g, n, x)) {
                t = n;
                moved = true;
            }
        }
        if (!moved) {
            throw Error("gift-wrapping: the seed walk lost its interior point");
        }
    }
}

}  // namespace

GiftWrapResult gift_wrap_delaunay(const PointSet& points) {
    GiftWrapResult out;
    const auto first = first_occurrences(points.points, points.weights);
    std::vector<VertexId> candidates;
    for (std::uint32_t i = 0; i < first.size(); ++i) {
        if (first[i] == i) {
            candidates.push_back(i);
        } else {
            out.duplicates.push_back({i, first[i]});
        }
    }
    const Geometry geometry = geometry_by_index(points);
    const auto boot = find_bootstrap(points.points, candidates);
    TetVertices start{
        candidates[boot[0]], candidates[boot[1]], candidates[boot[2]], candidates[boot[3]]};
    if (geometry.orient3d(start[0], start[1], start[2], start[3]) == Sign::kNeg) {
        std::swap(start[0], start[1]);
    }
    const TetVertices seed = seed_tetrahedron(geometry, candidates, start, out.counters);

    detail::GiftWrapEngine engine(geometry, candidates, false, out.counters);
    for (int f = 0; f < 4; ++f) {
        engine.offer(facet_vertices(seed, f), seed[static_cast<std::size_t>(f)]);
    }
    engine.run();
    // The engine's orientation mirrored: the API hands out positive right-hand volume.
    out.tets.push_back({seed[1], seed[0], seed[2], seed[3]});
    for (const TetVertices& t : engine.tets()) {
        out.tets.push_back({t[1], t[0], t[2], t[3]});
    }
    ++out.counters.tets_created;
    out.hull_triangles = engine.hull_triangles();
    if (points.weighted()) {
        std::vector<bool> used(points.size(), false);
        for (const auto& t : out.tets) {
            for (auto v : t) {
                used[v] = true;
            }
        }
        for (VertexId v : candidates) {
            if (!used[v]) {
                out.redundant.push_back(v);
            }
        }
    }
    return out;
}

std::vector<TetVertices> gift_wrap_cavity(const Geometry& geometry,
                                          std::span<const TetVertices> boundary,
                                          std::span<const VertexId> candidates,
                                          bool ghost_allowed,
                                          RetriangulationCounters& counters) {
    detail::GiftWrapEngine engine(geometry, candidates, ghost_allowed, counters);
    for (const TetVertices& t : boundary) {
        engine.offer(facet_vertices(t, 3), t[3]);
    }
    engine.run();
    if (engine.hull_triangles() != 0) {
        throw Error("gift-wrapping failed: a cavity facet has no vertex in front of it");
    }
    return engine.tets();
}

}  // namespace cavity::core
