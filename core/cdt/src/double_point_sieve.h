#pragma once

#include "cavity/predicates/point.h"

/// A cheap exact test that rules out protection_point's search on most segments between decimal
/// doubles, where no point inside has double coordinates: the search cuts the window into pieces
/// and intersects three progressions of GMP rationals per piece (about 195 k instructions a call
/// on turbine), to find nothing on nearly every call.
///
/// Why it can be cheap. Scale the segment's doubles by a common power of two 2^-E to integers A_c,
/// B_c, D_c = B_c - A_c. A point a + t (b - a) whose coordinate c is a multiple of 2^f_c >= 2^E has
/// t D_c an integer for every c, so t = m / G with G = gcd(D_x, D_y, D_z) and m an integer; its
/// coordinate c is a multiple of 2^f_c exactly when A_c + m D_c / G = 0 modulo 2^(f_c - E). The
/// moduli are powers of two, so the three congruences on m combine by modular inverses of odd
/// numbers, with no gcd: m = r modulo 2^K, or no m at all. One gcd per segment, on integers of a
/// hundred bits or so, instead of one per rational operation.
namespace cavity::core {

using predicates::Point3;

/// False only when protection_point's search of the parameters [lo, hi] (0 <= lo < hi <= 1) of
/// segment ab finds no point: when no t in [lo, hi] makes each coordinate that changes along ab a
/// multiple of the finest spacing of the doubles that the search uses for it in the window (that
/// of the coordinate's smaller magnitude at the window's ends). True when that may hold, when a
/// coordinate may cross zero in the window (its spacing there has no useful bound), and whenever
/// the integers would pass 128 bits: then the search decides.
bool may_hold_double_point(const Point3& a, const Point3& b, double lo, double hi);

}  // namespace cavity::core
