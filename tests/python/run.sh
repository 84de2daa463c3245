#!/bin/sh
# Reads every ParaView file wearfem writes with a real VTK reader (meshio) and checks the
# values against summary.json.
#
#   tests/python/run.sh VENV_DIR [WEARFEM_BINARY]
#
# VENV_DIR: where to create (or reuse) the Python virtual environment; meshio, numpy and pytest
# are installed into it from PyPI. WEARFEM_BINARY defaults to target/release/wearfem (build it
# first: cargo build --release).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
venv=${1:?usage: tests/python/run.sh VENV_DIR [WEARFEM_BINARY]}
binary=${2:-$root/target/release/wearfem}
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check meshio numpy pytest
WEARFEM_BIN=$(cd "$(dirname "$binary")" && pwd)/$(basename "$binary") \
    exec "$venv/bin/python" -m pytest -q "$here"
