#pragma once

#include "cavity/core/input/plc.h"
#include "cavity/core/io/atomic_file.h"

namespace cavity::core {

/// Writes `plc` as a TetGen .poly that read_poly reads back to the same PLC: its points (numbered
/// from points.index_base, coordinates that read back exactly), each facet with its loops, hole
/// points and marker, each segment as a facet of one two-corner polygon, and the volume holes.
/// The CDT writes the PLC its mesh conforms to (protection and inserted vertices included), so
/// that `cavity check MESH.node MESH.ele --poly MESH.poly` can validate any output.
void write_poly(AtomicFileGroup::Writer& out, const Plc& plc);

}  // namespace cavity::core
