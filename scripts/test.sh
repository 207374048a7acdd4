#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs the test suites.
#   scripts/test.sh            release build, every test but the `long` label
#   scripts/test.sh asan       the same under AddressSanitizer + UndefinedBehaviorSanitizer
#   scripts/test.sh debug      a debug build with the expensive checks (the whole complex validated
#                              after insertion batches, flips, deletions and polygons) over the
#                              degenerate corpus, the CDT and the editing suites; it builds only
#                              the test programs those suites live in (CMakePresets.json lists
#                              them, and architecture.debug_preset_targets checks the list)
#   scripts/test.sh long       the long suites (>= 10^7 oracle queries per predicate, ...)
#   scripts/test.sh tsan       the parallel construction's and the parallel sort's suites under
#                              ThreadSanitizer
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
configure="$preset"
[ "$preset" = "long" ] && configure="release"

scripts/install-deps.sh
cmake --preset "$configure" >/dev/null
cmake --build --preset "$configure"
ctest --preset "$preset" -j 2
