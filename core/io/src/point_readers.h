#pragma once

// One reader per point format; read_points() dispatches on the file extension.

#include <string>
#include <string_view>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// Each takes the file's name (for messages) and its bytes.
PointSet read_node(const std::string& file, std::string_view bytes, bool weighted);
PointSet read_xyz(const std::string& file, std::string_view bytes, bool weighted);
PointSet read_ply(const std::string& file, std::string_view bytes, bool weighted);

}  // namespace cavity::core
