# Dependencies come from the distribution (scripts/install-deps.sh installs them on Debian).

find_path(GMP_INCLUDE_DIR gmp.h REQUIRED)
find_library(GMP_LIBRARY gmp REQUIRED)
add_library(cavity_gmp INTERFACE)
add_library(cavity::gmp ALIAS cavity_gmp)
target_include_directories(cavity_gmp SYSTEM INTERFACE ${GMP_INCLUDE_DIR})
target_link_libraries(cavity_gmp INTERFACE ${GMP_LIBRARY})

find_package(Boost 1.74 REQUIRED)  # header-only: Boost.Multiprecision (oracle, generic predicates)
if(CAVITY_BUILD_PROGRAMS)
  find_package(CLI11 CONFIG QUIET)
  if(NOT CLI11_FOUND)
    find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
    add_library(CLI11::CLI11 INTERFACE IMPORTED)
    target_include_directories(CLI11::CLI11 INTERFACE ${CLI11_INCLUDE_DIR})
  endif()
endif()
find_package(Threads REQUIRED)
find_package(ZLIB REQUIRED)  # the .vtu writer's compression (Debian: zlib1g-dev)

if(CAVITY_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(CAVITY_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
  find_package(CGAL CONFIG QUIET)  # optional: the side-by-side peer benchmark
endif()
