#!/usr/bin/env bash
# Build the wheel in a fresh virtual environment and run the Python tests.
#
#   python/run_tests.sh VENV_DIR
#
# Creates VENV_DIR (python3 -m venv), installs maturin and the test dependencies into it,
# builds the wheel (sharing ../target with the main crate, so what `cargo build --release`
# built is reused), installs it and runs pytest on python/tests. WEARFEM_BIN (default
# target/release/wearfem, built here if missing) is the command line the tests compare with.
set -euo pipefail
if [ $# -ne 1 ]; then
    echo "usage: $0 VENV_DIR" >&2
    exit 2
fi
venv=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
export CARGO_TARGET_DIR="$root/target"

python3 -m venv "$venv"
py="$venv/bin/python"
"$py" -m pip install --quiet --upgrade pip
"$py" -m pip install --quiet "maturin>=1.5,<2" numpy pytest "dask[distributed]" pandas mypy

export WEARFEM_BIN=${WEARFEM_BIN:-$root/target/release/wearfem}
if [ ! -x "$WEARFEM_BIN" ]; then
    (cd "$root" && cargo build --release --bin wearfem)
fi

wheels=$(mktemp -d)
trap 'rm -rf "$wheels"' EXIT
"$venv/bin/maturin" build --release --strip --manifest-path "$here/Cargo.toml" --out "$wheels" \
    --interpreter "$py"
"$py" -m pip install --quiet --force-reinstall --no-deps "$wheels"/wearfem-*.whl

# Run from outside python/ so that the installed wheel is imported, not the source folder.
cd "$root"
"$py" -m pytest -q -p no:cacheprovider "$here/tests"
