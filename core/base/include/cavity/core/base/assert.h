#pragma once

#include <string>
#include <vector>

namespace cavity::core::detail {

/// Throws InternalError "internal error: FILE:LINE: WHAT (CONDITION)". Out of line: never on a
/// fast path.
[[noreturn]] void assertion_failed(const char* condition,
                                   const std::string& what,
                                   const char* file,
                                   int line);

/// Throws InternalError listing the first problems when `problems` is not empty.
void require_no_problems(const std::vector<std::string>& problems,
                         const std::string& what,
                         const char* file,
                         int line);

}  // namespace cavity::core::detail

/// Three tiers of checks, all reporting a broken invariant as an InternalError (a bug: exit 4 in
/// the CLI, RuntimeError in Python):
/// - CAVITY_ASSERT(condition, what): always on; cheap invariants whose failure would corrupt
///   output silently.
/// - CAVITY_DEBUG_ASSERT(condition, what): only without NDEBUG (the debug preset).
/// - CAVITY_EXPENSIVE_CHECK(problems, what): only with -DCAVITY_EXPENSIVE_CHECKS=ON (the debug
///   preset); `problems` is a std::vector<std::string> from a full validation (check_complex
///   after each batch of insertions, flip, deletion and polygon), evaluated only in that build.
#define CAVITY_ASSERT(condition, what)                                                        \
    do {                                                                                      \
        if (!(condition)) {                                                                   \
            ::cavity::core::detail::assertion_failed(#condition, (what), __FILE__, __LINE__); \
        }                                                                                     \
    } while (false)

#ifdef NDEBUG
#define CAVITY_DEBUG_ASSERT(condition, what) \
    do {                                     \
    } while (false)
#else
#define CAVITY_DEBUG_ASSERT(condition, what) CAVITY_ASSERT(condition, what)
#endif

#if defined(CAVITY_EXPENSIVE_CHECKS) && CAVITY_EXPENSIVE_CHECKS
#define CAVITY_EXPENSIVE_CHECK(problems, what) \
    ::cavity::core::detail::require_no_problems((problems), (what), __FILE__, __LINE__)
#else
#define CAVITY_EXPENSIVE_CHECK(problems, what) \
    do {                                       \
    } while (false)
#endif
