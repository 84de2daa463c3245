"""Variants per second of a 64-variant steady study of punch-b40 on this machine.

    python python/examples/benchmark.py [WEARFEM_BIN]     # default target/release/wearfem

Serial Python, a thread pool of 2, a Dask LocalCluster of threads (one worker, 2 threads) and
one of processes (2 workers, one thread each), and the command line's `wearfem sweep -j 2`; prints a Markdown table for
docs/performance.md. The overhead per task is the wall time the executor spends beyond the
variants' own solve time, per variant, relative to a variant's mean solve time:
(workers · wall − Σ seconds) / Σ seconds.
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
punch = wearfem.Problem.builtin("punch-b40")
grid = {
    "contact.friction": [round(float(x), 3) for x in np.linspace(0.05, 0.3, 8)],
    "plate.pin": [[1100.0, float(z)] for z in np.linspace(110.0, 145.0, 8)],
}
n = 64


def timed(label, workers, executor=None):
    start = time.perf_counter()
    table = wearfem.study(punch, grid, executor=executor)
    wall = time.perf_counter() - start
    own = float(np.sum(table["seconds"]))
    overhead = (workers * wall - own) / own
    return label, n / wall, overhead, table, own / n, own / wall


def main():
    rows = []
    wearfem.study(punch, {"contact.friction": [0.2]})  # warm-up
    rows.append(timed("serial Python", 1))
    with ThreadPoolExecutor(WORKERS) as pool:
        rows.append(timed(f"thread pool ({WORKERS} threads)", WORKERS, pool))
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
            rows.append(timed(label, WORKERS, client))

    serial = rows[0][3]
    for label, _, _, table, _, _ in rows[1:]:
        assert list(table["peak_p_plus"]) == list(serial["peak_p_plus"]), label

    binary = sys.argv[1] if len(sys.argv) > 1 else "target/release/wearfem"
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

    print(f"load average after: {os.getloadavg()[0]:.1f}; mean variant {np.mean(serial['seconds']) * 1e3:.1f} ms")
    print("| how | variants/s | vs serial | mean variant (ms) | variants at once | overhead per task |")
    print("|---|---|---|---|---|---|")
    base = rows[0][1]
    for label, rate, overhead, _, mean, overlap in rows:
        print(f"| {label} | {rate:.1f} | {rate / base:.2f}× | {1e3 * mean:.1f} | {overlap:.2f} | {100 * overhead:.0f} % |")
    print(f"| `wearfem sweep -j {WORKERS}` (process start and output files included) | {n / wall:.1f} | {n / wall / base:.2f}× | | | |")


# Dask starts its worker processes by re-importing this file: only run when executed.
if __name__ == "__main__":
    main()
