#!/usr/bin/env bash
# cavity against CGAL's Delaunay_triangulation_3 (Epick) and, when its source is given, HXT; and
# cavity's parallel construction and its instrumented (counting) engine against its sequential
# engine: time in the same process, and whole-process peak memory of each engine run alone.
# Writes results/peers/peers.csv, results/peers/README.md and the peers item of the top README.
#   bench/run_peers_bench.sh [N]           generated cube, grid and sphere of N points (default
#                                          1000000; the grid is round(cbrt N)^3)
#   bench/run_peers_bench.sh FILE...       the given point files (.node, .xyz, .ply), e.g. held out
#   THREADS=T (default 2) threads for the parallel engines; REPEATS=R (default 3)
#   HXT_SOURCE=<gmsh>/contrib/hxt          also time HXT, built from that source by bench/CMakeLists
#                                          (the page names gmsh's version from <gmsh>/CMakeLists.txt
#                                          and a digest of the HXT files)
set -euo pipefail
cd "$(dirname "$0")/.."
repeats="${REPEATS:-3}"
threads="${THREADS:-2}"
build="${BUILD_DIR:-build/release}"
inputs=()
if [ $# -eq 0 ] || { [ $# -eq 1 ] && [[ "$1" =~ ^[0-9]+$ ]]; }; then
  n="${1:-1000000}"
  label="$n"
  for dist in cube grid sphere; do inputs+=("--dist $dist --n $n"); done
else
  label="$*"
  for file in "$@"; do
    [ -f "$file" ] || { echo "run_peers_bench.sh: no point file $file" >&2; exit 1; }
    inputs+=("--points $file")
  done
fi
scripts/install-deps.sh
cmake --preset release -DCAVITY_PEERS_HXT_SOURCE="${HXT_SOURCE:-}" >/dev/null
cmake --build "$build" --target peers_bench
bin="$build/bench/peers_bench"
engines="cavity cgal cavity-threads"
if [ -n "${HXT_SOURCE:-}" ]; then engines="$engines hxt hxt-threads"; fi
out=results/peers
mkdir -p "$out"
csv="$out/peers.csv.tmp"
echo "distribution,n,engine,threads,run,seconds,wall_seconds,tets,peak_rss_bytes,baseline_rss_bytes" > "$csv"
for input in "${inputs[@]}"; do
  # shellcheck disable=SC2086  # each input is its own flags
  "$bin" $input --repeats "$repeats" --threads "$threads" >> "$csv"
  for engine in $engines; do
    # shellcheck disable=SC2086
    "$bin" $input --repeats 1 --threads "$threads" --only "$engine" >> "$csv"
  done
done
mv "$csv" "$out/peers.csv"
# The HXT source, named so that runs can be compared: gmsh's version from the CMakeLists.txt two
# folders up (when the source is a gmsh tree) and a digest of the files under contrib/hxt.
hxt_source=""
if [ -n "${HXT_SOURCE:-}" ]; then
  gmsh_cmake="$HXT_SOURCE/../../CMakeLists.txt"
  version=""
  if [ -f "$gmsh_cmake" ]; then
    version=$(sed -n 's/^set(GMSH_\(MAJOR\|MINOR\|PATCH\)_VERSION \([0-9]*\)).*/\2/p' "$gmsh_cmake" |
      paste -sd.)
  fi
  digest=$(cd "$HXT_SOURCE" && find . -type f -print0 | LC_ALL=C sort -z | xargs -0 sha256sum |
    sha256sum | cut -c1-12)
  hxt_source="gmsh ${version:-of unknown version}, sha256 of its files $digest"
fi
/usr/bin/python3 bench/peers_report.py "$out/peers.csv" "$label" "$(uptime | sed 's/.*load average: //')" \
  --readme README.md --hxt-source "$hxt_source" > "$out/README.md"
cat "$out/README.md"
