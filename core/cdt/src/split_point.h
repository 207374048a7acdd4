#pragma once

#include <optional>

#include "cavity/predicates/generic_point.h"

/// Where edge protection splits a missing piece pq of a PLC segment. After Si & Shewchuk 2014's
/// reference point rule, as TetGen's segment recovery uses it, the vertex w that encroaches most
/// upon pq aims the split when w is a split point itself, so that w encroaches neither piece; of
/// the points that do that (the projection of w is one), the one nearest the midpoint, which keeps
/// the pieces even and the new vertex as far from w as freeing pq allows. When w is an input
/// vertex, or the aim falls near an end: at the midpoint. Only the count of points depends on the
/// choice: every point made is exactly on the segment.
namespace cavity::core {

using predicates::GenericPoint3;
using predicates::Point3;

/// Where the split of a piece pq aims, as parameters t of p + t (q - p): `target`, and the window
/// [lo, hi] around it in which a point with double coordinates may stand in for it.
struct SplitTarget {
    double target;
    double lo;
    double hi;
};

/// Where a point w stands beside piece pq, in units of |pq|: the parameter s of its projection on
/// the line p + s (q - p), and its squared height over that line. In doubles: it aims splits only.
struct ProjectionOnPiece {
    double s;
    double height2;
};

ProjectionOnPiece projection_on_piece(const Point3& p, const Point3& q, const Point3& w);

/// Where the split of pq aims, computed in doubles (it needs no exactness): without a reference,
/// the midpoint; else the parameter nearest 1/2 of those that leave the reference outside both
/// pieces' diametral balls (its projection is one), with a window kept inside them. The midpoint
/// whenever the aim falls outside [0.2, 0.8].
SplitTarget split_target(const Point3& p, const Point3& q, const std::optional<Point3>& reference);

/// Where a piece pq that ends at an input vertex c (p when `about_p`, else q) splits when a split
/// point on another PLC edge through c encroaches upon it and earlier splits have already made the
/// piece short (protect_edges decides): on the sphere about c whose radius is a
/// power of two, the largest not above 2/3 |pq| (concentric shells, as Ruppert's Delaunay
/// refinement protects small input angles).
/// Pieces at c then have lengths of one power of two on every edge there, so that the new vertices
/// stop encroaching upon each other's pieces, where an aim set by each encroacher in turn shrinks
/// the pieces about c without end (cheese's fan of 28 edges). The window keeps the length within
/// 2^-30 of the radius: pieces of equal length at an angle above about 0.004 degrees free each
/// other.
SplitTarget shell_target(const Point3& p, const Point3& q, bool about_p);

/// A point exactly on the open piece pq (p, q as protect_edges made them: input points, double
/// points on a segment, or SegmentParameterPoints of one base edge) near `target.target` of pq: a
/// point with double coordinates in [target.lo, target.hi] when the ends are doubles and one is
/// there (first the one at the coarsest dyadic parameter k / 2^j, j <= 10, within 2^-11 of the
/// target, for short coordinates: the midpoint when the target is 1/2 and it is a double), else the
/// SegmentParameterPoint of the base edge nearest the target on a dyadic grid at least 1024 times
/// finer than the piece and with two points in the window, kept in the window. nullopt when the
/// base parameters would need a denominator beyond 2^53 (the piece is 2^-52 of its base edge).
std::optional<GenericPoint3> split_point(const GenericPoint3& p,
                                         const GenericPoint3& q,
                                         const SplitTarget& target);

}  // namespace cavity::core
