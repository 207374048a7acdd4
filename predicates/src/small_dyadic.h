#pragma once

#include <optional>

#include "cavity/predicates/sign.h"

// orient3d's commonest exact zeros: exact coordinate differences of points on coarse grids.
// Height fields, CAD parts drawn in halves or quarters of a unit and the flat faces of surface
// meshes put four coplanar points into orient3d by the thousand; their differences are exact (no
// two_diff tail) and two of the three coordinates, at least, lie on a grid, yet the expansion
// stage B proves each zero with full expansions (about 800 instructions, after a double-double
// stage that cannot succeed on a zero). Scaled to integers, a column at a time (a power of two
// per column scales the determinant by a positive factor), the determinant takes a few dozen
// integer operations.
namespace cavity::predicates::detail {

/// The exact sign of det[x; y; z] (x, y and z the columns of orient3d's exact differences, one
/// entry per point) when each column, scaled by a power of two of its own, is a vector of
/// integers, two of them below 2^31 in magnitude and the third below 2^62: the 2x2 minors of the
/// narrow columns are then below 2^63 (64-bit integers) and the determinant below 2^127 (128-bit
/// integers). None otherwise (wider columns, subnormal or non-finite entries).
std::optional<Sign> orient3d_small_dyadic(const double (&x)[3],
                                          const double (&y)[3],
                                          const double (&z)[3]);

}  // namespace cavity::predicates::detail
