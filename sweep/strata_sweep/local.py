"""The local backend: N runs at a time (N = the number of cores unless told), each its own
strata-sim process, with a progress line. Ctrl-C reaches the simulators too (one process
group); the runs they were on get no done marker and run again next time, the finished ones
stay finished."""
import concurrent.futures
import os

from . import run as run_mod
from .progress import Progress


def run_pending(pending, root, jobs, timeout, label="sweep", sim=None):
    """Runs each pending parameter set. Returns {key: error or None}."""
    jobs = jobs or os.cpu_count() or 1
    outcome = {}
    progress = Progress(label, len(pending))
    failed = 0
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=jobs)
    try:
        futures = {pool.submit(run_mod.execute, p, root, timeout, sim): p for p in pending}
        for n, f in enumerate(concurrent.futures.as_completed(futures), 1):
            _, error = f.result()
            outcome[run_mod.run_key(futures[f])] = error
            failed += error is not None
            progress.update(n, failed, final=n == len(pending))
    except KeyboardInterrupt:
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)
    return outcome
