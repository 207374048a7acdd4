#include "cavity/core/cdt/edge_protection.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <queue>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/cdt/plc_validity.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/mesh/star.h"
#include "cavity/core/order/insertion_order.h"
#include "dyadic_point.h"
#include "exact_plane.h"
#include "split_point.h"

namespace cavity::core {

DelaunayTriangulation plc_delaunay(const Plc& plc) {
    // The engine's default order (BRIO along a Hilbert curve), not the input's: a surface mesh
    // lists its vertices facet by facet, and in that order each point's cavity reaches far along
    // the front of the points before it (on a 80397-point height field from OpenSCAD's tests, 21 M
    // tetrahedra created and 13 s against 2 M and 0.6 s). The tetrahedra are the same in any order.
    const InsertionOrder order = make_insertion_order(plc.points.points, OrderOptions{});
    DelaunayTriangulation dt(plc.points, order.sequence, TriangulateOptions{});
    if (!dt.duplicates().empty()) {
        const auto& d = dt.duplicates().front();
        throw Error(located_message(plc.source,
                                    std::nullopt,
                                    "points " + std::to_string(d[0] + plc.points.index_base) +
                                        " and " + std::to_string(d[1] + plc.points.index_base) +
                                        " coincide"));
    }
    return dt;
}

void split_plc_edge(Plc& plc, const Edge& e, std::uint32_t m) {
    for (auto& s : plc.segments) {
        if (std::min(s[0], s[1]) == e[0] && std::max(s[0], s[1]) == e[1]) {
            const std::uint32_t other = s[1];
            s[1] = m;
            plc.segments.push_back({m, other});
        }
    }
    for (auto& facet : plc.facets) {
        for (auto& loop : facet.loops) {
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const std::uint32_t p = loop[i];
                const std::uint32_t q = loop[(i + 1) % loop.size()];
                if (std::min(p, q) == e[0] && std::max(p, q) == e[1]) {
                    loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), m);
                    ++i;
                }
            }
        }
    }
}

std::vector<Edge> unprotected_edges(const Plc& plc,
                                    std::span<const std::array<std::uint32_t, 4>> tets) {
    return unprotected_edges(plc_edges(plc), plc.points.size(), tets);
}

std::vector<Edge> unprotected_edges(std::span<const Edge> edges,
                                    std::size_t points,
                                    std::span<const std::array<std::uint32_t, 4>> tets) {
    // The PLC edges, sorted, are runs by their lower end; each tetrahedron edge looks in the run
    // of its lower end (a few edges) instead of every tetrahedron edge being sorted (6 per
    // tetrahedron: the largest cost of the CDT's checks on surface meshes).
    std::vector<std::uint32_t> run(points + 1, 0);
    for (const Edge& e : edges) {
        ++run[e[0] + 1];
    }
    for (std::size_t v = 1; v < run.size(); ++v) {
        run[v] += run[v - 1];
    }
    std::vector<bool> present(edges.size(), false);
    for (const auto& t : tets) {
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = i + 1; j < 4; ++j) {
                const std::uint32_t a = std::min(t[i], t[j]);
                const std::uint32_t b = std::max(t[i], t[j]);
                if (a + 1 >= run.size()) {
                    continue;  // not a point of the PLC: no PLC edge ends there
                }
                for (std::uint32_t k = run[a]; k < run[a + 1]; ++k) {
                    if (edges[k][1] == b) {
                        present[k] = true;
                        break;
                    }
                }
            }
        }
    }
    std::vector<Edge> missing;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        if (!present[k]) {
            missing.push_back(edges[k]);
        }
    }
    return missing;
}

std::vector<Edge> unprotected_edges(const Plc& plc) {
    return unprotected_edges(plc, plc_delaunay(plc).tets());
}

namespace {

std::uint64_t edge_key(std::uint32_t p, std::uint32_t q) {
    return (std::uint64_t{std::min(p, q)} << 32) | std::max(p, q);
}

/// The points that splitting made between p and q (recursively, in order from p to q, q
/// included): how a PLC side p -> q reads after protection.
void append_pieces(const std::unordered_map<std::uint64_t, std::uint32_t>& split_at,
                   std::uint32_t p,
                   std::uint32_t q,
                   std::vector<std::uint32_t>& out) {
    const auto it = split_at.find(edge_key(p, q));
    if (it == split_at.end()) {
        out.push_back(q);
        return;
    }
    append_pieces(split_at, p, it->second, out);
    append_pieces(split_at, it->second, q, out);
}

/// Replaces every PLC segment and loop side by its pieces, once at the end (splitting the PLC at
/// each insertion would cost a pass over it per point).
void apply_splits(Plc& plc, const std::unordered_map<std::uint64_t, std::uint32_t>& split_at) {
    std::vector<std::array<std::uint32_t, 2>> segments;
    std::vector<std::uint32_t> run;
    for (const auto& s : plc.segments) {
        run.assign(1, s[0]);
        append_pieces(split_at, s[0], s[1], run);
        for (std::size_t i = 0; i + 1 < run.size(); ++i) {
            segments.push_back({run[i], run[i + 1]});
        }
    }
    plc.segments = std::move(segments);
    for (auto& facet : plc.facets) {
        for (auto& loop : facet.loops) {
            std::vector<std::uint32_t> split;
            for (std::size_t i = 0; i < loop.size(); ++i) {
                split.push_back(loop[i]);
                append_pieces(split_at, loop[i], loop[(i + 1) % loop.size()], split);
                split.pop_back();  // the next side starts with it
            }
            loop = std::move(split);
        }
    }
}

/// The pieces waiting to be checked, shortest first (squared length on the rounded coordinates,
/// ties by the pair of indices: deterministic). A short missing piece sits among the finest
/// features, and its split there often makes the longer edges nearby Delaunay edges before their
/// turn, where first in, first out halved each long edge first, far from what spoiled it, and then
/// its pieces again. Steiner points over the CDT bench's 77 models: 85740 first in first out,
/// 77615 shortest first (turbine 30395 -> 24280, anchor 10956 -> 8984, oblong 10667 -> 9129; joint
/// 2283 -> 3859, its acute fans worse), 87517 longest first, 84315 last in first out.
class ShortestFirst {
public:
    explicit ShortestFirst(const std::vector<Point3>& points) : points_(points) {}

    void push(const Edge& e) {
        const Point3& a = points_[e[0]];
        const Point3& b = points_[e[1]];
        const double dx = a.x - b.x;
        const double dy = a.y - b.y;
        const double dz = a.z - b.z;
        heap_.push({dx * dx + dy * dy + dz * dz, e});
    }

    bool empty() const { return heap_.empty(); }

    Edge pop() {
        const Edge e = heap_.top().second;
        heap_.pop();
        return e;
    }

private:
    using Entry = std::pair<double, Edge>;
    const std::vector<Point3>& points_;  ///< grows as pieces are split: read at each push
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap_;
};

/// True when piece pq of input edge ab is shorter than 2^-kShellDepth of it: splits have
/// converged on an end that far, which is how a cascade about an acute vertex shows. Halving two
/// edges that meet at angle a stops only when their pieces there differ in length by less than a
/// factor cos a; cheese's edges at 1.2 degrees (1 - cos a = 2e-4) have lengths in the ratio
/// 1.057, which no number of halvings brings that near 1, and went to 2^-52. Concentric shells
/// from the start made more points on organic meshes (pinion 444 -> 11140, the CDT bench's 81
/// models 78950 -> 109013); past 2^-6 they changed seven models (78950 -> 79100), past 2^-12
/// two (78950 -> 78943).
constexpr int kShellDepth = 12;

bool deep_piece(const Point3& p, const Point3& q, const Point3& a, const Point3& b) {
    const auto length2 = [](const Point3& u, const Point3& v) {
        const double dx = u.x - v.x, dy = u.y - v.y, dz = u.z - v.z;
        return dx * dx + dy * dy + dz * dz;
    };
    return length2(p, q) < std::ldexp(length2(a, b), -2 * kShellDepth);
}

/// How near line pq, relative to |pq|, an encroaching input vertex must stand to aim the split
/// of pq. Halving frees pq of a vertex at height h only when the pieces about its projection are
/// about h long, some log2(|pq| / h) rounds of splits there, where one split in the window that
/// frees pq of it does (split_target); an apex at a moderate height is better halved (see
/// protect_edges_live). Steiner points over the CDT bench's 89 meshed models: 72711 halving every
/// input reference, 72052 with 1/64 here (mpi_triang 850 -> 487, mpi 421 -> 147, femur
/// 1056 -> 1042, no model more), 72051 with 1/100; from 1/32 on some models take more
/// (couplingdown 1279 -> 1475 at 1/32), and 1/5 makes 74266 in all.
constexpr double kHuggingHeight = 1.0 / 64;

/// True when w stands within kHuggingHeight |pq| of the line through p and q, over pq's interior.
/// In doubles: it only aims the split.
bool hugs_piece(const Point3& p, const Point3& q, const Point3& w) {
    const auto [s, height2] = projection_on_piece(p, q, w);
    return s > 0 && s < 1 && height2 < kHuggingHeight * kHuggingHeight;
}

/// Split point m rounded to the nearest doubles: in integers when its parameter is dyadic (every
/// implicit split point's is), else, or on an exact tie, by the rationals.
Point3 rounded_split_point(const GenericPoint3& m) {
    if (const auto* s = std::get_if<predicates::SegmentParameterPoint>(&m)) {
        if (const std::optional<Point3> r = rounded_dyadic_point(*s)) {
            return *r;
        }
    }
    return rounded_point(m);
}

/// The live Delaunay triangulation that protect_edges inserts into, with the questions it asks
/// by the PLC's point indices.
class ProtectionMesh {
public:
    explicit ProtectionMesh(DelaunayTriangulation dt) : dt_(std::move(dt)) {
        const Geometry& g = dt_.geometry();
        vertex_.assign(dt_.point_count(), kNoVertex);
        for (VertexId v = 0; v < g.size(); ++v) {
            vertex_[g.key(v)] = v;
        }
    }

    /// The live tetrahedra around point i (its star) into `star`, in vertex_star's order (the
    /// breadth-first order from the vertex's tetrahedron), with a stamp per tetrahedron marking
    /// those found: vertex_star looks each one up in the list, quadratic in the star, and the
    /// stars of the vertices on long split segments hold hundreds of tetrahedra.
    void star(std::uint32_t i, std::vector<TetId>& star) {
        vertex_star_into(
            dt_.storage(), vertex_[i], first_reach(), [](TetId) { return false; }, star);
    }

    /// star(i, star), returning true, or false when point j is a vertex of one of its tetrahedra
    /// (ij is an edge): the search stops at the first such tetrahedron, where most pieces asked
    /// about are edges.
    bool star_unless_edge(std::uint32_t i, std::uint32_t j, std::vector<TetId>& star) {
        const ArrayStorage& storage = dt_.storage();
        const VertexId w = vertex_[j];
        return vertex_star_into(
            storage,
            vertex_[i],
            first_reach(),
            [&](TetId t) {
                const TetVertices& x = storage.vertices(t);
                return std::find(x.begin(), x.end(), w) != x.end();
            },
            star);
    }

    /// Inserts the point with index point_count(), exactly `exact`, rounded `rounded`, locating
    /// it from a solid tetrahedron of `near` (the star of a vertex near it). The split points
    /// are made shortest piece first, all over the model, so from the last insertion the walk
    /// crossed the mesh: on an 80397-point height field this walk was most of the insertions'
    /// time.
    void insert(const GenericPoint3& exact, const Point3& rounded, std::span<const TetId> near) {
        const ArrayStorage& storage = dt_.storage();
        const auto solid = std::find_if(
            near.begin(), near.end(), [&](TetId t) { return !is_ghost(storage.vertices(t)); });
        const std::uint32_t key = dt_.insert(exact, rounded, solid != near.end() ? *solid : kNoTet);
        if (key + 1 != dt_.point_count()) {
            throw InternalError("internal error: a protection point repeats point " +
                                std::to_string(key));
        }
        vertex_.push_back(static_cast<VertexId>(dt_.geometry().size() - 1));
        // An edge that the insertion removed was an edge of a tetrahedron in conflict with the
        // new point, and every vertex of those is a neighbour of the new point afterwards (the
        // triangulation is Delaunay before and after, and no vertex leaves it); the new point is
        // no end of it.
        ++insertions_;
        neighbour_of_.resize(vertex_.size());
        const Geometry& g = dt_.geometry();
        star(key, scratch_);
        for (TetId t : scratch_) {
            for (VertexId w : dt_.storage().vertices(t)) {
                if (w == kGhostVertex || w == vertex_[key]) {
                    continue;
                }
                std::vector<std::uint64_t>& list = neighbour_of_[g.key(w)];
                if (list.empty()) {
                    listed_.push_back(g.key(w));
                }
                if (list.empty() || list.back() != insertions_) {
                    list.push_back(insertions_);
                }
            }
        }
    }

    /// False when no insertion since the last forget_insertions() had both p and q as neighbours
    /// of its point: then none removed edge pq, if it was there.
    bool maybe_removed(std::uint32_t p, std::uint32_t q) const {
        if (p >= neighbour_of_.size() || q >= neighbour_of_.size()) {
            return false;
        }
        const std::vector<std::uint64_t>& a = neighbour_of_[p];
        const std::vector<std::uint64_t>& b = neighbour_of_[q];
        // Both lists are increasing: a merge finds a common insertion.
        for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
            if (a[i] == b[j]) {
                return true;
            }
            if (a[i] < b[j]) {
                ++i;
            } else {
                ++j;
            }
        }
        return false;
    }

    /// Starts maybe_removed afresh from the insertions after this call.
    void forget_insertions() {
        for (const std::uint32_t i : listed_) {
            neighbour_of_[i].clear();
        }
        listed_.clear();
    }

    DelaunayTriangulation release() && { return std::move(dt_); }

    /// The vertex that encroaches most upon edge pq (in the closed diametral ball, the largest
    /// angle p-w-q) among the vertices of the stars of p and q, as a point index; nullopt when
    /// none does. Decided on rounded coordinates: it only aims the split.
    std::optional<std::uint32_t> reference(const std::vector<TetId>& star_p,
                                           const std::vector<TetId>& star_q,
                                           std::uint32_t p,
                                           std::uint32_t q) const {
        const Geometry& g = dt_.geometry();
        const Point3& a = g.point(vertex_[p]);
        const Point3& b = g.point(vertex_[q]);
        std::optional<std::uint32_t> best;
        double best_cos = 0;
        for (const auto* star : {&star_p, &star_q}) {
            for (TetId t : *star) {
                for (VertexId w : dt_.storage().vertices(t)) {
                    if (w == kGhostVertex || w == vertex_[p] || w == vertex_[q]) {
                        continue;
                    }
                    const Point3& x = g.point(w);
                    const double ux = a.x - x.x, uy = a.y - x.y, uz = a.z - x.z;
                    const double vx = b.x - x.x, vy = b.y - x.y, vz = b.z - x.z;
                    const double d = ux * vx + uy * vy + uz * vz;
                    if (d > 0) {
                        continue;  // outside the diametral ball
                    }
                    const double cosine = d / std::sqrt((ux * ux + uy * uy + uz * uz) *
                                                        (vx * vx + vy * vy + vz * vz));
                    if (!best || cosine < best_cos) {
                        best = g.key(w);
                        best_cos = cosine;
                    }
                }
            }
        }
        return best;
    }

private:
    /// vertex_star's first_reach for one search: a tetrahedron is reached for the first time when
    /// its stamp is not this search's.
    struct FirstReach {
        std::vector<std::uint64_t>& found;
        std::uint64_t search;

        bool operator()(const std::vector<TetId>&, TetId t) const {
            return std::exchange(found[t], search) != search;
        }
    };

    /// A fresh search's FirstReach.
    FirstReach first_reach() {
        if (found_.size() < dt_.storage().capacity()) {
            found_.resize(dt_.storage().capacity(), 0);
        }
        return {found_, ++search_};
    }

    DelaunayTriangulation dt_;
    std::vector<VertexId> vertex_;      ///< by point index
    std::vector<std::uint64_t> found_;  ///< by tetrahedron: the last star search that found it
    std::uint64_t search_ = 0;
    /// By point index: the insertions (numbered from 1) since the last forget_insertions() whose
    /// point it neighbours, in order; listed_ holds the indices whose list is not empty.
    std::vector<std::vector<std::uint64_t>> neighbour_of_;
    std::vector<std::uint32_t> listed_;
    std::uint64_t insertions_ = 0;
    std::vector<TetId> scratch_;  ///< the new point's star in insert()
};

}  // namespace

Protection protect_edges(Plc& plc, std::size_t max_points) {
    return protect_edges_live(plc, max_points).protection;
}

ProtectedDelaunay protect_edges_live(Plc& plc, std::size_t max_points) {
    Protection result;
    result.rounds = 1;
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    const auto inputs = static_cast<std::uint32_t>(plc.points.size());
    DelaunayTriangulation dt = plc_delaunay(plc);
    // Built and sorted once: the search for missing edges, the check of those, and the pieces
    // all start from the input's edges.
    std::vector<Edge> pieces = plc_edges(plc);
    const std::vector<Edge> missing = unprotected_edges(pieces, plc.points.size(), dt.tets());
    if (missing.empty()) {
        return {result, std::move(dt)};
    }
    // Splitting never protects an edge that a point lies on or another edge crosses; the pieces
    // of the others inherit the check.
    require_edges_meet_properly(plc, pieces, missing);
    ProtectionMesh mesh(std::move(dt));
    std::unordered_map<std::uint64_t, std::uint32_t> split_at;
    std::vector<Edge> segment_of;  ///< by split point (index - inputs): the input edge it is on
    const auto segment_of_piece = [&](const Edge& e) {
        return e[0] >= inputs   ? segment_of[e[0] - inputs]
               : e[1] >= inputs ? segment_of[e[1] - inputs]
                                : e;
    };
    ShortestFirst queue(plc.points.points);
    for (const Edge& e : missing) {
        queue.push(e);
    }
    // Every piece made so far: a later split can take a protected piece out of the triangulation
    // again, so each pass ends by checking them all. Each piece not split was seen in the
    // triangulation after the previous pass began (in that pass, or when it was popped later):
    // only an insertion since then whose point neighbours both its ends can have removed it, and
    // the others need no star search (homer: 291223 searches, most of them in these passes).
    // The stars of a piece's ends, their vectors kept across iterations: growing fresh ones was
    // three quarters of the cost of the searches themselves.
    std::vector<TetId> star_p;
    std::vector<TetId> star_q;
    const auto recheck = [&](ShortestFirst& out) {
        ++result.rounds;
        for (const Edge& e : pieces) {
            // maybe_removed first: mostly two empty lists, where the hash lookup missed the
            // cache (5% of the time on a height field of 56118 split points).
            if (mesh.maybe_removed(e[0], e[1]) && !split_at.contains(edge_key(e[0], e[1])) &&
                mesh.star_unless_edge(e[0], e[1], star_p)) {
                out.push(e);
            }
        }
        mesh.forget_insertions();
    };
    while (!queue.empty()) {
        const Edge e = queue.pop();
        if (!mesh.star_unless_edge(e[0], e[1], star_p)) {
            if (queue.empty()) {
                recheck(queue);
            }
            continue;  // protected by an earlier split
        }
        const std::string name =
            "edge " + std::to_string(e[0] + base) + "-" + std::to_string(e[1] + base);
        if (result.inserted.size() >= max_points) {
            throw Error(located_message(plc.source,
                                        std::nullopt,
                                        "still not edge-protected after inserting " +
                                            std::to_string(max_points) + " points (" + name + ")"));
        }
        mesh.star(e[1], star_q);
        // A split point aims the split (the window that frees the piece of it). An input vertex
        // that encroaches is most often the apex of a skinny input triangle on pq: a split in
        // its window stands about its height from it and starts cascades there, which halving
        // does not (Steiner points over the CDT bench's 74 models: 37347 -> 33722), unless it
        // hugs pq (hugs_piece), where halving takes many rounds. The sphere about a shared
        // input vertex through the reference (concentric shells) made more points than halving
        // on the bench as well, pinion most (1966 against 445). A split point on another PLC
        // edge through an input end c of a deep piece (an acute angle at c, where splits keep
        // converging) aims it at a concentric shell about c.
        std::optional<Point3> reference;
        std::optional<std::uint32_t> shell_centre;
        const Edge segment = segment_of_piece(e);
        const Point3 p = plc.points.points[e[0]];
        const Point3 q = plc.points.points[e[1]];
        if (const auto w = mesh.reference(star_p, star_q, e[0], e[1]); w && *w >= inputs) {
            reference = plc.points.points[*w];
            const Edge host = segment_of[*w - inputs];
            for (const std::uint32_t c : e) {
                if (c < inputs && (host[0] == c || host[1] == c) &&
                    deep_piece(
                        p, q, plc.points.points[segment[0]], plc.points.points[segment[1]])) {
                    shell_centre = c;
                }
            }
        } else if (w && hugs_piece(p, q, plc.points.points[*w])) {
            reference = plc.points.points[*w];
        }
        const GenericPoint3 gp = generic_point(plc.points, e[0]);
        const GenericPoint3 gq = generic_point(plc.points, e[1]);
        const SplitTarget target = shell_centre ? shell_target(p, q, *shell_centre == e[0])
                                                : split_target(p, q, reference);
        const std::optional<GenericPoint3> m = split_point(gp, gq, target);
        if (!m) {
            throw Error(
                located_message(plc.source,
                                std::nullopt,
                                name + " needs a split, but its pieces are already 2^-52 of it"));
        }
        if (!std::holds_alternative<Point3>(*m) && plc.points.exact.empty()) {
            plc.points.exact.assign(plc.points.points.begin(), plc.points.points.end());
        }
        const auto id = static_cast<std::uint32_t>(plc.points.size());
        const Point3 rounded = rounded_split_point(*m);
        plc.points.points.push_back(rounded);
        if (!plc.points.exact.empty()) {
            plc.points.exact.push_back(*m);
        }
        mesh.insert(*m, rounded, star_p);
        result.inserted.push_back(id);
        split_at.emplace(edge_key(e[0], e[1]), id);
        segment_of.push_back(segment);
        queue.push({e[0], id});
        queue.push({id, e[1]});
        pieces.push_back({e[0], id});
        pieces.push_back({id, e[1]});
    }
    apply_splits(plc, split_at);
    return {result, std::move(mesh).release()};
}

}  // namespace cavity::core
