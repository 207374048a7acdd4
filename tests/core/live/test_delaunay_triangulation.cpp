// The live triangulation: built as triangulate() builds, it stays equal to the triangulation
// rebuilt from scratch through insertions, deletions and flips, and its views equal the ones
// derived from the bare list of tetrahedra.
#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"

namespace cavity::core {
namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;
using test::canonical;

std::vector<std::uint32_t> identity(std::size_t n) {
    std::vector<std::uint32_t> sequence(n);
    std::iota(sequence.begin(), sequence.end(), 0u);
    return sequence;
}

DelaunayTriangulation live_in_input_order(const PointSet& ps) {
    return DelaunayTriangulation(ps, identity(ps.size()), TriangulateOptions{});
}

/// The first `count` points of ps (with their weights).
PointSet head(const PointSet& ps, std::size_t count) {
    PointSet out;
    out.points.assign(ps.points.begin(), ps.points.begin() + static_cast<std::ptrdiff_t>(count));
    if (ps.weighted()) {
        out.weights.assign(ps.weights.begin(),
                           ps.weights.begin() + static_cast<std::ptrdiff_t>(count));
    }
    return out;
}

TEST(DelaunayTriangulation, ReleaseEqualsTriangulateForEveryLocator) {
    const PointSet ps = generate_points("ball", 2000, 3);
    OrderOptions order_options;
    order_options.kind = OrderKind::kBrio;
    order_options.seed = 5;
    const InsertionOrder order = make_insertion_order(ps.points, order_options);
    for (const auto& locate : kLocateKinds) {
        TriangulateOptions options;
        options.locate = locate.kind;
        options.count = true;
        DelaunayTriangulation dt(ps, order.sequence, options);
        EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty()) << locate.name;
        EXPECT_EQ(dt.tet_count() + dt.hull_triangle_count(), dt.storage().live_count());
        const Counters counters = dt.counters();
        const Triangulation released = std::move(dt).release();
        const Triangulation batch = triangulate(ps, order.sequence, options);
        EXPECT_EQ(released.tets, batch.tets) << locate.name;
        EXPECT_EQ(released.hull_triangles, batch.hull_triangles);
        EXPECT_EQ(counters.tets_created, batch.counters.tets_created);
        EXPECT_GT(counters.tets_created, 0u);
    }
}

TEST(DelaunayTriangulation, HashStorageIsForTheBatchFunction) {
    const PointSet ps = generate_points("cube", 50, 1);
    TriangulateOptions options;
    options.storage = StorageKind::kHash;
    EXPECT_THROW(DelaunayTriangulation(ps, identity(ps.size()), options), Error);
}

/// The adjacency read off the live complex equals the one matched from the list of tetrahedra:
/// the same simplices, the same neighbour across every facet, the same oriented hull triangles.
TEST(DelaunayTriangulation, AdjacencyEqualsTheMatchedOne) {
    for (const char* dist : {"cube", "grid", "sphere"}) {
        const PointSet ps = generate_points(dist, 1000, 7);
        const DelaunayTriangulation dt = live_in_input_order(ps);
        const Adjacency live = dt.adjacency();
        const Adjacency matched = build_adjacency(dt.tets(), identity(ps.size()));
        ASSERT_EQ(live.simplices.size(), matched.simplices.size()) << dist;
        // Each simplex (as given, oriented) with its four neighbours as simplices.
        const auto described = [](const Adjacency& a) {
            std::map<Tet, std::array<Tet, 4>> out;
            for (std::size_t t = 0; t < a.simplices.size(); ++t) {
                std::array<Tet, 4> across{};
                for (std::size_t i = 0; i < 4; ++i) {
                    const std::int32_t o = a.neighbors[4 * t + i];
                    across[i] = o < 0 ? Tet{} : a.simplices[static_cast<std::size_t>(o)];
                }
                out[a.simplices[t]] = across;
            }
            return out;
        };
        EXPECT_EQ(described(live), described(matched)) << dist;
        const auto rotated = [](std::vector<std::array<std::int32_t, 3>> hull) {
            for (auto& h : hull) {
                std::rotate(h.begin(), std::min_element(h.begin(), h.end()), h.end());
            }
            std::sort(hull.begin(), hull.end());
            return hull;
        };
        EXPECT_EQ(rotated(live.hull), rotated(matched.hull)) << dist;
        EXPECT_EQ(live.hull.size(), dt.hull_triangle_count());
        for (std::uint32_t v = 0; v < ps.size(); ++v) {
            const std::int32_t t = live.vertex_to_simplex[v];
            ASSERT_GE(t, 0);
            const Tet& tet = live.simplices[static_cast<std::size_t>(t)];
            EXPECT_NE(std::find(tet.begin(), tet.end(), v), tet.end());
        }
    }
}

/// Points inserted one by one after the build give the triangulation of all of them, repeats and
/// submerged weighted points included.
TEST(DelaunayTriangulation, InsertionsEqualTheBatchOfAllPoints) {
    for (const char* dist : {"cube", "grid"}) {
        PointSet ps = generate_points(dist, 600, 11);
        ps.points.push_back(ps.points[17]);  // a repeat, inserted late
        DelaunayTriangulation dt = live_in_input_order(head(ps, 300));
        for (std::size_t i = 300; i < ps.size(); ++i) {
            EXPECT_EQ(dt.insert(ps.points[i]), i);
        }
        EXPECT_EQ(dt.point_count(), ps.size());
        EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty()) << dist;
        const Triangulation batch = test::triangulate_in_input_order(ps);
        EXPECT_EQ(canonical(dt.tets()), canonical(batch.tets)) << dist;
        ASSERT_EQ(dt.duplicates().size(), 1u);
        const auto last = static_cast<std::uint32_t>(ps.size() - 1);
        EXPECT_EQ(dt.duplicates()[0], (std::array<std::uint32_t, 2>{last, 17}));
    }
    const PointSet weighted = generate_points("cube", 400, 2, parse_weight_spec("uniform:0:0.1"));
    DelaunayTriangulation dt = live_in_input_order(head(weighted, 100));
    for (std::size_t i = 100; i < weighted.size(); ++i) {
        dt.insert(weighted.points[i], weighted.weights[i]);
    }
    const Triangulation batch = test::triangulate_in_input_order(weighted);
    EXPECT_EQ(canonical(dt.tets()), canonical(batch.tets));
    EXPECT_EQ(dt.redundant(), batch.redundant);
    EXPECT_GT(batch.redundant.size(), 0u);
    EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty());
    EXPECT_THROW(dt.insert({0.5, std::numeric_limits<double>::quiet_NaN(), 0.5}, 0.0), Error);
}

/// Implicit points (the CDT's edge protection inserts them): inserted one by one into a
/// triangulation of explicit points, they give the tetrahedra of the batch construction of all the
/// points with the same definitions, on a grid whose ties the perturbation decides.
TEST(DelaunayTriangulation, ImplicitInsertionsEqualTheBatch) {
    const PointSet grid = generate_points("grid", 216, 3);
    PointSet all = grid;
    all.exact.assign(grid.points.begin(), grid.points.end());
    DelaunayTriangulation dt = live_in_input_order(grid);
    for (std::uint32_t i = 0; i < 40; ++i) {
        const Point3& a = grid.points[i];
        const Point3& b = grid.points[(7 * i + 50) % grid.size()];
        // Sevenths are not doubles, and no seventh of a grid step is a grid point: the rounding is
        // only where the walk starts.
        const double t = (1 + i % 6) / 7.0;
        const auto s = predicates::segment_parameter_point(a, b, 1 + i % 6, 7);
        ASSERT_TRUE(s);
        const Point3 rounded{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
        EXPECT_EQ(dt.insert(predicates::GenericPoint3(*s), rounded), all.size());
        all.points.push_back(rounded);
        all.exact.emplace_back(*s);
    }
    EXPECT_TRUE(dt.geometry().implicit(static_cast<VertexId>(dt.geometry().size() - 1)));
    EXPECT_TRUE(dt.duplicates().empty());
    EXPECT_TRUE(dt.check(CheckLevel::kComplex).empty());
    EXPECT_EQ(canonical(dt.tets()), canonical(live_in_input_order(all).tets()));
    // An explicit point after them goes through the generic predicates too.
    EXPECT_EQ(dt.insert(predicates::GenericPoint3(Point3{0.25, 0.5, 0.75}), Point3{}), all.size());
}

/// A start for the walk (CGAL's hint) changes where each point is looked for, never the result:
/// implicit and explicit points inserted from live solid tetrahedra anywhere in the mesh, and from
/// hints that cannot be used (none, a ghost, a dead or an unknown tetrahedron), give the batch's
/// tetrahedra.
TEST(DelaunayTriangulation, InsertionsFromAnyHintEqualTheBatch) {
    const PointSet grid = generate_points("grid", 216, 5);
    PointSet all = grid;
    all.exact.assign(grid.points.begin(), grid.points.end());
    DelaunayTriangulation dt = live_in_input_order(grid);
    const auto find_tet = [&](std::size_t from, auto wanted) {
        const ArrayStorage& storage = dt.storage();
        for (std::size_t k = 0; k < storage.capacity(); ++k) {
            const auto t = static_cast<TetId>((from + k) % storage.capacity());
            if (wanted(storage, t)) {
                return t;
            }
        }
        return kNoTet;
    };
    const auto solid = [](const ArrayStorage& storage, TetId t) {
        return storage.alive(t) && !is_ghost(storage.vertices(t));
    };
    const auto ghost = [](const ArrayStorage& storage, TetId t) {
        return storage.alive(t) && is_ghost(storage.vertices(t));
    };
    const auto dead = [](const ArrayStorage& storage, TetId t) { return !storage.alive(t); };
    std::size_t dead_hints = 0;
    for (std::uint32_t i = 0; i < 60; ++i) {
        const Point3& a = grid.points[(5 * i) % grid.size()];
        // 6i + 91 is odd, so a and b differ; sevenths put no point on the grid (as above).
        const Point3& b = grid.points[(11 * i + 91) % grid.size()];
        const auto s = predicates::segment_parameter_point(a, b, 1 + i % 6, 7);
        ASSERT_TRUE(s);
        const double t = (1 + i % 6) / 7.0;
        const Point3 rounded{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
        TetId hint = kNoTet;
        switch (i % 5) {
            case 0:
            case 1:
                hint = find_tet(97 * i, solid);
                ASSERT_NE(hint, kNoTet);
                break;
            case 2:
                hint = find_tet(31 * i, ghost);
                ASSERT_NE(hint, kNoTet);
                break;
            case 3:
                hint = find_tet(13 * i, dead);
                dead_hints += hint != kNoTet;
                break;
            default:
                hint = static_cast<TetId>(dt.storage().capacity() + 7);
                break;
        }
        // Every fourth point an explicit one, through the same call.
        const predicates::GenericPoint3 p =
            i % 4 == 3 ? predicates::GenericPoint3(Point3{rounded.x, rounded.y, rounded.z + 0.125})
                       : predicates::GenericPoint3(*s);
        const Point3 located = i % 4 == 3 ? std::get<Point3>(p) : rounded;
        EXPECT_EQ(dt.insert(p, located, hint), all.size());
        all.points.push_back(located);
        all.exact.push_back(p);
    }
    EXPECT_GT(dead_hints, 0u);
    EXPECT_TRUE(dt.duplicates().empty());
    EXPECT_TRUE(dt.check(CheckLevel::kComplex).empty());
    EXPECT_EQ(canonical(dt.tets()), canonical(live_in_input_order(all).tets()));
}

/// A batch inserted along a space-filling curve gives what row-by-row insertion gives: the same
/// tetrahedra, and the same repeats, inside the batch and of earlier points, the lowest equal row
/// kept whatever the order.
TEST(DelaunayTriangulation, BatchInsertionEqualsRowByRow) {
    for (const char* dist : {"cube", "grid"}) {
        PointSet ps = generate_points(dist, 700, 12);
        ps.points[650] = ps.points[20];   // repeats a point of the build
        ps.points[690] = ps.points[680];  // repeats a later row of the batch
        ps.points[610] = ps.points[695];  // repeated by a later row of the batch
        DelaunayTriangulation dt = live_in_input_order(head(ps, 300));
        PointSet batch;
        batch.points.assign(ps.points.begin() + 300, ps.points.end());
        const InsertionOrder order = make_insertion_order(batch.points, OrderOptions{});
        EXPECT_EQ(dt.insert(batch, order.sequence), 300u);
        EXPECT_EQ(dt.point_count(), ps.size());
        EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty()) << dist;
        const Triangulation whole = test::triangulate_in_input_order(ps);
        EXPECT_EQ(canonical(dt.tets()), canonical(whole.tets)) << dist;
        EXPECT_EQ(dt.duplicates(), whole.duplicates) << dist;
    }
    const PointSet weighted = generate_points("cube", 400, 3, parse_weight_spec("uniform:0:0.1"));
    DelaunayTriangulation dt = live_in_input_order(head(weighted, 100));
    PointSet batch;
    batch.points.assign(weighted.points.begin() + 100, weighted.points.end());
    batch.weights.assign(weighted.weights.begin() + 100, weighted.weights.end());
    std::vector<std::uint32_t> backwards(batch.size());
    std::iota(backwards.rbegin(), backwards.rend(), 0u);
    dt.insert(batch, backwards);
    const Triangulation whole = test::triangulate_in_input_order(weighted);
    EXPECT_EQ(canonical(dt.tets()), canonical(whole.tets));
    EXPECT_EQ(dt.redundant(), whole.redundant);
    // Refused before anything changes.
    batch.weights.clear();
    EXPECT_THROW(dt.insert(batch, backwards), Error);
    batch.weights.assign(weighted.weights.begin() + 100, weighted.weights.end());
    batch.points[7].y = std::numeric_limits<double>::infinity();
    EXPECT_THROW(dt.insert(batch, backwards), Error);
    backwards.pop_back();
    EXPECT_THROW(dt.insert(batch, backwards), Error);
    EXPECT_EQ(dt.point_count(), weighted.size());
}

TEST(DelaunayTriangulation, LocateFindsAClosedCell) {
    const PointSet ps = generate_points("cube", 500, 4);
    const DelaunayTriangulation dt = live_in_input_order(ps);
    Random rng(9);
    for (int k = 0; k < 200; ++k) {
        const Point3 p{rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2)};
        const TetId t = dt.locate(p);
        const TetVertices& v = dt.storage().vertices(t);
        const Geometry& g = dt.geometry();
        if (is_ghost(v)) {
            // p strictly in front of the hull triangle.
            EXPECT_EQ(Geometry::orient3d(g.point(v[0]), g.point(v[2]), g.point(v[1]), p),
                      Sign::kNeg);
            continue;
        }
        for (int f = 0; f < 4; ++f) {
            const auto tri = facet_vertices(v, f);
            EXPECT_NE(Geometry::orient3d(g.point(tri[0]), g.point(tri[1]), g.point(tri[2]), p),
                      Sign::kNeg);
        }
    }
}

TEST(DelaunayTriangulation, RemovalEqualsRebuildAndInsertionContinues) {
    const PointSet ps = generate_points("grid", 216, 1);
    DelaunayTriangulation dt = live_in_input_order(head(ps, 200));
    const std::vector<std::uint32_t> ids{0, 7, 199, 100, 43, 36, 180};
    dt.remove(ids);
    EXPECT_EQ(dt.edit_counters().vertices_deleted, ids.size());
    std::vector<bool> gone(ps.size(), false);
    for (auto id : ids) {
        gone[id] = true;
    }
    std::vector<bool> gone_and_later = gone;
    std::fill(gone_and_later.begin() + 200, gone_and_later.end(), true);
    EXPECT_EQ(canonical(dt.tets()), canonical(test::rebuilt_without(ps, gone_and_later).tets));
    EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty());
    // The bootstrap vertices (0 among them) are gone; insertion goes on.
    for (std::size_t i = 200; i < ps.size(); ++i) {
        dt.insert(ps.points[i]);
    }
    EXPECT_EQ(canonical(dt.tets()), canonical(test::rebuilt_without(ps, gone).tets));
    EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty());
    const std::vector<std::uint32_t> again{7};
    EXPECT_THROW(dt.remove(again), Error);
}

TEST(DelaunayTriangulation, RemovalRefusesBadIdsBeforeChangingAnything) {
    PointSet ps = generate_points("cube", 50, 4);
    ps.points.push_back(ps.points[3]);  // point 50 repeats point 3
    DelaunayTriangulation dt = live_in_input_order(ps);
    const Tets before = canonical(dt.tets());
    for (const std::vector<std::uint32_t>& bad :
         {std::vector<std::uint32_t>{3}, {51}, {4, 4}, {9, 51}}) {
        EXPECT_THROW(dt.remove(bad), Error);
        EXPECT_EQ(canonical(dt.tets()), before);
    }
    const std::vector<std::uint32_t> both{3, 50};
    dt.remove(both);
    std::vector<bool> gone(ps.size(), false);
    gone[3] = gone[50] = true;
    EXPECT_EQ(canonical(dt.tets()), canonical(test::rebuilt_without(ps, gone).tets));
    EXPECT_TRUE(dt.duplicates().empty());

    PointSet flat;
    flat.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}};
    DelaunayTriangulation pyramid = live_in_input_order(flat);
    const std::vector<std::uint32_t> apex{4};
    EXPECT_THROW(pyramid.remove(apex), Error);
    EXPECT_EQ(pyramid.tet_count(), 2u);
}

TEST(DelaunayTriangulation, FlipsAreCheckedAndUndone) {
    const PointSet ps = generate_points("cube", 300, 6);
    DelaunayTriangulation dt = live_in_input_order(ps);
    const Tets before = canonical(dt.tets());
    // The first interior facet whose 2-3 flip is legal (both apices see the facet).
    const ArrayStorage& s = dt.storage();
    std::vector<TetId> fresh;
    for (TetId t = 0; t < s.capacity() && fresh.empty(); ++t) {
        if (!s.alive(t) || is_ghost(s.vertices(t))) {
            continue;
        }
        for (int f = 0; f < 4 && fresh.empty(); ++f) {
            if (!is_ghost(s.vertices(tet_of(s.adjacent(t, f))))) {
                fresh = dt.flip23(half_facet(t, f));
            }
        }
    }
    ASSERT_EQ(fresh.size(), 3u);
    EXPECT_TRUE(dt.check(CheckLevel::kComplex).empty());
    EXPECT_FALSE(dt.check(CheckLevel::kDelaunay).empty());  // a Delaunay facet flipped away
    // The 3-2 flip around the new edge restores the Delaunay triangulation.
    const TetVertices& v = s.vertices(fresh[0]);
    int i = -1;
    int j = -1;
    for (int a = 0; a < 4; ++a) {
        const VertexId w = v[static_cast<std::size_t>(a)];
        const bool shared = std::all_of(fresh.begin(), fresh.end(), [&](TetId t) {
            const TetVertices& u = s.vertices(t);
            return std::find(u.begin(), u.end(), w) != u.end();
        });
        if (shared) {
            (i < 0 ? i : j) = a;
        }
    }
    ASSERT_GE(j, 0);
    EXPECT_EQ(dt.flip32(fresh[0], i, j).size(), 2u);
    EXPECT_EQ(canonical(dt.tets()), before);
    EXPECT_TRUE(dt.check(CheckLevel::kDelaunay).empty());
}

TEST(DelaunayTriangulation, ReleaseByIndexIsTheComplexOfTheTetrahedra) {
    const PointSet ps = generate_points("ball", 800, 2);
    OrderOptions order_options;
    order_options.kind = OrderKind::kHilbert;
    const InsertionOrder order = make_insertion_order(ps.points, order_options);
    DelaunayTriangulation dt(ps, order.sequence, TriangulateOptions{});
    const Tets tets = dt.tets();
    const ArrayStorage by_index = std::move(dt).release_by_index();
    EXPECT_TRUE(check_complex(by_index, geometry_by_index(ps)).empty());
    EXPECT_EQ(canonical(solid_tets(by_index)), canonical(tets));
    EXPECT_EQ(canonical(solid_tets(complex_from_tets(tets))), canonical(tets));
    for (VertexId v = 0; v < ps.size(); ++v) {
        const TetId t = by_index.tet_at_vertex(v);
        ASSERT_NE(t, kNoTet);
        const TetVertices& w = by_index.vertices(t);
        EXPECT_NE(std::find(w.begin(), w.end(), v), w.end());
    }
}

}  // namespace
}  // namespace cavity::core
