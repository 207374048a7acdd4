#pragma once

// Number formatting shared by the writers.

#include <charconv>
#include <cstdint>
#include <string>

namespace cavity::core {

/// Appends the shortest decimal that reads back to exactly `value` (std::to_chars guarantees the
/// round trip), so written coordinates and weights survive a write/read cycle bit for bit.
inline void append_double(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

inline void append_uint(std::string& out, std::uint64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

inline void append_int(std::string& out, std::int64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

}  // namespace cavity::core
