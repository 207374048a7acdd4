#pragma once

#include <string>

#include "cavity/core/base/error.h"

/// The program's exit statuses, few enough that a script can branch on them (listed in
/// `cavity --help` and docs/api.md).
namespace cavity::cli {

inline constexpr int kExitOk = 0;
/// Bad input or a refused request: an unreadable file, a point set with no 3D triangulation, a mesh
/// that `check` finds invalid, a vertex CDT insertion refuses.
inline constexpr int kExitInput = 1;
/// Usage: an unknown option or subcommand, a missing or out-of-range argument.
inline constexpr int kExitUsage = 2;
/// The system refused: out of memory, a failed read, write, rename or lock.
inline constexpr int kExitSystem = 3;
/// A broken internal invariant: a bug in cavity, to be reported.
inline constexpr int kExitInternal = 4;

/// The table above, for the footer of every --help.
inline constexpr const char* kExitStatusHelp =
    "Exit status: 0 success; 1 bad input or a refused request (the message names the file and "
    "line, or the point); 2 usage (unknown option, missing or out-of-range argument); 3 out of "
    "memory or an I/O failure; 4 internal error (a bug: please report it).\n";

/// CLI11 reports an option's error as "NAME: message"; a message that already starts with the
/// name ("n: n must be between 4 and ...") is given once.
std::string usage_message(const std::string& what);

constexpr int exit_code(core::ErrorKind kind) {
    switch (kind) {
        case core::ErrorKind::kInput:
            return kExitInput;
        case core::ErrorKind::kSystem:
            return kExitSystem;
        case core::ErrorKind::kInternal:
            return kExitInternal;
    }
    return kExitInternal;
}

}  // namespace cavity::cli
