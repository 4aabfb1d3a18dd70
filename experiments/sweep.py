#!/usr/bin/python3
"""The paper experiments' view of strata-sweep (sweep/strata_sweep): a list of parameter sets
in, a Result per set out. The runs go through strata-sweep's runner (one folder per run named
by a hash of its parameters, a lock while it runs, a done marker after its stats were read
back, failures recorded and retried, a progress line, Ctrl-C), so an experiment and a sweep
spec run frames the same way. Standard library only."""
import os
import signal
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "sweep"))
from strata_sweep import local, results as results_mod, run as run_mod, spec  # noqa: E402,F401

# STRATA_SIM: another simulator binary, e.g. a copy that a rebuild during a long sweep leaves alone.
SIM = run_mod.SIM
run_key = run_mod.run_key
with_digest = run_mod.with_digest
flatten = results_mod.flatten


class Result:
    def __init__(self, params, folder, stats=None, error=None, wall=0.0, cached=False):
        self.params, self.folder, self.stats, self.error, self.wall, self.cached = \
            params, folder, stats, error, wall, cached


def sweep(runs, root, jobs=None, timeout=6 * 3600, label="sweep"):
    """Runs every parameter set (duplicates once), `jobs` at a time. Returns the results in the
    order given; Ctrl-C stops cleanly (finished runs stay done) and re-raises."""
    unique = list({run_key(p): p for p in runs}.values())
    done_before = {run_key(p) for p in unique if run_mod.is_done(run_mod.folder_of(root, p))}
    pending = [p for p in unique if run_key(p) not in done_before]
    print(f"{label}: {len(unique)} runs, {len(done_before)} already done, {len(pending)} to run on "
          f"{jobs or os.cpu_count() or 1} worker(s)", file=sys.stderr)
    if pending:
        try:
            local.run_pending(pending, root, jobs, timeout, label, SIM)
        except KeyboardInterrupt:
            print(f"\n{label}: interrupted; finished runs are kept, the rest run next time", file=sys.stderr)
            raise
    by_key = {}
    for p in unique:
        stats, done, error = run_mod.load_result(root, p)
        if stats is None and error is None:
            error = "did not run"
        by_key[run_key(p)] = Result(p, run_mod.folder_of(root, p), stats, error if stats is None else None,
                                    (done or {}).get("wall_seconds", 0.0), run_key(p) in done_before)
    ordered = [by_key[run_key(p)] for p in runs]
    for r in {id(r): r for r in ordered if r.error}.values():
        print(f"{label}: FAILED {r.folder}: {r.error}", file=sys.stderr)
    return ordered


def collect(runs, root):
    """The results of `runs` as they stand, running nothing; a frame not finished has an error."""
    out = []
    for p in runs:
        stats, done, error = run_mod.load_result(root, p)
        out.append(Result(p, run_mod.folder_of(root, p), stats, None if stats is not None else (error or "not run yet"),
                          (done or {}).get("wall_seconds", 0.0), stats is not None))
    return out


def get(stats, path):
    node = stats
    for part in path.split("."):
        node = node[part]
    return node


signal.signal(signal.SIGPIPE, signal.SIG_DFL)
