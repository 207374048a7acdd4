#!/usr/bin/env bash
# cavity cdt (with and without --protect) beside TetGen -p and -pY on the real closed surface meshes
# that Debian packages ship (CGAL's data meshes, OpenSCAD's test STL files): status, wall time,
# Steiner points, tetrahedra and an exact `cavity check --poly` of every mesh. Writes
# results/cdt/cdt.csv and results/cdt/README.md. A benchmark: not part of CI or the tests.
#   bench/run_cdt_bench.sh [bench/cdt_bench.py options]   e.g. --timeout 120 --max-faces 20000
# The models are not in the repository: this installs libcgal-demo (24 MB download; data.tar.gz,
# CGAL's examples and demos), openscad-testing-data (7 MB) and openscad (which renders the solids of
# OpenSCAD's test scripts; --no-render leaves them out) when missing, and reads them there.
# See `/usr/bin/python3 bench/cdt_bench.py --help` for the options.
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(libcgal-demo openscad-testing-data openscad)
for arg in "$@"; do
  if [ "$arg" = "-h" ] || [ "$arg" = "--help" ]; then exec /usr/bin/python3 bench/cdt_bench.py --help; fi
  if [ "$arg" = "--no-render" ]; then packages=(libcgal-demo openscad-testing-data); fi
done
build="${BUILD_DIR:-build/release}"
scripts/install-deps.sh
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then missing+=("$p"); fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "run_cdt_bench: installing the model packages ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
cmake --preset release >/dev/null
cmake --build "$build" --target cavity
/usr/bin/python3 bench/cdt_bench.py --cavity "$build/cli/cavity" "$@"
cat results/cdt/README.md
