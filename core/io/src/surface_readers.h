#pragma once

// One reader per surface-mesh format; read_surface_mesh() dispatches on the file extension.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cavity/core/input/plc.h"

namespace cavity::core {

/// Each takes the file's name (for messages) and its bytes. read_off reads the vertices and faces
/// its counts declare and sets `*unread_line` to the line where data after them begins (0: none).
Plc read_off(const std::string& file, std::string_view bytes, std::size_t* unread_line);
Plc read_stl(const std::string& file, std::string_view bytes);
Plc read_obj(const std::string& file, std::string_view bytes);
Plc read_ply_surface(const std::string& file, std::string_view bytes);

/// Appends a face as a facet of one loop, numbered as the file numbers its points (the next
/// position plus points.index_base), read at `line` (0 in binary data).
void add_surface_face(Plc& plc, std::vector<std::uint32_t> corners, std::size_t line);

/// "vertex index I is not a point (points are numbered B to L)", in the file's numbering.
std::string not_a_point(std::int64_t index, const Plc& plc);

}  // namespace cavity::core
