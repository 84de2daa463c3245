"""Dask's own CPU on a small machine: a 64-variant steady study of punch-b40 on a
LocalCluster of 2 worker processes, with Dask's defaults or with its worker profiler and
monitors turned down, against serial Python (docs/performance.md, "2026-11-29").

    python python/examples/dask_quiet.py default|quiet

Prints three alternated serial and Dask runs: variants per second and the mean variant time
(ms) the study table reports. On a 2-core machine the scheduler, the client and the workers'
event loops share the cores with the solves, so what they take shows in the variants' time.
"""

import sys
import time

import dask
import numpy as np

import wearfem

punch = wearfem.Problem.builtin("punch-b40")
grid = {
    "contact.friction": [round(float(x), 3) for x in np.linspace(0.05, 0.3, 8)],
    "plate.pin": [[1100.0, float(z)] for z in np.linspace(110.0, 145.0, 8)],
}

#: Dask settings that cost CPU on every worker whether or not anyone looks at them.
QUIET = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.worker.memory.monitor-interval": "5s",
    "distributed.admin.tick.interval": "1s",
    "distributed.scheduler.work-stealing": False,
}


def timed(executor=None):
    start = time.perf_counter()
    table = wearfem.study(punch, grid, executor=executor)
    wall = time.perf_counter() - start
    return 64 / wall, 1e3 * float(np.mean(table["seconds"]))


def main():
    from distributed import Client, LocalCluster

    mode = sys.argv[1] if len(sys.argv) > 1 else "quiet"
    wearfem.study(punch, {"contact.friction": [0.2]})  # warm-up
    with dask.config.set(QUIET if mode == "quiet" else {}):
        with LocalCluster(dashboard_address=None, n_workers=2, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
            wearfem.study(punch, {"contact.friction": [0.2, 0.25]}, executor=client)  # workers warm
            for _ in range(3):
                serial, dask_rate = timed(), timed(client)
                print(f"{mode}: serial {serial[0]:.1f}/s ({serial[1]:.1f} ms), Dask {dask_rate[0]:.1f}/s ({dask_rate[1]:.1f} ms): {dask_rate[0] / serial[0]:.2f}x")


# Dask starts its worker processes by re-importing this file: only run when executed.
if __name__ == "__main__":
    main()
