#pragma once

#include <optional>

#include "cavity/predicates/generic_point.h"

/// Where edge protection splits a missing piece pq of a PLC segment (Si & Shewchuk 2014's
/// reference point rule, as TetGen's segment recovery uses it): at the projection of the vertex
/// that encroaches most upon pq, or, when that vertex lies on another segment from a shared input
/// vertex c, on the sphere about c through it (concentric shells, so that splits near a small
/// input angle do not cascade); at the midpoint when the aim falls near an end. Only the count of
/// points depends on the choice: every point made is exactly on the segment.
namespace cavity::core {

using predicates::GenericPoint3;
using predicates::Point3;

/// The vertex that aims a split, and the shell centre when the rule is the shell's.
struct SplitAim {
    Point3 reference;
    std::optional<Point3> shell_centre;
};

/// The parameter t of p + t (q - p) where the split of pq aims, computed in doubles (it needs no
/// exactness): 1/2 without an aim, else the aim's when it lies in [0.2, 0.8], else 1/2.
double split_target(const Point3& p, const Point3& q, const std::optional<SplitAim>& aim);

/// A point exactly on the open piece pq (p, q as protect_edges made them: input points, double
/// points on a segment, or SegmentParameterPoints of one base edge) near parameter `target` of pq:
/// a point with double coordinates within 1/20 of the piece when the ends are doubles and one is
/// there (first the one at the coarsest dyadic parameter k / 2^j, j <= 10, within 2^-11 of the
/// target, for short coordinates: the midpoint when the target is 1/2 and it is a double), else the
/// SegmentParameterPoint of the base edge nearest the target on a dyadic grid at least 1024 times
/// finer than the piece. nullopt when the base parameters would need a denominator beyond 2^53 (the
/// piece is 2^-52 of its base edge).
std::optional<GenericPoint3> split_point(const GenericPoint3& p,
                                         const GenericPoint3& q,
                                         double target);

}  // namespace cavity::core
