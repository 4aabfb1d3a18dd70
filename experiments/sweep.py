#!/usr/bin/python3
"""A small, resumable sweep runner for strata-sim frames (standard library only).

Each run is a dict of parameters (config, scene, resolution, --set overrides, ...). Its folder
is named by a stable hash of those parameters, so the same frame asked for by two experiments
runs once. A run that finished is marked by done.json, written atomically after its stats.json
was read back; the next invocation skips it. A run that crashed, timed out or was interrupted
has no marker and runs again. Failures are recorded (error.json) and do not stop the others.

Used by experiments/paper.py; written so that a fuller sweep tool (specs from files, a Slurm
backend) can grow from it without changing the experiments.
"""
import concurrent.futures
import hashlib
import json
import os
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# STRATA_SIM: another simulator binary, e.g. a copy that a rebuild during a long sweep leaves alone.
SIM = os.environ.get("STRATA_SIM") or os.path.join(ROOT, "build", "sim", "strata-sim")


def run_key(params):
    """Stable name of a run: the same parameters always give the same folder."""
    text = json.dumps(params, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def command(params, out_dir):
    cmd = [SIM, "run", "--config", os.path.join(ROOT, "sim", "configs", params["config"] + ".json"),
           "--scene", params["scene"], "--res", params["res"], "--out", out_dir, "--quiet"]
    for key in ("spp", "seed", "max_path_vertices"):
        if key in params:
            cmd += ["--" + key.replace("_", "-"), str(params[key])]
    for path, value in sorted(params.get("set", {}).items()):
        cmd += ["--set", f"{path}={json.dumps(value) if not isinstance(value, str) else value}"]
    return cmd


def write_atomically(path, obj):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=1, sort_keys=True)
        f.write("\n")
    os.replace(tmp, path)


class Result:
    def __init__(self, params, folder, stats=None, error=None, wall=0.0, cached=False):
        self.params, self.folder, self.stats, self.error, self.wall, self.cached = \
            params, folder, stats, error, wall, cached


def run_one(params, root, timeout):
    folder = os.path.join(root, "runs", run_key(params))
    done = os.path.join(folder, "done.json")
    stats_path = os.path.join(folder, "out", "stats.json")
    if os.path.exists(done):
        with open(stats_path) as f:
            return Result(params, folder, json.load(f), wall=json.load(open(done))["wall_seconds"], cached=True)
    os.makedirs(folder, exist_ok=True)
    write_atomically(os.path.join(folder, "params.json"), params)
    for stale in ("error.json", "done.json"):
        if os.path.exists(os.path.join(folder, stale)):
            os.remove(os.path.join(folder, stale))
    env = dict(os.environ, SC_COPYRIGHT_MESSAGE="DISABLE")
    t0 = time.monotonic()
    try:
        with open(os.path.join(folder, "log.txt"), "w") as log:
            p = subprocess.run(command(params, os.path.join(folder, "out")), stdout=log, stderr=subprocess.STDOUT,
                               env=env, timeout=timeout)
        wall = time.monotonic() - t0
        if p.returncode != 0:
            tail = open(os.path.join(folder, "log.txt")).read().strip().splitlines()[-3:]
            raise RuntimeError(f"strata-sim exited with {p.returncode}: " + " | ".join(tail))
        with open(stats_path) as f:
            stats = json.load(f)  # complete and parseable, or this run is not done
        if stats.get("interrupted") or "frame" not in stats:
            raise RuntimeError("stats.json is not a finished frame")
    except (subprocess.TimeoutExpired, RuntimeError, OSError, ValueError) as e:
        error = f"timed out after {timeout} s" if isinstance(e, subprocess.TimeoutExpired) else str(e)
        write_atomically(os.path.join(folder, "error.json"), {"error": error, "params": params})
        return Result(params, folder, error=error, wall=time.monotonic() - t0)
    write_atomically(done, {"wall_seconds": wall, "finished": time.strftime("%Y-%m-%dT%H:%M:%S")})
    return Result(params, folder, stats, wall=wall)


def sweep(runs, root, jobs=None, timeout=6 * 3600, label="sweep"):
    """Runs every parameter set (duplicates once), `jobs` at a time, with a progress line.
    Returns the results in the order given. Ctrl-C stops cleanly: finished runs stay done."""
    unique = list({run_key(p): p for p in runs}.values())
    jobs = jobs or os.cpu_count() or 1
    results, todo = {}, []
    for p in unique:
        if os.path.exists(os.path.join(root, "runs", run_key(p), "done.json")):
            results[run_key(p)] = run_one(p, root, timeout)
        else:
            todo.append(p)
    print(f"{label}: {len(unique)} runs, {len(unique) - len(todo)} already done, {len(todo)} to run on {jobs} "
          f"worker(s)", file=sys.stderr)
    start = time.monotonic()
    finished = failed = 0
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=jobs)
    try:
        futures = {pool.submit(run_one, p, root, timeout): p for p in todo}
        for f in concurrent.futures.as_completed(futures):
            r = f.result()
            results[run_key(r.params)] = r
            finished += 1
            failed += r.error is not None
            elapsed = time.monotonic() - start
            eta = elapsed / finished * (len(todo) - finished)
            print(f"\r{label}: {finished}/{len(todo)} runs, {failed} failed, {elapsed / 60:.1f} min elapsed, "
                  f"ETA {eta / 60:.1f} min   ", end="" if finished < len(todo) else "\n", file=sys.stderr)
    except KeyboardInterrupt:
        print(f"\n{label}: interrupted; finished runs are kept, the rest run next time", file=sys.stderr)
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)
    ordered = [results[run_key(p)] for p in runs]
    errors = [r for r in ordered if r.error]
    for r in {id(r): r for r in errors}.values():
        print(f"{label}: FAILED {r.folder}: {r.error}", file=sys.stderr)
    return ordered


def flatten(stats, prefix=""):
    """stats.json as {"dotted.path [unit]": number}, units from its "units" map."""
    units = stats.get("units", {})
    out = {}

    def walk(node, path):
        if isinstance(node, dict):
            for k, v in node.items():
                if k in ("config", "units") and not path:
                    continue
                walk(v, f"{path}.{k}" if path else k)
        elif isinstance(node, (int, float)) and not isinstance(node, bool):
            unit = units.get(path)
            out[f"{prefix}{path}" + (f" [{unit}]" if unit else "")] = node

    walk(stats, "")
    return out


def get(stats, path):
    node = stats
    for part in path.split("."):
        node = node[part]
    return node


signal.signal(signal.SIGPIPE, signal.SIG_DFL)
