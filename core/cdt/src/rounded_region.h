#pragma once

// A floating-point stage in front of FacetRegion::contains: the point asked about (the crossing of
// an edge with a facet's plane, or the centroid of a face in it) and the region's loop corners in
// doubles, each within a proven distance of the exact point, and the exact test's point-in-loop
// walk on them, answering only when every comparison and orientation it takes is decided by the
// bounds. The exact point costs a rational crossing or centroid and its reduction, and the exact
// loops a rational per corner (cheese.off: 16 k instructions per crossing, a tenth of the run).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cavity/core/input/plc.h"
#include "cavity/predicates/generic_filter.h"
#include "cavity/predicates/point.h"

namespace cavity::core {

/// A point of a facet's plane projected by dropping one coordinate (as FacetRegion's), in
/// doubles: the exact point's coordinates lie within error_u of u and error_v of v.
struct RoundedPoint2 {
    double u;
    double v;
    double error_u;
    double error_v;
};

/// Where segment pq meets the plane through the three points `plane` (exact), projected by
/// dropping coordinate `drop`, given p and q within their errors of exact points that lie
/// strictly on opposite sides of the plane. nullopt when the rounded heights of p and q over the
/// plane are not well apart from their error bounds (a crossing near an end), or out of range.
std::optional<RoundedPoint2> rounded_crossing(const std::array<predicates::Point3, 3>& plane,
                                              int drop,
                                              const predicates::RoundedPoint& p,
                                              const predicates::RoundedPoint& q);

/// The centroid of one to three points, projected as above.
std::optional<RoundedPoint2> rounded_centroid(std::span<const predicates::RoundedPoint> points,
                                              int drop);

/// A loop's corners (PLC point indices) projected as above, from the points' rounded coordinates
/// and a bound on their rounding: no rational is made. nullopt when a corner's rounding cannot be
/// bounded.
std::optional<std::vector<RoundedPoint2>> rounded_loop(const Plc& plc,
                                                       const std::vector<std::uint32_t>& loop,
                                                       int drop);

/// Whether x lies strictly inside the loop, by the crossing-number rule of the exact test
/// (exact_plane.cpp's position, along the ray from x in direction +u); nullopt when a comparison
/// or orientation is undecided, and so whenever x may lie on the loop (the exact test answers).
std::optional<bool> inside_loop_rounded(const std::vector<RoundedPoint2>& loop,
                                        const RoundedPoint2& x);

}  // namespace cavity::core
