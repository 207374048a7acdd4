#include "cavity/core/geometry/geometry.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "cavity/core/base/assert.h"
#include "cavity/predicates/generic_predicates.h"

namespace cavity::core {

Geometry::Geometry(std::vector<Point3> points,
                   std::vector<std::uint32_t> keys,
                   std::vector<double> weights,
                   std::vector<GenericPoint3> exact)
    : points_(std::move(points))
    , keys_(std::move(keys))
    , weights_(std::move(weights))
    , exact_(std::move(exact))
    , plain_(weights_.empty() && exact_.empty()) {
    // Implicit points are the CDT's, which is unweighted.
    CAVITY_ASSERT(exact_.empty() || (exact_.size() == points_.size() && weights_.empty()),
                  "implicit points need one definition per point and no weights");
    errors_.reserve(exact_.size());
    for (std::size_t i = 0; i < exact_.size(); ++i) {
        errors_.push_back(predicates::rounding_error(exact_[i], points_[i]));
    }
    if (points_.empty()) {
        return;
    }
    box_lo_ = points_.front();
    box_hi_ = points_.front();
    for (const Point3& p : points_) {
        box_lo_ = {std::min(box_lo_.x, p.x), std::min(box_lo_.y, p.y), std::min(box_lo_.z, p.z)};
        box_hi_ = {std::max(box_hi_.x, p.x), std::max(box_hi_.y, p.y), std::max(box_hi_.z, p.z)};
    }
    // The box first: it rejects most non-lattice inputs before any point is looked at again, and
    // the integer scan stops at the first fractional coordinate.
    lattice_ = plain_ && predicates::is_lattice_box(box_lo_, box_hi_) &&
               std::all_of(points_.begin(), points_.end(), [](const Point3& p) {
                   return predicates::is_integral(p);
               });
    make_static_filters();
}

void Geometry::make_static_filters() {
    insphere_static_ = lattice_ ? predicates::InsphereStaticFilter::exact()
                                : predicates::InsphereStaticFilter(box_lo_, box_hi_);
    orient3d_static_ = predicates::Orient3dStaticFilter(box_lo_, box_hi_);
    staged_lattice_ = lattice_ && predicates::is_staged_lattice_box(box_lo_, box_hi_);
}

VertexId Geometry::append_implicit(const GenericPoint3& exact,
                                   const Point3& rounded,
                                   std::uint32_t key) {
    CAVITY_ASSERT(!weighted(), "implicit points are unweighted");
    if (!has_implicit()) {
        exact_.assign(points_.begin(), points_.end());
        errors_.assign(points_.size(), 0.0);
        plain_ = false;
    }
    // Not a lattice any more, even when the rounded point is an integer point: the plain
    // determinants would see the rounded coordinates, not the definition. widen_box keeps it off
    // and remakes the static filters without the lattice's exact one.
    lattice_ = false;
    points_.push_back(rounded);
    widen_box(rounded);
    exact_.push_back(exact);
    errors_.push_back(predicates::rounding_error(exact, rounded));
    keys_.push_back(key);
    return static_cast<VertexId>(points_.size() - 1);
}

void Geometry::widen_box(const Point3& p) {
    if (points_.size() == 1) {
        box_lo_ = p;
        box_hi_ = p;
    }
    box_lo_ = {std::min(box_lo_.x, p.x), std::min(box_lo_.y, p.y), std::min(box_lo_.z, p.z)};
    box_hi_ = {std::max(box_hi_.x, p.x), std::max(box_hi_.y, p.y), std::max(box_hi_.z, p.z)};
    if (points_.size() == 1) {
        lattice_ = plain_;  // the empty set was vacuously a lattice
    }
    lattice_ =
        lattice_ && predicates::is_integral(p) && predicates::is_lattice_box(box_lo_, box_hi_);
    make_static_filters();
}

namespace {

/// A perturbed test's deciding stage and its tie-break's work, when the tally counts.
template <Tally T>
void count(const perturbation::SosVerdict& v, PredicateKind kind, T& tally) {
    if constexpr (T::kCounting) {
        tally.count_predicate(kind, v.stage);
        if (v.cofactors > 0) {
            ++tally.perturbations;
            tally.perturbation_cofactors += v.cofactors;
        }
    }
}

/// True when the four points are integer points: the lattice routes' test that the plain
/// determinant of these points is exact. `&`, not `&&`: one branch on the combined answer (the
/// tests in locals first: clang warns of `&` between calls).
[[gnu::always_inline]] inline bool all_integral(const Point3& a,
                                                const Point3& b,
                                                const Point3& c,
                                                const Point3& d) {
    const bool ia = predicates::is_integral(a);
    const bool ib = predicates::is_integral(b);
    const bool ic = predicates::is_integral(c);
    const bool id = predicates::is_integral(d);
    return ia & ib & ic & id;
}

}  // namespace

predicates::Verdict Geometry::orient3d_generic(VertexId a,
                                               VertexId b,
                                               VertexId c,
                                               VertexId d) const {
    if (const int s =
            predicates::orient3d_rounded(rounded(a), rounded(b), rounded(c), rounded(d))) {
        return {s > 0 ? Sign::kPos : Sign::kNeg, predicates::Stage::kFilter};
    }
    return predicates::orient3d_staged(exact_[a], exact_[b], exact_[c], exact_[d]);
}

Sign Geometry::orient3d_on_lattice_or_exact(const Point3& a,
                                            const Point3& b,
                                            const Point3& c,
                                            const Point3& d) const {
    // Integer points in the box have an exact plain determinant; the walks' other points (the
    // straight walk's source) need not be integer points and take the exact predicate.
    if (all_integral(a, b, c, d)) {
        return predicates::orient3d_on_lattice(a, b, c, d);
    }
    return predicates::orient3d(a, b, c, d);
}

predicates::Verdict Geometry::orient3d_staged_on_lattice_or_staged(const Point3& a,
                                                                   const Point3& b,
                                                                   const Point3& c,
                                                                   const Point3& d) const {
    // Points in the box have small coordinates on a staged lattice; integer ones are lattice
    // points.
    if (all_integral(a, b, c, d)) {
        return predicates::orient3d_staged_on_lattice(a, b, c, d);
    }
    return predicates::orient3d_staged(a, b, c, d);
}

Sign Geometry::orient3d(VertexId a, VertexId b, VertexId c, const GenericPoint3& d) const {
    return predicates::orient3d(generic(a), generic(b), generic(c), d);
}

bool Geometry::tie_breaks_into(const TetVertices& t, VertexId u) const {
    const perturbation::Keys5 keys{keys_[t[0]], keys_[t[1]], keys_[t[2]], keys_[t[3]], keys_[u]};
    if (lattice_) {
        return perturbation::detail::sos_tie_on_lattice(
                   point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u), keys) ==
               Sign::kPos;
    }
    return perturbation::detail::sos_tie(
               point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u), keys) == Sign::kPos;
}

bool Geometry::tie_breaks_into(const TetVertices& t, VertexId u, Counters& tally) const {
    const perturbation::Keys5 keys{keys_[t[0]], keys_[t[1]], keys_[t[2]], keys_[t[3]], keys_[u]};
    // The cofactors' stages are not counted, only how many there were: on a lattice the plain
    // engine's route gives the same count at about half the cost of the staged cofactors (ties
    // are most of a grid's insphere tests).
    const perturbation::detail::SosTie tie =
        lattice_ ? perturbation::detail::sos_tie_on_lattice_counted(
                       point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u), keys)
                 : perturbation::detail::sos_tie_counted(
                       point(t[0]), point(t[1]), point(t[2]), point(t[3]), point(u), keys);
    ++tally.perturbations;
    tally.perturbation_cofactors += tie.cofactors;
    return tie.sign == Sign::kPos;
}

template <Tally T>
bool Geometry::conflicts_solid_exactly(const TetVertices& t, VertexId u, T& tally) const {
    const perturbation::Keys5 keys{keys_[t[0]], keys_[t[1]], keys_[t[2]], keys_[t[3]], keys_[u]};
    if (has_implicit()) {
        // A nonzero exact determinant is the perturbed one's sign: no tie-break to run.
        if (const int s = predicates::insphere_rounded(
                rounded(t[0]), rounded(t[1]), rounded(t[2]), rounded(t[3]), rounded(u))) {
            count(
                perturbation::SosVerdict{
                    s > 0 ? Sign::kPos : Sign::kNeg, predicates::Stage::kFilter, 0},
                PredicateKind::kInsphere,
                tally);
            return s > 0;
        }
        const auto v = perturbation::insphere_sos_staged(
            exact_[t[0]], exact_[t[1]], exact_[t[2]], exact_[t[3]], exact_[u], keys);
        count(v, PredicateKind::kInsphere, tally);
        return v.sign == Sign::kPos;
    }
    // Neither implicit nor weighted is plain_, which conflicts_solid decides inline.
    CAVITY_ASSERT(weighted(), "conflicts_solid decides unweighted explicit points inline");
    const auto a = weighted_point(t[0]), b = weighted_point(t[1]), c = weighted_point(t[2]),
               d = weighted_point(t[3]), e = weighted_point(u);
    if constexpr (!T::kCounting) {
        return perturbation::orient4d_sos(a, b, c, d, e, keys) == Sign::kPos;
    }
    const auto v = perturbation::orient4d_sos_staged(a, b, c, d, e, keys);
    count(v, PredicateKind::kOrient4d, tally);
    return v.sign == Sign::kPos;
}

template <Tally T>
bool Geometry::conflicts_ghost(const TetVertices& t,
                               VertexId u,
                               const std::array<VertexId, 4>& interior,
                               T& tally) const {
    // In front of the hull triangle: a conflict whatever the weights (the new point becomes a hull
    // vertex). Behind it: none. Only a coplanar point needs the in-plane (perturbed) disk test.
    const Sign front = orient3d(t[0], t[1], t[2], u, tally);
    if (front != Sign::kZero) {
        return front == Sign::kPos;
    }
    VertexId behind = interior[0];
    for (VertexId y : interior) {
        if (orient3d(t[0], t[1], t[2], y, tally) == Sign::kNeg) {
            behind = y;
            break;
        }
    }
    return conflicts_ghost_in_plane(t, u, behind, tally);
}

template <Tally T>
bool Geometry::conflicts_ghost_in_plane(const TetVertices& t,
                                        VertexId u,
                                        VertexId behind,
                                        T& tally) const {
    const perturbation::Keys4 keys{keys_[t[0]], keys_[t[1]], keys_[t[2]], keys_[u]};
    perturbation::SosVerdict v;
    if (has_implicit()) {
        v = perturbation::outer_halfspace_sos_staged(
            exact_[t[0]], exact_[t[1]], exact_[t[2]], exact_[behind], exact_[u], keys);
    } else if (!weighted()) {
        v = perturbation::outer_halfspace_sos_staged(
            point(t[0]), point(t[1]), point(t[2]), point(behind), point(u), keys);
    } else {
        v = perturbation::outer_halfspace_weighted_sos_staged(weighted_point(t[0]),
                                                              weighted_point(t[1]),
                                                              weighted_point(t[2]),
                                                              weighted_point(behind),
                                                              weighted_point(u),
                                                              keys);
    }
    count(v, PredicateKind::kGhost, tally);
    return v.sign == Sign::kPos;
}

// The two tallies there are (counters.h).
template bool Geometry::conflicts_solid_exactly(const TetVertices&, VertexId, Uncounted&) const;
template bool Geometry::conflicts_solid_exactly(const TetVertices&, VertexId, Counters&) const;
template bool Geometry::conflicts_ghost(const TetVertices&,
                                        VertexId,
                                        const std::array<VertexId, 4>&,
                                        Uncounted&) const;
template bool Geometry::conflicts_ghost(const TetVertices&,
                                        VertexId,
                                        const std::array<VertexId, 4>&,
                                        Counters&) const;
template bool Geometry::conflicts_ghost_in_plane(const TetVertices&,
                                                 VertexId,
                                                 VertexId,
                                                 Uncounted&) const;
template bool Geometry::conflicts_ghost_in_plane(const TetVertices&,
                                                 VertexId,
                                                 VertexId,
                                                 Counters&) const;

}  // namespace cavity::core
