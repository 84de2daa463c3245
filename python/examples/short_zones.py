"""Steady states of short contact zones: `wearfem steady` against long runs.

punch-b40 (Example 1, pin 40 mm up) with its 16.666 MPa on only part of its top: the first w mm
(w = 2.5 ... 60, mu = 0 ... 0.25, b = 1: 63 problems), or the last or middle w mm (w = 5, 10,
20; mu = 0 ... 0.2; b = 0.5, 1, 2: 72 problems). For each, the exact steady solve and a run of
6000 steps; where the run reaches a steady state (its wear per period rigid to < 1e-3), the two
must agree. Prints one line per problem and the counts (docs/validation.md, "Session of
2026-11-25"). Uses only the command line, so that two builds can be compared:

    python3 python/examples/short_zones.py target/release/wearfem [OLD_BINARY] [--small-b]

About 4 minutes on 2 cores.
"""

import csv
import itertools
import re
import subprocess
import sys
import tempfile
from pathlib import Path


def problems(base, small_b=False):
    """(name, problem text) of the 135 variants (with `small_b`, the 69 of small_exponents)."""
    def variant(window, mu, b):
        return (
            base.replace(
                "normal = 16.666                # MPa",
                f"normal = 16.666\nwindow = {{ x = {window} }}",
            )
            .replace("friction = 0.25", f"friction = {mu}")
            .replace("a = 1.0, b = 1.0 }", f"a = 1.0, b = {b} }}")
        )

    if small_b:
        yield from small_exponents(variant)
        return
    for w in [2.5, 5, 7.5, 10, 15, 20, 30, 45, 60]:
        for mu in ["0.0", "0.01", "0.02", "0.05", "0.1", "0.2", "0.25"]:
            yield f"L-{w}-{mu}-1.0", variant(f"[1070.0, {1070 + w}]", mu, "1.0")
    for side, w, mu, b in itertools.product(
        ["R", "M"], [5, 10, 20], ["0.0", "0.05", "0.1", "0.2"], ["1.0", "0.5", "2.0"]
    ):
        window = f"[{1130 - w}.0, 1130.0]" if side == "R" else f"[{1100 - w / 2}, {1100 + w / 2}]"
        yield f"{side}-{w}-{mu}-{b}", variant(window, mu, b)


def small_exponents(variant):
    """Wear laws with b < 1 (docs/validation.md, "wear laws with b < 1"): the first w mm with
    b = 0.3 (15 problems), the last or middle w mm with b = 0.1, 0.3, 0.7 (54)."""
    for w in [2.5, 5, 10, 20, 45]:
        for mu in ["0.0", "0.05", "0.2"]:
            yield f"L-{w}-{mu}-0.3", variant(f"[1070.0, {1070 + w}]", mu, "0.3")
    for side, w, mu, b in itertools.product(
        ["R", "M"], [5, 10, 20], ["0.0", "0.05", "0.1"], ["0.1", "0.3", "0.7"]
    ):
        window = f"[{1130 - w}.0, 1130.0]" if side == "R" else f"[{1100 - w / 2}, {1100 + w / 2}]"
        yield f"{side}-{w}-{mu}-{b}", variant(window, mu, b)


def main(new, old=None, small_b=False):
    base = subprocess.run(
        [new, "examples", "show", "punch-b40"], capture_output=True, text=True, check=True
    ).stdout
    assert "normal = 16.666                # MPa" in base
    quiet = ["--quiet", "--set", "analysis.p_check=false"]
    counts = dict(problems=0, run_steady=0, new_solved=0, old_solved=0, worst=0.0)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for name, text in problems(base, small_b):
            path = tmp / f"{name}.toml"
            path.write_text(text)

            def steady(binary, out):
                return subprocess.run(
                    [binary, "steady", str(path), "--out", str(out), *quiet], capture_output=True
                ).returncode

            new_code = steady(new, tmp / f"s-{name}")
            old_code = steady(old, tmp / f"o-{name}") if old else None
            run = subprocess.run(
                [new, "run", str(path), "--out", str(tmp / f"r-{name}"), *quiet,
                 "--set", "wear.steps=6000", "--set", "wear.record=[1]"],
                capture_output=True, text=True,
            )
            rigid = re.search(r"rigid to ([0-9.e+-]+)", run.stdout)
            run_steady = run.returncode == 0 and rigid is not None and float(rigid.group(1)) < 1e-3
            distance = None
            if new_code == 0 and run_steady:
                final = list(csv.DictReader(open(tmp / f"r-{name}" / "final.csv")))
                state = list(csv.DictReader(open(tmp / f"s-{name}" / "steady.csv")))
                peak = max(float(row["p_plus_MPa"]) for row in state)
                distance = max(
                    abs(float(a[k]) - float(b[k])) / peak
                    for a, b in zip(final, state)
                    for k in ["p_plus_MPa", "p_minus_MPa"]
                )
                counts["worst"] = max(counts["worst"], distance)
            counts["problems"] += 1
            counts["run_steady"] += run_steady
            counts["new_solved"] += new_code == 0 and run_steady
            counts["old_solved"] += old_code == 0 and run_steady
            print(name, "steady", new_code, "old", old_code, "run", run.returncode,
                  "rigid", rigid.group(1) if rigid else None, "distance", distance, flush=True)
    print(counts)
    # Every problem whose run reaches a steady state must be solved, and agree with it.
    return 0 if counts["new_solved"] == counts["run_steady"] and counts["worst"] < 0.01 else 1


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--small-b"]
    sys.exit(main(*args[:2], small_b="--small-b" in sys.argv))
