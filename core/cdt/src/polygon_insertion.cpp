#include "cavity/core/cdt/polygon_insertion.h"

#include <algorithm>
#include <map>
#include <optional>
#include <queue>
#include <string>
#include <unordered_set>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/edit/flips.h"
#include "cavity/core/mesh/star.h"
#include "exact_plane.h"
#include "polygon_region.h"

namespace cavity::core {

namespace {

/// An event time: -S0/S1 followed by the coefficients of eps^(k+1) in increasing key k (a lower key
/// has the larger perturbation, so it decides first).
struct EventTime {
    Rational base;
    std::vector<std::pair<std::uint32_t, Rational>> terms;  // increasing key, nonzero coefficients
};

int compare(const EventTime& a, const EventTime& b) {
    if (a.base != b.base) {
        return a.base < b.base ? -1 : 1;
    }
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.terms.size() || j < b.terms.size()) {
        const std::uint32_t ka = i < a.terms.size() ? a.terms[i].first : 0xFFFF'FFFFu;
        const std::uint32_t kb = j < b.terms.size() ? b.terms[j].first : 0xFFFF'FFFFu;
        const Rational va = ka <= kb ? a.terms[i].second : Rational(0);
        const Rational vb = kb <= ka ? b.terms[j].second : Rational(0);
        if (va != vb) {
            return va < vb ? -1 : 1;
        }
        i += ka <= kb ? 1 : 0;
        j += kb <= ka ? 1 : 0;
    }
    return 0;
}

struct Event {
    EventTime time;
    std::uint64_t order;  // queue order among exactly simultaneous events
    TetId tet;
    int facet;
    TetVertices snapshot;
    VertexId apex;
};

struct Later {
    bool operator()(const Event& a, const Event& b) const {
        const int c = compare(a.time, b.time);
        return c != 0 ? c > 0 : a.order > b.order;
    }
};

Rational det3(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

std::array<VertexId, 3> sorted_triangle(std::array<VertexId, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
}

/// The state of one FlipInsertPolygon call.
class PolygonInserter {
public:
    PolygonInserter(ArrayStorage& storage,
                    const Geometry& geometry,
                    const Plc& plc,
                    std::size_t facet,
                    ConstrainedFaces& constrained,
                    PolygonInsertionCounters& counters)
        : storage_(storage)
        , geometry_(geometry)
        , plc_(plc)
        , facet_(geometry, plc, plc.facets[facet])
        , name_(facet_name(plc, facet))
        , constrained_(constrained)
        , counters_(counters) {
        work_.facet = static_cast<std::uint32_t>(facet);
    }

    std::vector<std::array<VertexId, 3>> run() {
        find_region();
        const std::uint64_t flips_before = total_flips();
        const std::uint64_t events_before = counters_.events_queued;
        // Step 3, in tetrahedron order so that exactly simultaneous events keep a fixed order.
        std::vector<TetId> region = region_.tets;
        std::sort(region.begin(), region.end());
        for (TetId t : region) {
            for (int f = 0; f < 4; ++f) {
                const HalfFacet h = storage_.adjacent(t, f);
                if (h != kNoHalfFacet && tet_of(h) > t) {
                    certify(t, f);
                }
            }
        }
        drain_queue();
        auto faces = finish();
        work_.flips = total_flips() - flips_before;
        work_.events_queued = counters_.events_queued - events_before;
        counters_.per_polygon.push_back(work_);
        return faces;
    }

private:
    std::uint64_t total_flips() const {
        std::uint64_t n = 0;
        for (std::uint64_t k : counters_.flips.flips) {
            n += k;
        }
        return n;
    }

    bool in_region(TetId t) const { return in_region_.contains(t); }

    /// Steps 1-2: R by the rotary and depth-first searches (polygon_region.h).
    void find_region() {
        region_ = find_polygon_region(storage_, facet_);
        in_region_.insert(region_.tets.begin(), region_.tets.end());
        work_.region_vertices = region_.vertices;
        work_.region_tets = region_.tets.size();
        work_.rotary_steps = region_.rotary_steps;
        work_.search_visited = region_.search_visited;
        counters_.region_tets += work_.region_tets;
        counters_.region_vertices += work_.region_vertices;
        counters_.max_region_vertices =
            std::max(counters_.max_region_vertices, work_.region_vertices);
        counters_.rotary_steps += work_.rotary_steps;
        counters_.search_visited += work_.search_visited;
    }

    /// Certify(g, Q) for facet f of tetrahedron t.
    void certify(TetId t, int f) {
        const HalfFacet across = storage_.adjacent(t, f);
        if (across == kNoHalfFacet || !in_region(t) || !in_region(tet_of(across))) {
            return;
        }
        const TetVertices& sigma = storage_.vertices(t);
        const auto g = facet_vertices(sigma, f);
        if (!facet_.has_left_and_right(g) || constrained_.contains(sorted_triangle(g))) {
            return;
        }
        ++counters_.certify_calls;
        const VertexId q =
            storage_.vertices(tet_of(across))[static_cast<std::size_t>(facet_of(across))];
        // S = det[p_i - q, H_i - H_q] (> 0: the lifted q is below aff sigma+), linear in each
        // height: S = sum_i (H_i - H_q) C_i with C_i the cofactors of the height column.
        // The facet keeps each vertex's rational point: certify asks about the same few
        // vertices again and again.
        const ExactPoint& eq = facet_.point(q);
        std::array<ExactPoint, 4> rows;
        for (std::size_t i = 0; i < 4; ++i) {
            const ExactPoint& p = facet_.point(sigma[i]);
            rows[i] = {p[0] - eq[0], p[1] - eq[1], p[2] - eq[2]};
        }
        std::array<Rational, 4> cofactor;
        for (std::size_t i = 0; i < 4; ++i) {
            std::array<ExactPoint, 3> minor;
            for (std::size_t r = 0, k = 0; r < 4; ++r) {
                if (r != i) {
                    minor[k++] = rows[r];
                }
            }
            const Rational m = det3(minor[0], minor[1], minor[2]);
            cofactor[i] = ((i + 3) % 2 == 0) ? m : Rational(-m);
        }
        const auto lift = [&](VertexId v) {
            const ExactPoint& e = facet_.point(v);
            return Rational(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        };
        Rational s0 = 0;
        Rational s1 = 0;
        const Rational hq = lift(q);
        const Rational vq = facet_.speed(q);
        Rational sum = 0;
        for (std::size_t i = 0; i < 4; ++i) {
            s0 += (lift(sigma[i]) - hq) * cofactor[i];
            s1 += (facet_.speed(sigma[i]) - vq) * cofactor[i];
            sum += cofactor[i];
        }
        if (s1 <= 0) {
            return;  // never reflex as the right vertices rise
        }
        // Point k's height drops by eps^(k+1): S gains -dS/dH_k eps^(k+1), so the zero moves to
        // kappa = -S0/S1 + sum_k (dS/dH_k / S1) eps^(k+1).
        Event event{EventTime{Rational(-s0 / s1), {}}, next_order_++, t, f, sigma, q};
        std::vector<std::pair<std::uint32_t, Rational>> terms;
        for (std::size_t i = 0; i < 4; ++i) {
            terms.emplace_back(geometry_.key(sigma[i]), cofactor[i] / s1);
        }
        terms.emplace_back(geometry_.key(q), Rational(-sum / s1));
        std::sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) {
            return a.first < b.first;
        });
        for (auto& term : terms) {
            if (term.second != 0) {
                event.time.terms.push_back(std::move(term));
            }
        }
        ++counters_.events_queued;
        queue_.push(std::move(event));
    }

    bool still_there(const Event& e) const {
        if (!storage_.alive(e.tet) || storage_.vertices(e.tet) != e.snapshot) {
            return false;
        }
        const HalfFacet h = storage_.adjacent(e.tet, e.facet);
        return h != kNoHalfFacet &&
               storage_.vertices(tet_of(h))[static_cast<std::size_t>(facet_of(h))] == e.apex;
    }

    /// Whether a flip of the tetrahedra around an edge stays in R and keeps constrained facets.
    bool admissible_ring(const EdgeRing& ring) const {
        for (TetId t : ring.tets) {
            if (!in_region(t)) {
                return false;
            }
        }
        for (VertexId r : ring.ring) {
            if (constrained_.contains(sorted_triangle({ring.u, ring.v, r}))) {
                return false;
            }
        }
        return true;
    }

    /// Flip(T, g): the flip that eliminates the event's facet, if it is admissible now.
    std::vector<TetId> flip(const Event& e) {
        const TetVertices& sigma = storage_.vertices(e.tet);
        const VertexId p = sigma[static_cast<std::size_t>(e.facet)];
        const auto& slots = kFacetVertices[static_cast<std::size_t>(e.facet)];
        // For each edge (slot a, slot b) of g with opposite slot c: is q beyond the plane (a, b,
        // p) from c (-1), on it (0), or on c's side (+1)?
        std::array<int, 3> where{};
        for (std::size_t k = 0; k < 3; ++k) {
            const VertexId a = sigma[static_cast<std::size_t>(slots[k])];
            const VertexId b = sigma[static_cast<std::size_t>(slots[(k + 1) % 3])];
            const VertexId c = sigma[static_cast<std::size_t>(slots[(k + 2) % 3])];
            const Sign sc = geometry_.orient3d(a, b, p, c);
            const Sign sq = geometry_.orient3d(a, b, p, e.apex);
            where[k] = sq == Sign::kZero ? 0 : sq == sc ? 1 : -1;
        }
        const int beyond = static_cast<int>(std::count(where.begin(), where.end(), -1));
        const int on = static_cast<int>(std::count(where.begin(), where.end(), 0));
        if (beyond == 0 && on == 0) {
            return flip23(storage_, geometry_, half_facet(e.tet, e.facet), counters_.flips);
        }
        if (beyond + on != 1) {
            return {};
        }
        const std::size_t k = static_cast<std::size_t>(
            std::find_if(where.begin(), where.end(), [](int w) { return w != 1; }) - where.begin());
        const int i = slots[k];
        const int j = slots[(k + 1) % 3];
        const EdgeRing ring = edge_ring(storage_, e.tet, i, j);
        if (!admissible_ring(ring)) {
            return {};
        }
        if (beyond == 1) {
            return ring.tets.size() == 3 ? flip32(storage_, geometry_, e.tet, i, j, counters_.flips)
                                         : std::vector<TetId>{};
        }
        if (ring.tets.size() != 4) {
            return {};
        }
        const auto at = std::find(ring.ring.begin(), ring.ring.end(), p) - ring.ring.begin();
        return flip44(storage_, geometry_, e.tet, i, j, static_cast<int>(at % 2), counters_.flips);
    }

    /// Step 4, with inadmissible flips held back until another flip has changed the complex.
    void drain_queue() {
        std::vector<Event> held;
        while (!queue_.empty()) {
            Event e = queue_.top();
            queue_.pop();
            if (!still_there(e)) {
                ++counters_.events_stale;
                continue;
            }
            const std::vector<TetId> created = flip(e);
            if (created.empty()) {
                ++counters_.events_held;
                held.push_back(std::move(e));
                continue;
            }
            storage_.end_operation();
            in_region_.insert(created.begin(), created.end());
            created_.insert(created_.end(), created.begin(), created.end());
            // Every facet of the new tetrahedra, each once. A facet inside a 2-3 or 3-2 flip
            // joins two tetrahedra on the flip's five vertices, whose lifted images are
            // cohyperplanar only now, so it can never turn reflex; but a 4-4 flip joins six
            // vertices, and two of its four inner facets (those missing an end of the old edge)
            // belong to five points that may become cohyperplanar later.
            for (TetId t : created) {
                for (int f = 0; f < 4; ++f) {
                    const HalfFacet h = storage_.adjacent(t, f);
                    if (h != kNoHalfFacet &&
                        (tet_of(h) > t ||
                         std::find(created.begin(), created.end(), tet_of(h)) == created.end())) {
                        certify(t, f);
                    }
                }
            }
            for (Event& back : held) {
                queue_.push(std::move(back));
            }
            held.clear();
        }
        for (const Event& e : held) {
            if (still_there(e)) {
                throw Error(located_message(
                    plc_.source,
                    facet_.facet().line,
                    name_ + ": polygon insertion stuck on inadmissible flips (the PLC has no "
                            "CDT here; is it edge-protected?)"));
            }
        }
    }

    /// The polygon's triangles, after checking that no tetrahedron crosses it any more. Flips
    /// delete only tetrahedra of R, so the tetrahedra that touch the polygon now are the touching
    /// ones outside R, which never change, and the survivors of R and of the flips' creations.
    std::vector<std::array<VertexId, 3>> finish() {
        std::vector<TetId> candidates = region_.touching_outside;
        candidates.insert(candidates.end(), region_.tets.begin(), region_.tets.end());
        candidates.insert(candidates.end(), created_.begin(), created_.end());
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        std::set<std::array<VertexId, 3>> faces;
        for (TetId t : candidates) {
            if (!storage_.alive(t) || is_ghost(storage_.vertices(t))) {
                continue;
            }
            const TetVertices& v = storage_.vertices(t);
            if (in_region(t) && facet_.crosses(v)) {
                throw Error(located_message(plc_.source,
                                            facet_.facet().line,
                                            name_ + ": a tetrahedron still crosses the polygon "
                                                    "after every flip"));
            }
            for (int f = 0; f < 4; ++f) {
                const auto g = facet_vertices(v, f);
                if (facet_.holds_triangle(g)) {
                    faces.insert(sorted_triangle(g));
                }
            }
        }
        constrained_.insert(faces.begin(), faces.end());
        ++counters_.polygons;
        return {faces.begin(), faces.end()};
    }

    ArrayStorage& storage_;
    const Geometry& geometry_;
    const Plc& plc_;
    FacetGeometry facet_;
    std::string name_;
    ConstrainedFaces& constrained_;
    PolygonInsertionCounters& counters_;
    PolygonWork work_;
    PolygonRegion region_;
    std::unordered_set<TetId> in_region_;  // R and every tetrahedron the flips created
    std::vector<TetId> created_;
    std::priority_queue<Event, std::vector<Event>, Later> queue_;
    std::uint64_t next_order_ = 0;
};

/// A polygon that is one triangle without hole points and already a face of the complex: R is
/// empty (a face of a triangulation crosses no tetrahedron), so FlipInsertPolygon makes no flip
/// and returns that triangle. Checked first because a surface mesh's polygons are mostly such
/// triangles, and the general path builds the polygon's exact plane in rational arithmetic. Its
/// work is recorded as the general path's would be, with the edge walk and ring as rotary steps.
std::optional<std::array<VertexId, 3>> present_triangle(const ArrayStorage& storage,
                                                        const Geometry& geometry,
                                                        const Plc& plc,
                                                        std::size_t facet,
                                                        PolygonInsertionCounters& counters) {
    const PlcFacet& polygon = plc.facets[facet];
    if (polygon.loops.size() != 1 || polygon.loops[0].size() != 3 || !polygon.holes.empty()) {
        return std::nullopt;
    }
    const std::array<VertexId, 3> abc{
        polygon.loops[0][0], polygon.loops[0][1], polygon.loops[0][2]};
    PolygonWork work;
    work.facet = static_cast<std::uint32_t>(facet);
    if (!is_face(storage, geometry, abc, work.rotary_steps)) {
        return std::nullopt;
    }
    counters.rotary_steps += work.rotary_steps;
    counters.per_polygon.push_back(work);
    ++counters.polygons;
    return sorted_triangle(abc);
}

}  // namespace

std::vector<std::array<VertexId, 3>> insert_polygon(ArrayStorage& storage,
                                                    const Geometry& geometry,
                                                    const Plc& plc,
                                                    std::size_t facet,
                                                    ConstrainedFaces& constrained,
                                                    PolygonInsertionCounters& counters) {
    if (auto present = present_triangle(storage, geometry, plc, facet, counters)) {
        constrained.insert(*present);
        return {*present};
    }
    auto triangles = PolygonInserter(storage, geometry, plc, facet, constrained, counters).run();
    CAVITY_EXPENSIVE_CHECK(check_complex(storage, geometry), "the complex after a polygon");
    return triangles;
}

std::vector<TetId> polygon_region(const ArrayStorage& storage,
                                  const Geometry& geometry,
                                  const Plc& plc,
                                  std::size_t facet,
                                  PolygonWork* work) {
    FacetGeometry geometry_of_facet(geometry, plc, plc.facets[facet]);
    PolygonRegion region = find_polygon_region(storage, geometry_of_facet);
    if (work != nullptr) {
        *work = PolygonWork{};
        work->facet = static_cast<std::uint32_t>(facet);
        work->region_vertices = region.vertices;
        work->region_tets = region.tets.size();
        work->rotary_steps = region.rotary_steps;
        work->search_visited = region.search_visited;
    }
    return std::move(region.tets);
}

}  // namespace cavity::core
