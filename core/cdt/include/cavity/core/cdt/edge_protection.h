#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cavity/core/input/plc.h"
#include "cavity/core/live/delaunay_triangulation.h"

/// Edge protection (Cheng, Dey & Shewchuk §4.5, §5.8): the flip-based CDT construction needs
/// every PLC edge to be an edge of the Delaunay triangulation of the PLC's vertices. cavity reads
/// "Delaunay" under its symbolic perturbation (keyed on the input index), so the condition is
/// decided exactly and consistently with the triangulation the CDT starts from.
namespace cavity::core {

using Edge = std::array<std::uint32_t, 2>;

/// The PLC edges (plc_edges) that are not edges of `tets`, the Delaunay triangulation of the
/// PLC's points (0-based indices). Sorted.
std::vector<Edge> unprotected_edges(const Plc& plc,
                                    std::span<const std::array<std::uint32_t, 4>> tets);

/// The same for `edges`, the PLC's plc_edges already built (sorted, each once), and `points`, its
/// number of points: a caller that needs the edges again builds and sorts them once.
std::vector<Edge> unprotected_edges(std::span<const Edge> edges,
                                    std::size_t points,
                                    std::span<const std::array<std::uint32_t, 4>> tets);

/// The Delaunay triangulation of the PLC's points (0-based indices, the perturbation keyed on
/// them). \throws Error when two points coincide (naming them as the file numbers them) or the
/// points have no 3D triangulation.
DelaunayTriangulation plc_delaunay(const Plc& plc);

/// Splits PLC edge e (as {min, max}) at point m, which lies on it: in the explicit segments and in
/// every loop that has e as a side.
void split_plc_edge(Plc& plc, const Edge& e, std::uint32_t m);

/// The PLC edges that are not edges of the Delaunay triangulation of its points.
/// \throws Error when the points have no 3D triangulation or two points coincide.
std::vector<Edge> unprotected_edges(const Plc& plc);

/// What protect_edges did.
struct Protection {
    std::vector<std::uint32_t> inserted;  ///< indices of the new points, in insertion order
    /// Passes over every PLC edge: the first on the Delaunay triangulation built from scratch,
    /// each later one on the live triangulation after the queue of missing edges ran empty.
    std::size_t rounds = 0;
};

/// The point protect_edges inserts on edge ab: a point strictly inside the segment, exactly on it,
/// whose coordinates are doubles, as near the middle as the search finds (the midpoint when it is
/// one). Exact, and complete but for one bounded corner (core/cdt/src/protection_point.cpp):
/// nullopt means the open segment holds no point with double coordinates, except perhaps points
/// where a coordinate c is below 2^(e-60) in magnitude and not a multiple of 2^(e-113), 2^e being
/// the largest binade c reaches on the segment (a cap that bounds the work near zero crossings).
/// Such points are rare on segments between arbitrary doubles: a coordinate's doubles along the
/// segment recur every 2^q / |b_c - a_c| in t, and the three recurrences must meet.
/// Measured (ProtectionPoint.SuccessOnDecimalEdges in tests/core/cdt/test_plc.cpp: about 2000
/// random edges per kind, coordinates with 3 decimals in [0, 10); the exact midpoint alone in
/// brackets): a point is found on 6.6% of general edges [3.5%], 23.5% of edges in an axis-parallel
/// plane [9.8%] and 100% of axis-parallel edges [32.6%]. So --protect works on axis-aligned decimal
/// PLCs (AxisAlignedDecimalPlcsGetValidCdts) and fails on most general decimal ones (10 of 20 with
/// one general triangle got a CDT, DecimalPlcsWithAGeneralTriangle); snapping such inputs to a
/// binary grid first is the remedy.
std::optional<Point3> protection_point(const Point3& a, const Point3& b);

/// As above, searching only the parameters t in [lo, hi] (a + t (b - a); clipped to [0, 1]) for
/// the double point nearest parameter `target`: where protect_edges wants its split.
std::optional<Point3> protection_point(
    const Point3& a, const Point3& b, double target, double lo, double hi);

/// Splits unprotected PLC edges (appending the points to plc.points, and replacing each split
/// edge by its pieces in its segment and in every loop that has it) until every edge is protected.
/// Before the first split it checks that no point lies inside an unprotected edge and no PLC edge
/// crosses one (edge_violations), since splitting would never protect those.
/// It builds the Delaunay triangulation once and inserts each point into it (Si & Shewchuk's
/// incremental segment recovery, as TetGen does it): a queue of the missing edges, shortest
/// first, whose next edge is skipped when it has become a Delaunay edge and else split, its two
/// pieces queued; when the queue runs empty every piece is checked again (a later point can take
/// an edge away). Where it splits is split_point.h's rule: where the vertex that
/// encroaches most stops encroaching, nearest the midpoint, when that vertex is a split point,
/// else at the midpoint; at a point with double coordinates
/// (protection_point) when the piece's ends are doubles and one lies near the aim, else at an
/// implicit point (predicates::SegmentParameterPoint, exactly on the segment) of the edge between
/// doubles it was first made on, at a dyadic parameter n / 2^j whose numerator and denominator are
/// doubles exactly. plc.points.exact then holds every point's definition and plc.points.points
/// their rounding to nearest. The k-th point made has index and perturbation key n + k (sos.h),
/// in a deterministic order.
/// \throws Error naming the points or edges when the PLC is invalid as above, after `max_points`
/// insertions, or when a piece would need a parameter finer than 2^-53.
Protection protect_edges(Plc& plc, std::size_t max_points);

/// protect_edges, with the live Delaunay triangulation it inserted into: the triangulation of
/// every point of the protected PLC (input index = point index), the CDT's start.
struct ProtectedDelaunay {
    Protection protection;
    DelaunayTriangulation triangulation;
};

ProtectedDelaunay protect_edges_live(Plc& plc, std::size_t max_points);

}  // namespace cavity::core
