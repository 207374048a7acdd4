# Interface targets every cavity target links: warnings, and the floating-point discipline the exact
# predicates rely on.

add_library(cavity_warnings INTERFACE)
add_library(cavity::warnings ALIAS cavity_warnings)
target_compile_options(cavity_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                                 -Wno-sign-conversion)
# GCC 12's -Wrestrict reports overlaps inside libstdc++'s std::string on inlined paths that
# cannot happen (a known false positive of that release), so it is off where warnings are errors.
if(CAVITY_WERROR)
  target_compile_options(cavity_warnings INTERFACE -Werror
                                                   $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
endif()

# The filters' error bounds and the error-free transformations (two_sum, two_product) assume that
# every operation is rounded on its own, to nearest, in double precision. A fused multiply-add
# rounds once for two operations and silently breaks them, so contraction is off everywhere the
# predicates are evaluated, and that includes callers that inline the filters from the headers.
# -ffast-math is never allowed: it licenses reassociation and flush-to-zero.
add_library(cavity_strict_fp INTERFACE)
add_library(cavity::strict_fp ALIAS cavity_strict_fp)
target_compile_options(cavity_strict_fp INTERFACE -ffp-contract=off -fno-fast-math
                                                  -fno-unsafe-math-optimizations)

if(CAVITY_SANITIZE)
  # float-cast-overflow is not part of -fsanitize=undefined: it catches a double converted to an
  # integer type that cannot hold it (file data such as a PLY list length). _GLIBCXX_ASSERTIONS
  # bounds-checks operator[] of the standard containers, which ASan misses inside a vector's
  # capacity. The asan and fuzz presets compile at -O1 with line tables only (-g1): enough for the
  # sanitizers' stack traces, and tests/core/cdt/test_plc.cpp compiled in 70 s where
  # RelWithDebInfo's -O2 -g took 134 s (the sanitizer build was the largest part of CI).
  add_compile_options(-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endif()
if(CAVITY_EXPENSIVE_CHECKS)
  add_compile_definitions(CAVITY_EXPENSIVE_CHECKS=1)
endif()
