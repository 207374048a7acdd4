#!/usr/bin/env bash
# clang-tidy (.clang-tidy: bugprone-*, performance-*) over every source of the libraries, the CLI,
# the experiments, the Python module and the tests, with the headers they include; exit 1 on any
# finding. Needs the release build's compile database (configured here). About 10 minutes on 2
# cores.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
cmake --build --preset release >/dev/null  # generated headers, and the sources must compile
/usr/bin/python3 - <<'PY' > build/release/tidy-files.txt
import json
for entry in json.load(open("build/release/compile_commands.json")):
    f = entry["file"]
    if "/build/" not in f and "/bench/" not in f:
        print(f)
PY
log=build/release/tidy.log
xargs -P "$(nproc)" -n 4 clang-tidy -p build/release --quiet < build/release/tidy-files.txt > "$log" 2>&1 || true
if grep -E "(warning|error):" "$log"; then
  echo "tidy: findings above (full log: $log)" >&2
  exit 1
fi
echo "tidy: $(wc -l < build/release/tidy-files.txt) sources, no findings"
