#include "cavity/core/cdt/cdt_validate.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "box_grid.h"
#include "cavity/core/base/error.h"
#include "cavity/core/cdt/edge_protection.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/orient3d.h"
#include "exact_plane.h"
#include "points_in_tets.h"

namespace cavity::core {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

class Report {
public:
    explicit Report(CdtValidation& out) : out_(out) {}

    void add(std::string what) {
        if (out_.problems.size() < 20) {
            out_.problems.push_back(std::move(what));
        }
        ++out_.problem_count;
    }

private:
    CdtValidation& out_;
};

/// The PLC's points as exactly defined (edge protection's implicit points by their definitions),
/// so that no exact test below sees a rounded coordinate.
struct ExactPoints {
    const PointSet& points;

    predicates::GenericPoint3 operator[](std::uint32_t i) const { return generic_point(points, i); }
};

/// The box of the points `ids` in doubles (box_grid.h): min and max are exact, so a box test never
/// drops a simplex that meets a facet; it only spares exact tests of those that cannot. Implicit
/// points are boxed by their coordinates rounded to nearest, a monotone rounding, which keeps
/// that true.
template <class Ids>
Box box_of(const std::vector<Point3>& pts, const Ids& ids) {
    Box b;
    for (auto id : ids) {
        b.add(pts[id]);
    }
    return b;
}

Box facet_box(const Plc& plc, const PlcFacet& facet) {
    std::vector<std::uint32_t> corners;
    for (const auto& loop : facet.loops) {
        corners.insert(corners.end(), loop.begin(), loop.end());
    }
    return box_of(plc.points.points, corners);
}

/// The mesh simplices, shared by every facet's tests.
struct BoxedMesh {
    std::span<const std::array<std::uint32_t, 4>> tets;
    std::vector<Triangle> triangles;  ///< each sorted, in increasing order
    const std::vector<Point3>& points;
};

/// The boxes of the mesh's tetrahedra and triangles and uniform grids of them, made on the first
/// full scan of a polygon: a carved domain scans for every polygon, and testing each polygon's box
/// against every simplex's was quadratic on surface meshes. The whole hull's polygons are mostly
/// decided without a scan (facet_triangle, covering_faces), so nothing here is made for them.
class ScanIndex {
public:
    /// The tetrahedra (or triangles) whose boxes may meet `box`, for polygon `facet` (each polygon
    /// asks once), in the grid's order: a function of the mesh alone.
    std::vector<std::size_t> tets_near(const BoxedMesh& mesh, const Box& box, std::size_t facet) {
        if (!tets_) {
            for (const auto& t : mesh.tets) {
                tet_boxes_.push_back(box_of(mesh.points, t));
            }
            tets_.emplace(bounds(mesh), tet_boxes_);
        }
        return tets_->near(box, facet);
    }

    std::vector<std::size_t> triangles_near(const BoxedMesh& mesh,
                                            const Box& box,
                                            std::size_t facet) {
        if (!triangles_) {
            for (const Triangle& g : mesh.triangles) {
                triangle_boxes_.push_back(box_of(mesh.points, g));
            }
            triangles_.emplace(bounds(mesh), triangle_boxes_);
        }
        return triangles_->near(box, facet);
    }

    /// The box of tetrahedron k, once tets_near has been asked.
    const Box& tet_box(std::size_t k) const { return tet_boxes_[k]; }

    /// The box of triangle k, once triangles_near has been asked.
    const Box& triangle_box(std::size_t k) const { return triangle_boxes_[k]; }

private:
    /// The box of every point.
    static Box bounds(const BoxedMesh& mesh) {
        Box b;
        for (const Point3& p : mesh.points) {
            b.add(p);
        }
        return b;
    }

    std::vector<Box> tet_boxes_;
    std::vector<Box> triangle_boxes_;
    std::optional<BoxGrid> tets_;
    std::optional<BoxGrid> triangles_;
};

/// Named only when reported: building the name of every triangle cost a tenth of validating.
std::string triangle_name(const Triangle& g, std::uint32_t base) {
    return "triangle " + std::to_string(g[0] + base) + " " + std::to_string(g[1] + base) + " " +
           std::to_string(g[2] + base);
}

std::string tet_name(const std::array<std::uint32_t, 4>& t, int base) {
    std::string s = "tetrahedron";
    for (std::uint32_t v : t) {
        s += " " + std::to_string(v + static_cast<std::uint32_t>(base));
    }
    return s;
}

/// The mesh triangles around each vertex (indices into BoxedMesh::triangles), with a stamp per
/// vertex and per triangle so that each facet's search visits each once without clearing.
class VertexTriangles {
public:
    VertexTriangles(const std::vector<Triangle>& triangles, std::size_t vertices)
        : start_(vertices + 1, 0)
        , vertex_stamp_(vertices, 0)
        , triangle_stamp_(triangles.size(), 0) {
        for (const Triangle& g : triangles) {
            for (std::uint32_t v : g) {
                ++start_[v + 1];
            }
        }
        for (std::size_t v = 0; v < vertices; ++v) {
            start_[v + 1] += start_[v];
        }
        around_.resize(start_[vertices]);
        std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
        for (std::size_t k = 0; k < triangles.size(); ++k) {
            for (std::uint32_t v : triangles[k]) {
                around_[next[v]++] = static_cast<std::uint32_t>(k);
            }
        }
    }

    std::span<const std::uint32_t> of(std::uint32_t v) const {
        return {around_.data() + start_[v], around_.data() + start_[v + 1]};
    }

    /// Starts a new search: every vertex and triangle counts as unvisited again.
    void next_search() { ++stamp_; }

    /// True the first time v is seen in this search.
    bool first_visit_of_vertex(std::uint32_t v) {
        return std::exchange(vertex_stamp_[v], stamp_) != stamp_;
    }

    bool first_visit_of_triangle(std::uint32_t k) {
        return std::exchange(triangle_stamp_[k], stamp_) != stamp_;
    }

private:
    std::vector<std::size_t> start_;
    std::vector<std::uint32_t> around_;
    std::vector<std::uint32_t> vertex_stamp_;
    std::vector<std::uint32_t> triangle_stamp_;
    std::uint32_t stamp_ = 0;
};

/// The sides found so far, by point: the sign, and which facet's plane it is for (index + 1; 0:
/// none), so that each facet starts afresh without clearing and without a hash table of its own.
struct SideMemo {
    explicit SideMemo(std::size_t points) : facet(points, 0), sign(points, Sign::kZero) {}

    std::vector<std::uint32_t> facet;
    std::vector<Sign> sign;
};

/// The side of the facet's plane point v lies on: zero without a predicate for the facet's own
/// corners, the commonest question near a facet and orient3d's most expensive answer.
class FacetSide {
public:
    FacetSide(const Plc& plc, std::size_t index, const ExactPlane& plane, SideMemo& memo)
        : plc_(plc), plane_(plane), memo_(memo), stamp_(static_cast<std::uint32_t>(index + 1)) {
        for (const auto& loop : plc.facets[index].loops) {
            for (std::uint32_t c : loop) {
                memo_.facet[c] = stamp_;
                memo_.sign[c] = Sign::kZero;
            }
        }
    }

    Sign operator()(std::uint32_t v) const {
        // Kept: the search around the facet asks of each vertex once per triangle around it, and
        // orient3d with an implicit point can take thousands of instructions.
        if (memo_.facet[v] != stamp_) {
            memo_.facet[v] = stamp_;
            memo_.sign[v] = plane_.side(generic_point(plc_.points, v));
        }
        return memo_.sign[v];
    }

private:
    const Plc& plc_;
    const ExactPlane& plane_;
    SideMemo& memo_;
    std::uint32_t stamp_;
};

/// True when mesh triangle g lies in the facet's plane with its centroid in the facet's region.
bool in_facet(const ExactPlane& plane,
              const FacetRegion& region,
              const FacetSide& side,
              RationalPoints& rational,
              const Triangle& g) {
    if (side(g[0]) != Sign::kZero || side(g[1]) != Sign::kZero || side(g[2]) != Sign::kZero) {
        return false;
    }
    const ExactPoint& a = rational[g[0]];
    const ExactPoint& b = rational[g[1]];
    const ExactPoint& c = rational[g[2]];
    // Only the coordinates the region's projection keeps (FacetRegion::contains).
    ExactPoint centroid;
    for (std::size_t k = 0; k < 3; ++k) {
        if (static_cast<int>(k) != plane.dropped_axis()) {
            centroid[k] = (a[k] + b[k] + c[k]) / 3;
        }
    }
    return region.contains(std::move(centroid));
}

/// A polygon that is one triangle without hole points, when the mesh has that triangle: then it is
/// the polygon's only face, and a valid complex has no tetrahedron crossing it (the reason is
/// covering_faces'). Most polygons of a surface mesh are met here, without rational arithmetic.
std::optional<Triangle> facet_triangle(const PlcFacet& facet, const BoxedMesh& mesh) {
    if (facet.loops.size() != 1 || facet.loops[0].size() != 3 || !facet.holes.empty()) {
        return std::nullopt;
    }
    Triangle g{facet.loops[0][0], facet.loops[0][1], facet.loops[0][2]};
    std::sort(g.begin(), g.end());
    if (!std::binary_search(mesh.triangles.begin(), mesh.triangles.end(), g)) {
        return std::nullopt;
    }
    return g;
}

/// The whole hull's shortcut: the facet's triangles found from its corners outward, through the
/// triangles around the vertices of those already found, when their area is the facet's area;
/// nullopt otherwise (the caller then scans every simplex). Why this is the same answer. The
/// caller runs it only once the complex is known to be a valid triangulation and every PLC edge a
/// union of mesh edges. Then no mesh triangle's relative interior meets the facet's boundary (the
/// boundary is mesh edges, and simplices of a complex meet only in common faces), so a triangle
/// in the plane with its centroid in the region lies in the region; their interiors are disjoint,
/// so when their area equals the region's they cover it and there is no other such triangle; and
/// no tetrahedron crosses the region, because its edges and interior would meet the relative
/// interior of a covering triangle. The search visits only triangles around the facet, where the
/// full scan tests every tetrahedron and triangle against every facet: quadratic on surface
/// meshes, whose long Delaunay slivers defeat the boxes.
std::optional<std::vector<Triangle>> covering_faces(const Plc& plc,
                                                    const PlcFacet& facet,
                                                    const ExactPlane& plane,
                                                    const FacetRegion& region,
                                                    const FacetSide& side,
                                                    const BoxedMesh& mesh,
                                                    VertexTriangles& around,
                                                    RationalPoints& rational) {
    around.next_search();
    std::vector<std::uint32_t> frontier;
    for (const auto& loop : facet.loops) {
        for (std::uint32_t v : loop) {
            if (around.first_visit_of_vertex(v)) {
                frontier.push_back(v);
            }
        }
    }
    std::vector<Triangle> faces;
    Rational covered = 0;
    while (!frontier.empty()) {
        const std::uint32_t v = frontier.back();
        frontier.pop_back();
        for (std::uint32_t k : around.of(v)) {
            const Triangle& g = mesh.triangles[k];
            if (!around.first_visit_of_triangle(k) || !in_facet(plane, region, side, rational, g)) {
                continue;
            }
            faces.push_back(g);
            covered += triangle_area2(plane, rational[g[0]], rational[g[1]], rational[g[2]]);
            for (std::uint32_t w : g) {
                if (around.first_visit_of_vertex(w)) {
                    frontier.push_back(w);
                }
            }
        }
    }
    if (covered != facet_region_area2(plc, facet, plane, &rational)) {
        return std::nullopt;
    }
    return faces;
}

/// The coplanar triangles of a one-loop polygon found by combinatorics alone, no region test and
/// no rational area: a flood from a triangle on the loop's first side, across the mesh edges in
/// the plane that are no loop side, orienting each triangle reached like the one it was reached
/// from (each shared edge run both ways). Why the answer is exact. Run only once the complex is
/// a valid triangulation and every PLC edge a mesh edge (as covering_faces), so coplanar mesh
/// triangles never overlap: two on a common edge lie on its two sides, so orienting across it
/// gives both the same orientation in the plane, and every triangle found has the same one. Their
/// chain c (each +1, as oriented) then counts each point of the plane 0 or +-1 times; when its
/// boundary is exactly the loop, run one way or the other, c's count is the loop's winding number
/// up to sign, so the winding number is 0 or +-1 everywhere and nonzero exactly where it is odd:
/// the triangles cover exactly the points inside the loop by parity, which is FacetRegion's
/// region of a loop without hole points. Then, as in covering_faces, they are all its faces and
/// no tetrahedron crosses it. nullopt when the flood's boundary is anything else (other loops,
/// slits, a missing triangle, a seed outside): the caller then decides the slow way.
class LoopFlood {
public:
    explicit LoopFlood(std::size_t triangles) : stamp_(triangles, 0), even_(triangles, false) {}

    std::optional<std::vector<Triangle>> faces(const PlcFacet& facet,
                                               const FacetSide& side,
                                               const BoxedMesh& mesh,
                                               const VertexTriangles& around) {
        if (facet.loops.size() != 1 || !facet.holes.empty() || facet.loops[0].size() < 3) {
            return std::nullopt;
        }
        const auto& loop = facet.loops[0];
        std::vector<Edge> sides;  // directed, as the loop runs
        sides.reserve(loop.size());
        for (std::size_t i = 0; i < loop.size(); ++i) {
            sides.push_back({loop[i], loop[(i + 1) % loop.size()]});
        }
        std::vector<Edge> reversed;
        reversed.reserve(sides.size());
        for (const Edge& e : sides) {
            reversed.push_back({e[1], e[0]});
        }
        std::sort(sides.begin(), sides.end());
        std::sort(reversed.begin(), reversed.end());
        undirected_.clear();
        for (const Edge& e : sides) {
            undirected_.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
        }
        std::sort(undirected_.begin(), undirected_.end());
        if (std::adjacent_find(undirected_.begin(), undirected_.end()) != undirected_.end()) {
            return std::nullopt;  // a side run twice: a slit, for the slow way
        }
        const std::uint32_t p = loop[0];
        const std::uint32_t q = loop[1];
        std::array<std::uint32_t, 2> seeds{};
        std::size_t seed_count = 0;
        for (std::uint32_t k : fewer(around, p, q)) {
            const Triangle& g = mesh.triangles[k];
            const std::uint32_t r = third(g, p, q);
            if (r == kNone || side(r) != Sign::kZero) {
                continue;
            }
            if (seed_count == 2) {
                return std::nullopt;
            }
            seeds[seed_count++] = k;
        }
        for (std::size_t s = 0; s < seed_count; ++s) {
            if (flood(
                    seeds[s], {p, q, third(mesh.triangles[seeds[s]], p, q)}, side, mesh, around) &&
                (boundary_ == sides || boundary_ == reversed)) {
                std::vector<Triangle> out;
                out.reserve(found_.size());
                for (std::uint32_t k : found_) {
                    out.push_back(mesh.triangles[k]);
                }
                return out;
            }
        }
        return std::nullopt;
    }

private:
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};

    /// The vertex of g other than a and b, or kNone when g lacks one of them.
    static std::uint32_t third(const Triangle& g, std::uint32_t a, std::uint32_t b) {
        std::uint32_t other = kNone;
        int hits = 0;
        for (std::uint32_t v : g) {
            if (v == a || v == b) {
                ++hits;
            } else {
                other = v;
            }
        }
        return hits == 2 ? other : kNone;
    }

    /// The triangles around a or around b, whichever are fewer: those on edge ab are in both.
    static std::span<const std::uint32_t> fewer(const VertexTriangles& around,
                                                std::uint32_t a,
                                                std::uint32_t b) {
        const auto at_a = around.of(a);
        const auto at_b = around.of(b);
        return at_a.size() <= at_b.size() ? at_a : at_b;
    }

    bool loop_side(std::uint32_t a, std::uint32_t b) const {
        return std::binary_search(
            undirected_.begin(), undirected_.end(), Edge{std::min(a, b), std::max(a, b)});
    }

    /// Floods from triangle `seed` oriented as `t`; false on a boundary edge that is no loop side
    /// or an edge with more than one coplanar triangle across. The loop sides met, directed as
    /// the triangles run them, sorted, in boundary_; the triangles in found_.
    bool flood(std::uint32_t seed,
               const Triangle& t,
               const FacetSide& side,
               const BoxedMesh& mesh,
               const VertexTriangles& around) {
        ++search_;
        boundary_.clear();
        found_.assign(1, seed);
        stack_.assign(1, {seed, t});
        stamp_[seed] = search_;
        even_[seed] = parity(t);
        while (!stack_.empty()) {
            const auto [k, g] = stack_.back();
            stack_.pop_back();
            for (std::size_t i = 0; i < 3; ++i) {
                const std::uint32_t a = g[i];
                const std::uint32_t b = g[(i + 1) % 3];
                if (loop_side(a, b)) {
                    boundary_.push_back({a, b});
                    continue;
                }
                // The one other coplanar triangle on ab, run b -> a, among the triangles around
                // the end with fewer (a vertex of a large flat polygon has hundreds).
                std::uint32_t across = kNone;
                std::uint32_t apex = kNone;
                for (std::uint32_t m : fewer(around, a, b)) {
                    const std::uint32_t r = third(mesh.triangles[m], a, b);
                    if (m == k || r == kNone || side(r) != Sign::kZero) {
                        continue;
                    }
                    if (across != kNone) {
                        return false;
                    }
                    across = m;
                    apex = r;
                }
                if (across == kNone) {
                    return false;
                }
                const Triangle next{b, a, apex};
                if (stamp_[across] == search_) {
                    if (even_[across] != parity(next)) {
                        return false;
                    }
                    continue;
                }
                stamp_[across] = search_;
                even_[across] = parity(next);
                found_.push_back(across);
                stack_.push_back({across, next});
            }
        }
        std::sort(boundary_.begin(), boundary_.end());
        return true;
    }

    /// Whether t is an even permutation of its sorted vertices (which are distinct).
    static bool parity(const Triangle& t) {
        int inversions = 0;
        inversions += t[0] > t[1] ? 1 : 0;
        inversions += t[0] > t[2] ? 1 : 0;
        inversions += t[1] > t[2] ? 1 : 0;
        return inversions % 2 == 0;
    }

    std::vector<std::uint32_t> stamp_;  ///< by triangle: the last flood that reached it
    std::vector<bool> even_;            ///< by triangle: its orientation in that flood
    std::uint32_t search_ = 0;
    std::vector<Edge> undirected_;  ///< the loop's sides, {min, max}, sorted
    std::vector<Edge> boundary_;
    std::vector<std::uint32_t> found_;
    std::vector<std::pair<std::uint32_t, Triangle>> stack_;
};

/// The facet's triangles among the mesh triangles lying in its plane, after checking that no
/// tetrahedron crosses it and, for the whole hull, that they cover its area. A carved domain holds
/// only the part of a polygon next to its tetrahedra (none of a polygon with removed tetrahedra on
/// both sides, the lower half of a wall whose upper side was a hole), and a part of the polygon in
/// the domain but not covered would be crossed by a tetrahedron, which is checked.
std::vector<Triangle> polygon_faces(const Plc& plc,
                                    std::size_t index,
                                    const BoxedMesh& mesh,
                                    VertexTriangles& around,
                                    LoopFlood& loop_flood,
                                    ScanIndex& index_of_mesh,
                                    RationalPoints& rational,
                                    SideMemo& sides,
                                    bool carved,
                                    Report& report) {
    const PlcFacet& facet = plc.facets[index];
    if (!carved) {
        if (auto same = facet_triangle(facet, mesh)) {
            return {*same};
        }
    }
    const std::string name = facet_name(plc, index);
    const auto plane = ExactPlane::of_facet(plc, facet);
    std::vector<Triangle> faces;
    if (!plane) {
        report.add(name + ": corners are collinear");
        return faces;
    }
    const FacetSide side(plc, index, *plane, sides);
    if (!carved) {
        if (auto found = loop_flood.faces(facet, side, mesh, around)) {
            return std::move(*found);
        }
    }
    const FacetRegion region(plc, facet, *plane, &rational);
    if (!carved) {
        if (auto found = covering_faces(plc, facet, *plane, region, side, mesh, around, rational)) {
            return std::move(*found);
        }
    }
    const ExactPoints pts{plc.points};
    const Box box = facet_box(plc, facet);
    for (const std::size_t k : index_of_mesh.tets_near(mesh, box, index)) {
        if (!box.meets(index_of_mesh.tet_box(k))) {
            continue;
        }
        const auto& t = mesh.tets[k];
        std::array<int, 4> s{};
        for (std::size_t i = 0; i < 4; ++i) {
            s[i] = static_cast<int>(side(t[i]));
        }
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = 0; j < 4; ++j) {
                if (s[i] < 0 && s[j] > 0) {
                    if (crosses_facet_region(plc, facet, *plane, region, pts[t[i]], pts[t[j]])) {
                        report.add(tet_name(t, plc.points.index_base) + " crosses " + name);
                    }
                    i = j = 4;
                    break;
                }
            }
        }
    }
    Rational covered = 0;
    for (const std::size_t k : index_of_mesh.triangles_near(mesh, box, index)) {
        const Triangle& g = mesh.triangles[k];
        if (!box.meets(index_of_mesh.triangle_box(k))) {
            continue;
        }
        if (in_facet(*plane, region, side, rational, g)) {
            faces.push_back(g);
            covered += triangle_area2(*plane, rational[g[0]], rational[g[1]], rational[g[2]]);
        }
    }
    if (!carved && covered != facet_region_area2(plc, facet, *plane, &rational)) {
        report.add(name + " is not a union of mesh triangles (their area differs from its area)");
    }
    return faces;
}

/// The tetrahedra on a mesh triangle: `count` of them, the first two in `tet` (more: a problem).
struct Sides {
    std::size_t count = 0;
    std::array<std::uint32_t, 2> tet{};
};

/// Each mesh triangle (its vertices sorted) with its tetrahedra, in increasing order of triangle.
using TriangleSides = std::vector<std::pair<Triangle, Sides>>;

/// For tetrahedra on the points 0 to vertices - 1.
TriangleSides triangle_sides(std::span<const std::array<std::uint32_t, 4>> tets,
                             std::size_t vertices) {
    // Grouping (triangle, tetrahedron) pairs by sorting them gives each triangle's tetrahedra in
    // increasing tetrahedron order; a map of triangles cost a node allocation per triangle. A
    // counting sort by the lowest vertex, then a sort of each (short) run by the other two
    // vertices and the tetrahedron: the order of a comparison sort of all pairs, in about linear
    // time. Three counting sorts, one per vertex, moved every pair three times.
    struct Pair {
        std::uint64_t rest;  ///< the middle vertex << 32 | the highest
        std::uint32_t lowest;
        std::uint32_t tet;
    };

    // A tetrahedron's vertices sorted once give its four triangles sorted: drop one of them.
    const auto sorted_vertices = [](std::array<std::uint32_t, 4> v) {
        const auto order = [&](std::size_t i, std::size_t j) {
            if (v[j] < v[i]) {
                std::swap(v[i], v[j]);
            }
        };
        order(0, 1);
        order(2, 3);
        order(0, 2);
        order(1, 3);
        order(1, 2);
        return v;
    };
    std::vector<std::uint32_t> start(vertices + 1, 0);
    for (const auto& t : tets) {
        const auto v = sorted_vertices(t);
        start[v[0] + 1] += 3;  // the lowest vertex is the lowest of all triangles but one
        ++start[v[1] + 1];
    }
    for (std::size_t v = 0; v < vertices; ++v) {
        start[v + 1] += start[v];
    }
    std::vector<Pair> pairs(4 * tets.size());
    {
        std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
        const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t t) {
            pairs[next[a]++] = {(std::uint64_t{b} << 32) | c, a, t};
        };
        for (std::uint32_t t = 0; t < tets.size(); ++t) {
            const auto v = sorted_vertices(tets[t]);
            add(v[1], v[2], v[3], t);
            add(v[0], v[2], v[3], t);
            add(v[0], v[1], v[3], t);
            add(v[0], v[1], v[2], t);
        }
    }
    TriangleSides sides;
    sides.reserve(pairs.size() / 2 + 1);
    for (std::size_t v = 0; v < vertices; ++v) {
        const auto run = std::span(pairs).subspan(start[v], start[v + 1] - start[v]);
        // By triangle, then tetrahedron: the pairs are distinct, so the order is a total one.
        std::sort(run.begin(), run.end(), [](const Pair& x, const Pair& y) {
            return x.rest != y.rest ? x.rest < y.rest : x.tet < y.tet;
        });
        for (std::size_t i = 0; i < run.size(); ++i) {
            const Pair& p = run[i];
            if (i == 0 || run[i - 1].rest != p.rest) {
                const Triangle g{p.lowest,
                                 static_cast<std::uint32_t>(p.rest >> 32),
                                 static_cast<std::uint32_t>(p.rest)};
                sides.push_back({g, Sides{}});
            }
            Sides& on = sides.back().second;
            if (on.count < 2) {
                on.tet[on.count] = p.tet;
            }
            ++on.count;
        }
    }
    return sides;
}

/// The vertex of t not in triangle g.
std::uint32_t apex(const std::array<std::uint32_t, 4>& t, const Triangle& g) {
    for (std::uint32_t v : t) {
        if (std::find(g.begin(), g.end(), v) == g.end()) {
            return v;
        }
    }
    return t[0];  // unreachable: g is a facet of t
}

/// A carved domain keeps no tetrahedron whose closure holds a volume hole point (carve_cdt refuses
/// hole points on polygons, and the domain's boundary is polygons), nor a PLC point that is not
/// one of its vertices (it would be a polygon corner or segment end hidden inside the domain).
void check_points_outside(const Plc& plc,
                          std::span<const std::array<std::uint32_t, 4>> tets,
                          const std::vector<bool>& used,
                          Report& report) {
    std::vector<predicates::GenericPoint3> probes;
    std::vector<std::uint32_t> unused;
    for (const PlcVolumeHole& hole : plc.volume_holes) {
        probes.push_back(hole.point);
    }
    for (std::uint32_t v = 0; v < used.size(); ++v) {
        if (!used[v]) {
            probes.push_back(generic_point(plc.points, v));
            unused.push_back(v);
        }
    }
    const auto in = points_in_tets(plc.points, tets, probes);
    const std::size_t holes = plc.volume_holes.size();
    const auto base = static_cast<std::size_t>(plc.points.index_base);
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (!in[i]) {
            continue;
        }
        const std::string where = " lies in " + tet_name(tets[*in[i]], plc.points.index_base);
        if (i < holes) {
            const std::size_t line = plc.volume_holes[i].line;
            report.add("volume hole point " + std::to_string(i + base) +
                       (line > 0 ? " (line " + std::to_string(line) + ")" : std::string()) + where);
        } else {
            report.add("point " + std::to_string(unused[i - holes] + base) +
                       " is not a vertex of the carved mesh but" + where);
        }
    }
}

/// The facet pairing of complex_from_tets, read off the triangles' sides (found anyway for the
/// checks below) instead of matched a second time; nullopt when a triangle has more than two
/// tetrahedra, for complex_from_tets to refuse in its own words.
std::optional<std::vector<std::int32_t>> facet_pairing(
    std::span<const std::array<std::uint32_t, 4>> tets, const TriangleSides& sides) {
    std::vector<std::int32_t> across(4 * tets.size(), -1);
    const auto slot_of_apex = [&](std::uint32_t t, const Triangle& g) {
        const auto& v = tets[t];
        std::size_t s = 0;
        while (s < 3 && (v[s] == g[0] || v[s] == g[1] || v[s] == g[2])) {
            ++s;
        }
        return s;  // g is a facet of tets[t], so the one vertex not in it
    };
    for (const auto& [g, on] : sides) {
        if (on.count > 2) {
            return std::nullopt;
        }
        if (on.count == 2) {
            across[4 * std::size_t{on.tet[0]} + slot_of_apex(on.tet[0], g)] =
                static_cast<std::int32_t>(on.tet[1]);
            across[4 * std::size_t{on.tet[1]} + slot_of_apex(on.tet[1], g)] =
                static_cast<std::int32_t>(on.tet[0]);
        }
    }
    return across;
}

/// The whole hull: the complex glued with ghosts must be valid with a convex boundary.
void check_hull_complex(const Plc& plc,
                        std::span<const std::array<std::uint32_t, 4>> tets,
                        const TriangleSides& sides,
                        Report& report) {
    const int base = plc.points.index_base;
    // The complex checks name vertices by their ids: number them as the file does (ids shifted by
    // the base, keys unchanged so the perturbation is the same), so every message can be matched
    // against the input.
    std::vector<std::array<std::uint32_t, 4>> numbered(tets.begin(), tets.end());
    for (auto& t : numbered) {
        for (auto& v : t) {
            v += static_cast<std::uint32_t>(base);
        }
    }
    std::vector<Point3> points(static_cast<std::size_t>(base), Point3{0, 0, 0});
    points.insert(points.end(), plc.points.points.begin(), plc.points.points.end());
    std::vector<std::uint32_t> keys(points.size());
    for (std::size_t v = 0; v < keys.size(); ++v) {
        keys[v] = static_cast<std::uint32_t>(v < static_cast<std::size_t>(base) ? 0 : v - base);
    }
    std::vector<predicates::GenericPoint3> exact;
    if (!plc.points.exact.empty()) {
        exact.assign(static_cast<std::size_t>(base), Point3{0, 0, 0});
        exact.insert(exact.end(), plc.points.exact.begin(), plc.points.exact.end());
    }
    const Geometry geometry(std::move(points), std::move(keys), {}, std::move(exact));
    try {
        const auto across = facet_pairing(tets, sides);
        const ArrayStorage complex =
            across ? complex_from_tets(numbered, *across) : complex_from_tets(numbered);
        for (const std::string& p : check_complex(complex, geometry)) {
            report.add(p);
        }
    } catch (const Error& e) {
        report.add(e.what());
        return;
    }
}

/// A carved domain: its boundary may be anything, so the complex is checked triangle by
/// triangle (positive volumes, at most two tetrahedra on a triangle, on opposite sides).
void check_carved_complex(const Plc& plc,
                          std::span<const std::array<std::uint32_t, 4>> tets,
                          const TriangleSides& sides,
                          Report& report) {
    const ExactPoints pts{plc.points};
    const int base = plc.points.index_base;
    for (const auto& t : tets) {
        // Positive right-hand volume is orient3d < 0 (handedness.h).
        if (predicates::orient3d(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]) != Sign::kNeg) {
            report.add(tet_name(t, base) + ": volume not positive (right-hand rule)");
        }
    }
    for (const auto& [g, on] : sides) {
        const auto b = static_cast<std::uint32_t>(base);
        if (on.count > 2) {
            report.add(triangle_name(g, b) + " is on " + std::to_string(on.count) + " tetrahedra");
        } else if (on.count == 2 &&
                   predicates::orient3d(
                       pts[g[0]], pts[g[1]], pts[g[2]], pts[apex(tets[on.tet[0]], g)]) ==
                       predicates::orient3d(
                           pts[g[0]], pts[g[1]], pts[g[2]], pts[apex(tets[on.tet[1]], g)])) {
            report.add(triangle_name(g, b) + ": its two tetrahedra are on the same side");
        }
    }
}

/// insphere_sos of points v[0..4] keyed on their indices: on the input doubles when there are
/// no implicit points, else on the points' definitions where they are stored (copying each into a
/// GenericPoint3, as generic_point does, cost more than most of these tests).
Sign insphere_of(const PointSet& points, const perturbation::Keys5& v) {
    if (points.exact.empty()) {
        const auto& p = points.points;
        return perturbation::insphere_sos(p[v[0]], p[v[1]], p[v[2]], p[v[3]], p[v[4]], v);
    }
    const auto& e = points.exact;
    return perturbation::insphere_sos(e[v[0]], e[v[1]], e[v[2]], e[v[3]], e[v[4]], v);
}

}  // namespace

CdtValidation validate_cdt(const Plc& plc,
                           std::span<const std::array<std::uint32_t, 4>> tets,
                           CdtDomain domain) {
    CdtValidation result;
    Report report(result);
    const int base = plc.points.index_base;
    const auto b = static_cast<std::uint32_t>(base);
    for (const auto& t : tets) {
        for (std::uint32_t v : t) {
            if (v >= plc.points.size()) {
                report.add(tet_name(t, base) + " names a point that does not exist");
                return result;
            }
        }
    }
    const TriangleSides sides = triangle_sides(tets, plc.points.size());
    const bool carved = domain == CdtDomain::kCarved;
    std::vector<bool> used(plc.points.size(), false);
    for (const auto& t : tets) {
        for (std::uint32_t v : t) {
            used[v] = true;
        }
    }
    if (carved) {
        check_carved_complex(plc, tets, sides, report);
        check_points_outside(plc, tets, used, report);
    } else {
        check_hull_complex(plc, tets, sides, report);
    }
    for (std::size_t v = 0; v < used.size(); ++v) {
        if (!carved && !used[v]) {
            report.add("point " + std::to_string(v + b) + " is not a vertex");
        }
    }
    for (const Edge& e : unprotected_edges(plc, tets)) {
        if (carved && (!used[e[0]] || !used[e[1]])) {
            continue;  // removed with the exterior or a hole
        }
        report.add("PLC edge " + std::to_string(e[0] + b) + "-" + std::to_string(e[1] + b) +
                   " is not an edge of the mesh");
    }
    if (!result.ok()) {
        return result;
    }
    BoxedMesh mesh{tets, {}, plc.points.points};
    mesh.triangles.reserve(sides.size());
    for (const auto& [g, on] : sides) {
        mesh.triangles.push_back(g);
    }
    VertexTriangles around(mesh.triangles, plc.points.size());
    LoopFlood loop_flood(mesh.triangles.size());
    ScanIndex index_of_mesh;
    RationalPoints rational(plc.points);
    SideMemo side_memo(plc.points.size());
    // Sorted like the sides, so one walk along both finds the constrained ones.
    std::vector<Triangle> constrained;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        for (const Triangle& g : polygon_faces(plc,
                                               f,
                                               mesh,
                                               around,
                                               loop_flood,
                                               index_of_mesh,
                                               rational,
                                               side_memo,
                                               carved,
                                               report)) {
            constrained.push_back(g);
        }
    }
    std::sort(constrained.begin(), constrained.end());
    constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
    result.polygon_triangles = constrained.size();
    auto next_constrained = constrained.begin();
    for (const auto& [g, on] : sides) {
        while (next_constrained != constrained.end() && *next_constrained < g) {
            ++next_constrained;
        }
        if (next_constrained != constrained.end() && *next_constrained == g) {
            continue;
        }
        if (on.count == 1) {
            // The hull's boundary was checked convex; a carved domain's must be polygons.
            if (carved) {
                report.add(triangle_name(g, b) + " bounds the carved domain but is in no polygon");
            }
            continue;
        }
        // Stored mirrored, as the perturbation expects orient3d > 0; keys are the indices.
        const auto& t = tets[on.tet[0]];
        const std::uint32_t q = apex(tets[on.tet[1]], g);
        if (insphere_of(plc.points, {t[1], t[0], t[2], t[3], q}) == Sign::kPos) {
            report.add(triangle_name(g, b) + " is in no polygon and not locally Delaunay");
        }
    }
    return result;
}

}  // namespace cavity::core
