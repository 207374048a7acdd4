#pragma once

#include <cstddef>
#include <filesystem>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// True when the extension (case-insensitive) names a surface-mesh format read_surface_mesh reads:
/// `.off`, `.stl`, `.obj`, `.ply`.
bool is_surface_mesh_file(const std::filesystem::path& file);

/// Reads a closed surface mesh as a PLC: every face becomes a facet of one loop (coplanar adjacent
/// triangles stay separate polygons), with no segments, holes or regions.
/// - `.off`: `OFF` (or `COFF`, `NOFF`, `CNOFF`, whose extra vertex fields are skipped), the counts
///   `<#vertices> <#faces> [<#edges>]`, the vertices, then `n i1 ... in [colour]` per face;
///   points and faces numbered from 0. Only the vertices and faces the counts declare are read,
///   as CGAL's and TetGen's readers do: `unread_line`, when given, receives the line where data
///   after them begins (0 when there is none, and for the other formats).
/// - `.stl`: binary (an 80-byte header, a little-endian 32-bit count, 50 bytes per triangle; chosen
///   when the size agrees with the count) or ASCII (`solid ... facet ... outer loop, vertex x y z
///   ... endloop endfacet ... endsolid`). STL repeats coordinates instead of sharing vertices:
///   exactly equal coordinates become one point, numbered from 0 in order of first appearance.
/// - `.obj`: `v x y z` and `f a b c ...` (each corner `i`, `i/t`, `i//n` or `i/t/n`, negative
///   indices counting back from the last vertex); other statements are skipped; points and faces
///   numbered from 1, as the file does.
/// - `.ply`: ascii, binary_little_endian or binary_big_endian; the x, y, z of the `vertex` element
///   and the `vertex_indices` (or `vertex_index`) list of the `face` element; numbered from 0.
/// Facets keep their file line (0 in binary data) and number, so messages name them as the file
/// does. Degenerate faces (a repeated corner, collinear corners) are read, for the surface check
/// (cdt/surface_validity.h) to name them all.
/// \throws Error naming the file and the line (or, in binary data, the face and byte offset) of a
/// malformed or truncated entry, a face with fewer than 3 corners or an index that is not a point.
Plc read_surface_mesh(const std::filesystem::path& file, std::size_t* unread_line = nullptr);

}  // namespace cavity::core
