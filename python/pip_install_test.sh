#!/usr/bin/env bash
# The package as a pip user gets it: a wheel built from a copy of the source tree with `pip wheel`
# (no network: Debian's setuptools and wheel, --no-build-isolation), installed into a fresh
# virtual environment that sees Debian's numpy and pytest (--system-site-packages), and the Python
# tests run against the installed module, from a directory holding no build of it.
# Usage: python/pip_install_test.sh SOURCE_DIR [PYTHON]
set -euo pipefail
source_dir=$(cd "$1" && pwd)
python=${2:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir "$work/src"
tar -C "$source_dir" --exclude=./build --exclude='./build-*' --exclude=./.git -cf - . |
  tar -C "$work/src" -xf -
"$python" -m pip wheel --no-build-isolation --no-deps --quiet -w "$work/wheels" "$work/src"
wheel=$(ls "$work"/wheels/cavity-*.whl)

"$python" -m venv --system-site-packages "$work/venv"
"$work/venv/bin/python" -m pip install --no-deps --no-index --quiet "$wheel"

cd "$work"
unset PYTHONPATH
expected=$(sed -n 's/^project(cavity VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
"$work/venv/bin/python" - "$work/venv" "$expected" <<'PY'
import importlib.metadata
import sys

import cavity

venv, expected = sys.argv[1], sys.argv[2]
assert cavity.__file__.startswith(venv), f"cavity imported from {cavity.__file__}, not the venv"
installed = importlib.metadata.version("cavity")
assert installed == expected == cavity.__version__, (installed, expected, cavity.__version__)
print(f"pip_install_test: cavity {installed} installed at {cavity.__file__}")
PY
PYTHONDONTWRITEBYTECODE=1 "$work/venv/bin/python" -m pytest -q -p no:cacheprovider \
  "$source_dir/python/tests"
