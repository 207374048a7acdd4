#include "polygon_region.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "cavity/core/base/error.h"
#include "cavity/core/base/id_hash_map.h"
#include "cavity/core/mesh/star.h"
#include "cavity/predicates/generic_predicates.h"
#include "segment_interior.h"
#include "split_triangle.h"

namespace cavity::core {

namespace {

/// A live tetrahedron with vertices u and v found by a search across the facets of u's star from
/// `start` (each tetrahedron counted), or kNoTet when uv is not an edge of the complex.
TetId search_star(
    const ArrayStorage& storage, TetId start, VertexId u, VertexId v, std::uint64_t& steps) {
    std::vector<TetId> queue{start};
    IdHashSet seen;
    seen.insert(start);
    for (std::size_t k = 0; k < queue.size(); ++k) {
        const TetId t = queue[k];
        ++steps;
        const TetVertices& w = storage.vertices(t);
        if (slot_of(w, v) >= 0) {
            return t;
        }
        for (int f = 0; f < 4; ++f) {
            if (w[static_cast<std::size_t>(f)] == u) {
                continue;  // the facet opposite u leaves the star
            }
            const HalfFacet h = storage.adjacent(t, f);
            if (h != kNoHalfFacet && seen.insert(tet_of(h))) {
                queue.push_back(tet_of(h));
            }
        }
    }
    return kNoTet;
}

/// A live tetrahedron with edge uv, or kNoTet when uv is not an edge of the complex. Walks from
/// Adjacent2Vertex(u) through the solid tetrahedra of u's star toward v: from tetrahedron t, it
/// crosses a facet through u that has v strictly beyond it. When no facet does, the ray from u to
/// v lies in t's closed cone at u, and since uv is an edge of the complex (no edge passes through
/// a face or another vertex), v is a vertex of t. A walk that would revisit a tetrahedron or enter
/// a ghost falls back to a search of the whole star. Steps are counted.
TetId tet_with_edge(const ArrayStorage& storage,
                    const Geometry& geometry,
                    VertexId u,
                    VertexId v,
                    std::uint64_t& steps) {
    const TetId start = storage.tet_at_vertex(u);
    if (start == kNoTet) {
        return kNoTet;
    }
    IdHashSet seen;
    TetId t = start;
    if (is_ghost(storage.vertices(t))) {
        // The solid tetrahedron behind the ghost's hull triangle also has u.
        const HalfFacet behind = storage.adjacent(t, 3);
        t = behind == kNoHalfFacet ? t : tet_of(behind);
    }
    while (!is_ghost(storage.vertices(t)) && seen.insert(t)) {
        ++steps;
        const TetVertices& w = storage.vertices(t);
        if (slot_of(w, v) >= 0) {
            return t;
        }
        TetId next = kNoTet;
        for (int f = 0; f < 4 && next == kNoTet; ++f) {
            if (w[static_cast<std::size_t>(f)] == u) {
                continue;
            }
            const auto g = facet_vertices(w, f);
            if (geometry.orient3d(g[0], g[1], g[2], v) == predicates::Sign::kNeg) {
                const HalfFacet h = storage.adjacent(t, f);
                next = h == kNoHalfFacet ? kNoTet : tet_of(h);
            }
        }
        if (next == kNoTet) {
            break;
        }
        t = next;
    }
    return search_star(storage, start, u, v, steps);
}

}  // namespace

FacetGeometry::FacetGeometry(const Geometry& geometry, const Plc& plc, const PlcFacet& facet)
    : geometry_(geometry)
    , plc_(plc)
    , facet_(facet)
    , plane_([&] {
        const auto plane = ExactPlane::of_facet(plc, facet);
        if (!plane) {
            throw Error(
                located_message(plc.source, facet.line, "the facet's corners are all collinear"));
        }
        return *plane;
    }())
    , region_(plc, facet, plane_)
    , triangle_(facet.loops.size() == 1 && facet.loops[0].size() == 3 && facet.holes.empty()) {
    if (!triangle_ && facet.loops.size() == 1 && facet.holes.empty()) {
        if (const auto corners = split_triangle_corners(plc.points, facet.loops[0])) {
            split_triangle_.emplace(std::array<predicates::GenericPoint3, 3>{
                (*corners)[0], (*corners)[1], (*corners)[2]});
            triangle_corners_ = corners;
        }
    } else if (triangle_) {
        std::array<Point3, 3> corners{};
        bool inputs = true;
        for (std::size_t i = 0; i < 3; ++i) {
            const auto g = generic_point(plc.points, facet.loops[0][i]);
            const auto* p = std::get_if<Point3>(&g);
            inputs = inputs && p != nullptr;
            corners[i] = p != nullptr ? *p : Point3{};
        }
        if (inputs) {
            triangle_corners_ = corners;
        }
    }
    share_pieces_ = !triangle_ && !split_triangle_;
    if (triangle_corners_) {
        // The first corner moved along the dropped axis, along which h's normal is not zero.
        const Point3& c = (*triangle_corners_)[0];
        std::array<double, 3> x{c.x, c.y, c.z};
        double& moved = x[static_cast<std::size_t>(plane_.dropped_axis())];
        moved += 2 * (std::abs(moved) + 1);
        off_h_ = {x[0], x[1], x[2]};
        const auto& t = *triangle_corners_;
        triangle_turn_ = std::isfinite(moved)
                             ? predicates::to_int(predicates::orient3d(t[0], t[1], t[2], off_h_))
                             : 0;
        if (triangle_turn_ == 0) {
            triangle_corners_.reset();
        }
    }
    for (const auto& loop : facet.loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const VertexId a = loop[i];
            const VertexId b = loop[(i + 1) % loop.size()];
            const std::array<VertexId, 2> side{std::min(a, b), std::max(a, b)};
            if (side_set_.insert(side).second) {
                sides_.push_back(side);
            }
            corners_.insert(a);
        }
    }
}

const FacetGeometry::Placed& FacetGeometry::placed(VertexId v) {
    auto it = placed_.find(v);
    if (it == placed_.end()) {
        ExactPoint p = exact_point(geometry_.generic(v));
        // A vertex on h (side by orient3d, exact) has offset zero: most vertices placed are, for
        // the centroids of faces in h, and the offset's rational dot product is not needed.
        Rational d = side(v) == 0 ? Rational(0) : plane_.offset(p);
        it = placed_.emplace(v, Placed{std::move(d), std::move(p)}).first;
    }
    return it->second;
}

int FacetGeometry::side(VertexId v) {
    const auto [side, unknown] = vertex_sides_.try_emplace(v);
    if (unknown) {
        *side = static_cast<std::int8_t>(predicates::to_int(plane_.side(geometry_.generic(v))));
    }
    return *side;
}

Rational FacetGeometry::speed(VertexId v) {
    const Placed& p = placed(v);
    return side(v) > 0 ? p.offset : Rational(0);
}

bool FacetGeometry::has_left_and_right(std::span<const VertexId> vs) {
    bool left = false;
    bool right = false;
    for (VertexId v : vs) {
        if (v == kGhostVertex) {
            continue;
        }
        left = left || side(v) < 0;
        right = right || side(v) > 0;
    }
    return left && right;
}

bool FacetGeometry::edge_crosses_region(VertexId a, VertexId b) {
    if (triangle_) {
        return crosses_facet_region(
            plc_, facet_, plane_, region_, geometry_.generic(a), geometry_.generic(b));
    }
    if (split_triangle_) {
        // As crosses_facet_region's triangle: ab turns the same way, strictly, around the three
        // sides of the corners' triangle, the region (no crossing point lies on a loop side).
        const auto& c = *split_triangle_;
        const predicates::GenericPoint3 p = geometry_.generic(a);
        const predicates::GenericPoint3 q = geometry_.generic(b);
        const predicates::Sign first = predicates::orient3d(p, q, c[0], c[1]);
        return first != predicates::Sign::kZero &&
               predicates::orient3d(p, q, c[1], c[2]) == first &&
               predicates::orient3d(p, q, c[2], c[0]) == first;
    }
    if (const auto x = plane_.rounded_crossing(geometry_.rounded(a), geometry_.rounded(b))) {
        if (const std::optional<bool> inside = region_.contains_rounded(*x)) {
            return *inside;
        }
    }
    if (auto x = plane_.projected_crossing(geometry_.generic(a), geometry_.generic(b))) {
        return region_.contains(std::move(*x));
    }
    // The offsets are kept, so the crossing a + along (b - a) needs no plane evaluation; only
    // the coordinates the region's projection keeps are made (FacetRegion::contains).
    const Placed& pa = placed(a);
    const Placed& pb = placed(b);
    const Rational along = pa.offset / (pa.offset - pb.offset);
    ExactPoint x;
    for (std::size_t k = 0; k < 3; ++k) {
        if (static_cast<int>(k) != plane_.dropped_axis()) {
            x[k] = pa.point[k] + along * (pb.point[k] - pa.point[k]);
        }
    }
    return region_.contains(std::move(x));
}

namespace {

/// The sorted key of a vertex or an edge, unused slots kGhostVertex.
std::array<VertexId, 3> piece_key(VertexId a, VertexId b = kGhostVertex) {
    return {std::min(a, b), std::max(a, b), kGhostVertex};
}

}  // namespace

void FacetGeometry::add_pieces_on_h(std::span<const VertexId> on, Pieces& pieces) const {
    for (std::size_t i = 0; i < on.size(); ++i) {
        if (!corners_.contains(on[i])) {
            pieces.keys[pieces.count++] = piece_key(on[i]);
        }
        for (std::size_t j = i + 1; j < on.size(); ++j) {
            if (!side_set_.contains({std::min(on[i], on[j]), std::max(on[i], on[j])})) {
                pieces.keys[pieces.count++] = piece_key(on[i], on[j]);
            }
        }
    }
}

std::optional<bool> FacetGeometry::known(const Pieces& pieces) const {
    for (std::size_t k = 0; k < pieces.count; ++k) {
        if (const auto it = pieces_in_region_.find(pieces.keys[k]); it != pieces_in_region_.end()) {
            return it->second;
        }
    }
    return std::nullopt;
}

void FacetGeometry::learn(const Pieces& pieces, bool inside) {
    for (std::size_t k = 0; k < pieces.count; ++k) {
        pieces_in_region_.emplace(pieces.keys[k], inside);
    }
}

FacetGeometry::Contact FacetGeometry::contact(const TetVertices& t) {
    if (is_ghost(t)) {
        return Contact::kNone;
    }
    // Each vertex's side once: the pairs below asked the table sixteen times per tetrahedron,
    // 0.16 G instructions on homer.
    std::array<int, 4> sides{};
    for (std::size_t i = 0; i < 4; ++i) {
        sides[i] = side(t[i]);
    }
    std::array<VertexId, 3> on{};
    std::size_t count = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        if (sides[i] == 0) {
            on[count++] = t[i];
        }
    }
    // The section's pieces: its left-right edges' crossing points and the simplex on h.
    Pieces pieces;
    std::array<VertexId, 2> first{kGhostVertex, kGhostVertex};
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t j = 0; j < 4; ++j) {
            if (sides[i] < 0 && sides[j] > 0) {
                if (pieces.count == 0) {
                    first = {t[i], t[j]};
                }
                pieces.keys[pieces.count++] = piece_key(t[i], t[j]);
            }
        }
    }
    if (pieces.count == 0) {
        return count > 0 && face_in_region(std::span(on.data(), count)) ? Contact::kTouches
                                                                        : Contact::kNone;
    }
    if (share_pieces_) {
        add_pieces_on_h(std::span(on.data(), count), pieces);
    } else {
        pieces.count = 1;  // the first left-right edge alone
    }
    bool inside = false;
    if (const std::optional<bool> answer = known(pieces)) {
        inside = *answer;
    } else {
        inside = edge_crosses_region(first[0], first[1]);
        learn(pieces, inside);
    }
    return inside ? Contact::kCrosses : Contact::kNone;
}

bool FacetGeometry::holds_triangle(const std::array<VertexId, 3>& g) {
    return side(g[0]) == 0 && side(g[1]) == 0 && side(g[2]) == 0 && face_in_region(g);
}

bool FacetGeometry::face_in_region(std::span<const VertexId> on) {
    if (on.size() == 1 && corners_.contains(on[0])) {
        return false;
    }
    if (on.size() == 2 && side_set_.contains({std::min(on[0], on[1]), std::max(on[0], on[1])})) {
        return false;
    }
    // The face itself first, then (when shared) its vertices and edges off the loops.
    Pieces pieces;
    std::array<VertexId, 3> key{kGhostVertex, kGhostVertex, kGhostVertex};
    std::copy(on.begin(), on.end(), key.begin());
    std::sort(key.begin(), key.end());
    pieces.keys[pieces.count++] = key;
    if (share_pieces_) {
        add_pieces_on_h(on, pieces);
    }
    if (const std::optional<bool> answer = known(pieces)) {
        return *answer;
    }
    const bool inside = face_in_region_tested(on);
    learn(pieces, inside);
    return inside;
}

bool FacetGeometry::face_in_region_tested(std::span<const VertexId> on) {
    if (triangle_corners_) {
        if (const std::optional<bool> inside = face_in_triangle(on)) {
            return *inside;
        }
    }
    // A face on h has one to three vertices (the bound also shows the compiler the arrays hold
    // them).
    const std::size_t count = std::min<std::size_t>(on.size(), 3);
    // The centroid in doubles first: the exact one costs a rational per coordinate.
    std::array<predicates::RoundedPoint, 3> rounded;
    for (std::size_t i = 0; i < count; ++i) {
        rounded[i] = geometry_.rounded(on[i]);
    }
    if (const auto c = rounded_centroid(std::span(rounded.data(), count), plane_.dropped_axis())) {
        if (const std::optional<bool> inside = region_.contains_rounded(*c)) {
            return *inside;
        }
    }
    // Only the coordinates the region's projection keeps (FacetRegion::contains).
    std::array<predicates::GenericPoint3, 3> points;
    for (std::size_t i = 0; i < count; ++i) {
        points[i] = geometry_.generic(on[i]);
    }
    if (auto centroid =
            projected_centroid(std::span(points.data(), count), plane_.dropped_axis())) {
        return region_.contains(std::move(*centroid));
    }
    // A line-plane point (or a parameter 0 / 0): the vertices' rational coordinates, kept.
    const auto drop = static_cast<std::size_t>(plane_.dropped_axis());
    ExactPoint centroid{0, 0, 0};
    for (VertexId v : on) {
        const ExactPoint& p = placed(v).point;
        for (std::size_t k = 0; k < 3; ++k) {
            if (k != drop) {
                centroid[k] += p[k];
            }
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        if (k != drop) {
            centroid[k] /= static_cast<int>(on.size());
        }
    }
    return region_.contains(std::move(centroid));
}

std::uint8_t FacetGeometry::triangle_position(VertexId v) {
    if (const auto it = triangle_positions_.find(v); it != triangle_positions_.end()) {
        return it->second;
    }
    const auto& c = *triangle_corners_;
    const predicates::GenericPoint3 x = geometry_.generic(v);
    // Positive strictly inside side i's line, in h.
    const auto inward = [&](std::size_t i, const predicates::GenericPoint3& p) {
        return triangle_turn_ *
               predicates::to_int(predicates::orient3d(c[i], c[(i + 1) % 3], p, off_h_));
    };
    // Which corner p is, or 3.
    const auto corner = [&](const Point3& p) {
        std::size_t k = 0;
        while (k < 3 && !(c[k].x == p.x && c[k].y == p.y && c[k].z == p.z)) {
            ++k;
        }
        return k;
    };
    // Most vertices asked about are the loop's corners: the triangle's, on the lines of their
    // two sides, and the split points strictly inside a side, on its line only. Their positions
    // need no predicate, where each of their zero orientations was an exact evaluation.
    std::optional<std::uint8_t> known;
    if (const auto* p = std::get_if<Point3>(&x)) {
        if (const std::size_t k = corner(*p); k < 3) {
            known = static_cast<std::uint8_t>((1u << k) | (1u << ((k + 2) % 3)));
        }
    } else if (const auto* split = std::get_if<predicates::SegmentParameterPoint>(&x)) {
        const std::size_t ka = corner(split->a);
        const std::size_t kb = corner(split->b);
        if (strictly_inside(*split) && ka < 3 && kb < 3 && ka != kb) {
            known = static_cast<std::uint8_t>(1u << (kb == (ka + 1) % 3 ? ka : kb));
        }
    }
    if (known) {
        triangle_positions_.emplace(v, *known);
        return *known;
    }
    std::uint8_t position = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        std::optional<int> s;
        if (const auto* p = std::get_if<predicates::SegmentParameterPoint>(&x)) {
            // orient3d is affine in its third point, so strictly inside segment ab its sign is
            // that of the ends when they agree or one of them is zero (a split point of a side
            // lies on that side's line, where an implicit point's zero is the dearest answer).
            if (strictly_inside(*p)) {
                const int sa = inward(i, p->a);
                const int sb = inward(i, p->b);
                if (sa == sb || sb == 0) {
                    s = sa;
                } else if (sa == 0) {
                    s = sb;
                }
            }
        }
        const int sign = s ? *s : inward(i, x);
        if (sign == 0) {
            position = static_cast<std::uint8_t>(position | (1u << i));
        } else if (sign < 0) {
            position = static_cast<std::uint8_t>(position | 8u);
        }
    }
    triangle_positions_.emplace(v, position);
    return position;
}

std::optional<bool> FacetGeometry::face_in_triangle(std::span<const VertexId> on) {
    // The relative interior of a face on h avoids the loop sides (see the class), so it is
    // wholly inside or outside the open triangle, and so is the closure's part off the sides: a
    // vertex strictly inside or outside decides. A face whose vertices are all on the sides' lines
    // is inside unless they share one line: its relative interior then lies in the convex closed
    // triangle's interior. Otherwise (a side's piece, or vertices both inside and outside, which
    // a complex does not have) the centroid decides, as before.
    bool inside = false;
    bool outside = false;
    unsigned shared = 7;
    for (VertexId v : on) {
        const std::uint8_t position = triangle_position(v);
        if ((position & 8u) != 0) {
            outside = true;
        } else if (position == 0) {
            inside = true;
        }
        shared &= position;
    }
    if (inside != outside) {
        return inside;
    }
    if (inside || (shared & 7u) != 0) {
        return std::nullopt;
    }
    return true;
}

PolygonRegion find_polygon_region(const ArrayStorage& storage, FacetGeometry& facet) {
    using Contact = FacetGeometry::Contact;
    PolygonRegion region;
    IdHashSet tested;
    std::vector<TetId> stack;
    // Tests t once; a touching or crossing t joins its list and waits on the stack for its
    // neighbours to be tested.
    const auto test = [&](TetId t) {
        if (!tested.insert(t)) {
            return;
        }
        const Contact c = facet.contact(storage.vertices(t));
        if (c != Contact::kNone) {
            (c == Contact::kCrosses ? region.tets : region.touching_outside).push_back(t);
            stack.push_back(t);
        }
    };
    const Plc& plc = facet.plc();
    for (const auto& [u, v] : facet.loop_sides()) {
        // Step 1: the rotary search around the side.
        const TetId start = tet_with_edge(storage, facet.geometry(), u, v, region.rotary_steps);
        if (start == kNoTet) {
            const auto base = static_cast<VertexId>(plc.points.index_base);
            throw Error(located_message(
                plc.source,
                facet.facet().line,
                "polygon side " + std::to_string(u + base) + "-" + std::to_string(v + base) +
                    " is not an edge of the triangulation (is the PLC edge-protected?)"));
        }
        const TetVertices& w = storage.vertices(start);
        const EdgeRing ring = edge_ring(storage, start, slot_of(w, u), slot_of(w, v));
        for (TetId t : ring.tets) {
            ++region.rotary_steps;
            test(t);
        }
        // Step 2: the depth-first search from what the rotary search found.
        while (!stack.empty()) {
            const TetId t = stack.back();
            stack.pop_back();
            for (int f = 0; f < 4; ++f) {
                const HalfFacet h = storage.adjacent(t, f);
                if (h != kNoHalfFacet && !tested.contains(tet_of(h))) {
                    ++region.search_visited;
                    test(tet_of(h));
                }
            }
        }
    }
    std::vector<VertexId> vertices;
    for (TetId t : region.tets) {
        const TetVertices& w = storage.vertices(t);
        vertices.insert(vertices.end(), w.begin(), w.end());
    }
    std::sort(vertices.begin(), vertices.end());
    region.vertices = static_cast<std::uint64_t>(std::unique(vertices.begin(), vertices.end()) -
                                                 vertices.begin());
    return region;
}

bool is_face(const ArrayStorage& storage,
             const Geometry& geometry,
             const std::array<VertexId, 3>& abc,
             std::uint64_t& steps) {
    const TetId t = tet_with_edge(storage, geometry, abc[0], abc[1], steps);
    if (t == kNoTet) {
        return false;
    }
    const TetVertices& w = storage.vertices(t);
    const EdgeRing around = edge_ring(storage, t, slot_of(w, abc[0]), slot_of(w, abc[1]));
    steps += around.tets.size();
    return std::find(around.ring.begin(), around.ring.end(), abc[2]) != around.ring.end();
}

}  // namespace cavity::core
