#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace cavity::core {

/// What went wrong, in the three classes a caller treats differently: the input is at fault (fix
/// the file or the arguments), the system refused something (disk, permissions, memory: retry
/// elsewhere), or cavity itself is at fault (report a bug). The CLI maps them to its exit codes
/// and the Python module to ValueError, OSError/MemoryError and RuntimeError.
enum class ErrorKind { kInput, kSystem, kInternal };

/// Every error cavity reports: bad input (naming the file and line, or the point index), an input
/// that has no 3D triangulation (naming its affine dimension), or a failed write. The library
/// never prints or exits; the CLI turns an Error into a message and a non-zero exit status.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, ErrorKind kind = ErrorKind::kInput)
        : std::runtime_error(message), kind_(kind) {}

    [[nodiscard]] ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

/// The system refused a read or a write, or memory ran out: the input may well be fine.
class SystemError : public Error {
public:
    explicit SystemError(const std::string& message) : Error(message, ErrorKind::kSystem) {}
};

/// A broken internal invariant: a bug in cavity, never the input's fault.
class InternalError : public Error {
public:
    explicit InternalError(const std::string& message) : Error(message, ErrorKind::kInternal) {}
};

/// Builds "FILE:LINE: what", the form every parse error takes. Lines count from 1, so a line of 0
/// (data not read from a file, e.g. a PLC built in code) is left out like a missing one, and so is
/// an empty file name: "FILE: what" or "what".
std::string located_message(const std::string& file,
                            std::optional<std::size_t> line,
                            const std::string& what);

}  // namespace cavity::core
