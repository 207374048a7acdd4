#pragma once

#include <filesystem>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// Reads a point file, choosing the format by extension (case-insensitive):
/// - `.node` (TetGen): header `<#points> [<dim> [<#attributes> [<#boundary markers>]]]`, then
///   `index x y z [attributes...] [marker]` per point. The first point's index (0 or 1) becomes
///   `index_base`; later indices must follow consecutively. With `weighted`, the first attribute is
///   the weight.
/// - `.xyz`, `.csv`, `.txt`: one point per line, `x y z` (`x y z w` with `weighted`), separated by
///   whitespace or commas; `index_base` 0.
/// - `.ply`: ascii, binary_little_endian or binary_big_endian; the x, y, z (and, with `weighted`,
///   `weight` or `w`) properties of the `vertex` element, of any numeric type; `index_base` 0.
/// In text formats `#` starts a comment and blank lines are skipped. Numbers are decimal or
/// hex-float and must be finite. Duplicates and degenerate sets are accepted (the triangulator
/// reports them).
/// \throws Error naming the file and line (or the vertex index in binary data) for a missing or
/// unreadable file, a truncated or empty file, a wrong field count, a malformed number, a
/// dimension other than 3, non-consecutive indices, or a missing weight.
PointSet read_points(const std::filesystem::path& file, bool weighted);

/// Writes `points` atomically (see AtomicFileGroup) as `.node` (TetGen, numbered from
/// `points.index_base`, the weight as the single attribute when weighted) or as `.xyz`, `.txt`
/// or `.csv` (one point per line, the weight as a fourth column). Coordinates are printed in the
/// shortest form that reads back to the same double, so a round trip is exact.
/// \throws Error naming the file for an unknown extension or a failed write.
void write_points(const std::filesystem::path& file, const PointSet& points);

}  // namespace cavity::core
