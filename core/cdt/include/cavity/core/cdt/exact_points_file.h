#pragma once

#include <string>

#include "cavity/core/input/point_set.h"

/// PREFIX.exact, the side file of `cavity cdt` when edge protection made implicit Steiner points
/// (generic_point.h): the .node file holds their coordinates rounded to nearest, this file their
/// exact definitions and exact rational coordinates, so that `cavity check --poly --exact`
/// validates the exact mesh. One line per implicit point:
///   INDEX segment AX AY AZ BX BY BZ NUMERATOR DENOMINATOR : X Y Z
///   INDEX line_plane AX AY AZ BX BY BZ PX PY PZ QX QY QZ RX RY RZ : X Y Z
/// INDEX numbered as the .node numbers its points, the defining doubles as C99 hex floats (exact),
/// X Y Z exact rationals p/q (for readers; the definition is what is read back).
namespace cavity::core {

/// The file's text for `points` (empty exact: no implicit point, nothing to write).
std::string exact_points_text(const PointSet& points);

/// Reads `file` into points.exact. \throws Error naming the file and line when a line does not
/// parse, names a point out of range, or defines a point whose rounding is not its .node
/// coordinates.
void read_exact_points(const std::string& file, PointSet& points);

}  // namespace cavity::core
