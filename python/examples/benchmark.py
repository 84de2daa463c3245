"""Variants per second of a 64-variant steady study of punch-b40 on this machine.

    python python/examples/benchmark.py [WEARFEM_BIN]     # default target/release/wearfem

Serial Python, a thread pool of 2, a Dask LocalCluster of threads (one worker, 2 threads) and
one of processes (2 workers, one thread each), and the command line's `wearfem sweep -j 2`; prints a Markdown table for
docs/performance.md. The overhead per task is the wall time the executor spends beyond the
variants' own solve time, per variant, relative to a variant's mean solve time:
(workers · wall − Σ seconds) / Σ seconds.

This virtual machine's speed drifts by ±15 % from one second to the next (twelve serial
studies in a row ran at 46 to 62 variants per second), more than the differences measured
here. So each executor is timed in ROUNDS pairs, a serial study right before each of its own
runs, and the table gives the median of the paired ratios (and their range): a slow spell
slows both runs of a pair alike.
"""

import os
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import wearfem

WORKERS = 2
ROUNDS = 5
punch = wearfem.Problem.builtin("punch-b40")
grid = {
    "contact.friction": [round(float(x), 3) for x in np.linspace(0.05, 0.3, 8)],
    "plate.pin": [[1100.0, float(z)] for z in np.linspace(110.0, 145.0, 8)],
}
n = 64


def timed(executor=None):
    """One study: (wall s, Σ of the variants' own seconds, table)."""
    start = time.perf_counter()
    table = wearfem.study(punch, grid, executor=executor)
    wall = time.perf_counter() - start
    return wall, float(np.sum(table["seconds"])), table


def paired(label, workers, run):
    """ROUNDS pairs of (serial study, `run()`): the row of the table. `run` returns (wall,
    Σ seconds or None, table or None)."""
    ratios, rates, overheads, means, tables = [], [], [], [], []
    for _ in range(ROUNDS):
        serial_wall, _, serial_table = timed()
        wall, own, table = run()
        ratios.append(serial_wall / wall)
        rates.append(n / wall)
        if own is not None:
            overheads.append((workers * wall - own) / own)
            means.append(own / n)
            tables.append(table)
    for table in tables:
        # Every executor gives the serial results exactly.
        assert list(table["peak_p_plus"]) == list(serial_table["peak_p_plus"]), label
    median = float(np.median(ratios))
    cells = [
        label,
        f"{np.median(rates):.1f}",
        f"{median:.2f}× ({min(ratios):.2f}–{max(ratios):.2f})",
        f"{1e3 * np.median(means):.1f}" if means else "",
        f"{100 * np.median(overheads):.0f} %" if overheads else "",
    ]
    print("| " + " | ".join(cells) + " |", flush=True)


def sweep_run(binary):
    """`wearfem sweep -j WORKERS` over the same grid, as a `paired` run."""

    def run():
        with tempfile.TemporaryDirectory() as out:
            sets = ["--set", f"contact.friction={grid['contact.friction']}", "--set", f"plate.pin={grid['plate.pin']}"]
            start = time.perf_counter()
            proc = subprocess.run(
                [binary, "sweep", "punch-b40", *sets, "--steady", "-j", str(WORKERS), "--out", out],
                capture_output=True,
                text=True,
            )
            wall = time.perf_counter() - start
            # Exit 1 when a variant does not converge; sweep.json is written all the same.
            assert os.path.exists(os.path.join(out, "sweep.json")), proc.stderr
        return wall, None, None

    return run


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "target/release/wearfem"
    wearfem.study(punch, {"contact.friction": [0.2]})  # warm-up
    print(f"{ROUNDS} pairs per row, medians (range of the paired ratios)")
    print("| how | variants/s | vs serial, paired | mean variant (ms) | overhead per task |")
    print("|---|---|---|---|---|")
    paired("serial Python", 1, lambda: timed())
    with ThreadPoolExecutor(WORKERS) as pool:
        paired(f"thread pool ({WORKERS} threads)", WORKERS, lambda: timed(pool))
    from distributed import Client, LocalCluster

    # Dask's two kinds of local cluster: threads in this process (the Dask documentation's
    # advice for code that releases the GIL, as wearfem does), and worker processes (each with
    # its own interpreter, as on a cluster).
    # The last row turns down Dask's per-worker profiler and monitors (dask_quiet.py), which
    # take CPU from the solves on a machine with no cores to spare.
    import dask
    from dask_quiet import QUIET

    processes = dict(n_workers=WORKERS, threads_per_worker=1, processes=True)
    for label, layout, config in [
        (f"Dask LocalCluster (threads, 1 × {WORKERS})", dict(n_workers=1, threads_per_worker=WORKERS, processes=False), {}),
        (f"Dask LocalCluster (processes, {WORKERS} × 1)", processes, {}),
        (f"Dask LocalCluster (processes, {WORKERS} × 1, quiet)", processes, QUIET),
    ]:
        with dask.config.set(config), LocalCluster(dashboard_address=None, **layout) as cluster, Client(cluster) as client:
            wearfem.study(punch, {"contact.friction": [0.2, 0.25]}, executor=client)  # workers warm
            paired(label, WORKERS, lambda: timed(client))
    paired(f"`wearfem sweep -j {WORKERS}` (process start and output files included)", WORKERS, sweep_run(binary))
    print(f"load average after: {os.getloadavg()[0]:.1f}")


# Dask starts its worker processes by re-importing this file: only run when executed.
if __name__ == "__main__":
    main()
