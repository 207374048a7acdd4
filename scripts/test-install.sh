#!/usr/bin/env bash
# Installs a built cavity into a temporary prefix, then configures, builds and runs the separate
# project examples/consumer against the installed package only (find_package(cavity)).
#   scripts/test-install.sh BUILD_DIR [extra CMake arguments for the consumer...]
# Exits non-zero if any step fails. The temporary prefix is removed at exit.
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [cmake args for the consumer...]" >&2
  exit 2
fi
build_dir=$(cd "$1" && pwd)
shift
source_dir=$(cd "$(dirname "$0")/.." && pwd)

work=$(mktemp -d "${TMPDIR:-/tmp}/cavity-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install "$build_dir" --prefix "$prefix" >"$work/install.log"
for f in include/cavity/core/delaunay/triangulate.h include/cavity/predicates/orient3d.h \
         lib/cmake/cavity/cavityConfig.cmake lib/cmake/cavity/cavityTargets.cmake bin/cavity; do
  if [ ! -e "$prefix/$f" ]; then
    echo "test-install: $f was not installed" >&2
    exit 1
  fi
done

# The installed program runs from the prefix.
test "$(echo "orient3d 0 0 0 1 0 0 0 1 0 0 0 -1" | "$prefix/bin/cavity" sign)" = 1

# The Python module, when it was built, imports from the prefix.
python_dir="$prefix/lib/python3/dist-packages"
if compgen -G "$python_dir/cavity/_cavity.*.so" >/dev/null; then
  PYTHONPATH="$python_dir" /usr/bin/python3 -c \
    "import cavity; assert cavity.Delaunay([[0,0,0],[1,0,0],[0,1,0],[0,0,1]]).nsimplex == 1"
fi

generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
# Only the installed prefix is searched: the build tree must not leak into the consumer.
cmake -S "$source_dir/examples/consumer" -B "$work/consumer" "${generator[@]}" \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "$@" >"$work/configure.log" \
  || { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/consumer" -j2 >"$work/build.log" || { cat "$work/build.log" >&2; exit 1; }
"$work/consumer/tetrahedralize"
