"""Shared fixtures: the command-line binary the Python results are compared with."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def wearfem_bin():
    """Path of the `wearfem` binary: $WEARFEM_BIN, default target/release/wearfem."""
    path = pathlib.Path(os.environ.get("WEARFEM_BIN", ROOT / "target" / "release" / "wearfem"))
    if not path.exists():
        pytest.fail(f"{path}: no wearfem binary (build it with `cargo build --release` or set WEARFEM_BIN)")
    return path


@pytest.fixture
def cli(wearfem_bin, tmp_path):
    """Run `wearfem ARGS --out DIR`; return (exit code, DIR)."""

    def run(*args):
        out = tmp_path / "out"
        proc = subprocess.run(
            [str(wearfem_bin), *args, "--out", str(out)],
            capture_output=True,
            text=True,
            timeout=600,
        )
        return proc, out

    return run
