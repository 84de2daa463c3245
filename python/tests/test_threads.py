"""The GIL is released while the library computes.

This checks `allow_threads` by what other Python threads can do during a call, not by a
speed-up: wall-clock comparisons fail on a shared CI machine (one did: 1 thread 0.269 s,
2 threads 0.241 s with another job on the second core). The speed-up of threads and of Dask
is measured by python/examples/benchmark.py and recorded in docs/performance.md.
"""

import sys
import threading
import time

import wearfem


def test_python_runs_during_a_solve():
    """While the main thread is inside the library, another thread's Python loop must
    advance. With the GIL held it could only run in the switch intervals (5 ms) granted at
    the bytecode boundaries around the call: so demand more counts than 4 switch intervals
    and a tenth of the call's duration would give at the loop's own rate. Independent of the
    number of cores; a busy machine slows both the loop and the solve alike."""
    # A call of about 0.2 s, so that the four switch intervals are a small part of it: a
    # 0.05 s run of punch-b40 (300 steps) left the loop a third of a core on a busy two-core
    # CI machine (the solve's second thread, the check in p), below the bound.
    problem = wearfem.Problem.builtin("brake")._inner
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    t = threading.Thread(target=count)
    t.start()
    time.sleep(0.2)
    c0, t0 = counter[0], time.perf_counter()
    time.sleep(0.2)
    rate = (counter[0] - c0) / (time.perf_counter() - t0)  # counts/s while the main thread sleeps
    before = counter[0]
    start = time.perf_counter()
    problem._run(4000, None)
    after = counter[0]
    seconds = time.perf_counter() - start
    stop.set()
    t.join()
    leak = rate * max(4 * sys.getswitchinterval(), 0.1 * seconds)
    assert after - before > leak, (
        f"the counter advanced {after - before} during a {seconds:.3f} s run "
        f"(rate {rate:.3g}/s): the GIL was held"
    )
