#pragma once

// Point writers shared by write_points() and write_tetgen(); each writes one whole file body.

#include "cavity/core/input/point_set.h"
#include "cavity/core/io/atomic_file.h"

namespace cavity::core {

/// TetGen .node: numbered from points.index_base, the weight as the single attribute.
void write_node(AtomicFileGroup::Writer& out, const PointSet& points);

/// One point per line, fields separated by `separator`, the weight as a fourth field.
void write_xyz(AtomicFileGroup::Writer& out, const PointSet& points, char separator);

}  // namespace cavity::core
