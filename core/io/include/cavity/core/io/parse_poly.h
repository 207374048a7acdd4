#pragma once

#include <filesystem>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// Parses a TetGen `.poly` file. Part 1 lists the points (or declares 0 points, and then they come
/// from the `.node` file of the same name); part 2 lists the facets: `<#polygons> [<#holes>
/// [<marker>]]`, then each polygon `<#corners> c1 c2 ...`, then each hole `<i> x y z`; part 3 the
/// volume holes; then the region seeds. A `.smesh` (TetGen's surface mesh, by extension,
/// case-insensitive) is the same but for its facets: one polygon each, `<#corners> c1 c2 ...
/// [<marker>]`, on one line. Checks the syntax and what needs no geometry (indices,
/// counts, distinct corners of a polygon); the facets' geometry needs exact rational planes, which
/// belong to the CDT layer: read_poly (cdt/read_poly.h) is this parser followed by those checks.
/// \throws Error naming the file and line of any malformed or truncated entry.
Plc parse_poly(const std::filesystem::path& file);

}  // namespace cavity::core
