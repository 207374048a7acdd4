#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace cavity::core {

/// Every error cavity reports: bad input (naming the file and line, or the point index), an input
/// that has no 3D triangulation (naming its affine dimension), or a failed write. The library
/// never prints or exits; the CLI turns an Error into a message and a non-zero exit status.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// Builds "FILE:LINE: what", the form every parse error takes. Lines count from 1, so a line of 0
/// (data not read from a file, e.g. a PLC built in code) is left out like a missing one, and so is
/// an empty file name: "FILE: what" or "what".
std::string located_message(const std::string& file, std::optional<std::size_t> line,
                            const std::string& what);

}  // namespace cavity::core
