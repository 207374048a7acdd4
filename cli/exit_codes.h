#pragma once

#include "cavity/core/error.h"

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
