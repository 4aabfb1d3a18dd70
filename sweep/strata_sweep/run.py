"""One run of a sweep: its folder, named by a stable hash of its parameters, the strata-sim
command, and the done marker that makes the sweep resumable.

A run's folder holds params.json, log.txt, out/ (the simulator's outputs) and, at the end,
either done.json (written atomically after stats.json was read back complete and finished) or
error.json. Only done.json counts: a run without it is pending and runs again; a run with it is
never run or counted twice."""
import fcntl
import hashlib
import json
import os
import subprocess
import time

from .spec import ROOT, resolve_config

SIM = os.environ.get("STRATA_SIM") or os.path.join(ROOT, "build", "sim", "strata-sim")


_sim_digests = {}


def simulator_digest(sim=None):
    """The first 16 hex digits of the strata-sim binary's SHA-256, recorded with each finished
    run, so a table can tell frames of two builds apart (the run key does not include it: a
    rebuild that changes nothing would otherwise re-run every frame)."""
    path = os.path.realpath(sim or SIM)
    try:
        st = os.stat(path)
        key = (path, st.st_mtime_ns, st.st_size)  # a rebuild under a running sweep is seen
    except OSError:
        return None
    if key not in _sim_digests:
        h = hashlib.sha256()
        try:
            with open(path, "rb") as f:
                for block in iter(lambda: f.read(1 << 20), b""):
                    h.update(block)
            _sim_digests[key] = h.hexdigest()[:16]
        except OSError:
            _sim_digests[key] = None
    return _sim_digests[key]


def forget_other_builds(root, runs, sim=None):
    """Un-marks the finished runs among `runs` that another strata-sim build made (their
    done.json names a different binary digest), so they run again; returns how many. For
    reports that compare frames with each other (the fidelity report's errors against
    precise), where a frame of an older build would make the comparison meaningless. The old
    marker is kept as done-other-build.json."""
    current = simulator_digest(sim)
    forgotten = 0
    for params in runs:
        folder = folder_of(root, params)
        marker = os.path.join(folder, "done.json")
        try:
            with open(marker) as f:
                made_by = json.load(f).get("simulator_sha256")
        except (OSError, ValueError):
            continue
        if current is not None and made_by != current:
            os.replace(marker, os.path.join(folder, "done-other-build.json"))
            forgotten += 1
    return forgotten


def config_digest(config):
    path = resolve_config(config, ROOT, "config")
    path = path if os.path.isabs(path) else os.path.join(ROOT, path)
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:16]


def with_digest(params):
    """The parameters a key is made of: the config file's content too, so that an edited config
    is a new run rather than a stale result."""
    p = dict(params)
    if "config" in p:
        p["config_sha256"] = config_digest(p["config"])
    return p


def run_key(params):
    text = json.dumps(params, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def folder_of(root, params):
    return os.path.join(root, "runs", run_key(params))


def command(params, out_dir, sim=None):
    config = resolve_config(params["config"], ROOT, "config")  # a design name or a config file
    config = config if os.path.isabs(config) else os.path.join(ROOT, config)
    cmd = [sim or SIM, "run", "--config", config, "--scene", str(params["scene"]), "--out", out_dir, "--quiet"]
    if "res" in params:
        cmd += ["--res", str(params["res"])]
    for key in ("spp", "seed", "max_path_vertices"):
        if key in params:
            cmd += ["--" + key.replace("_", "-"), str(params[key])]
    if params.get("mode"):
        cmd += ["--set", f"timing.mode={params['mode']}"]
    for path, value in sorted(params.get("set", {}).items()):
        cmd += ["--set", f"{path}={value if isinstance(value, str) else json.dumps(value)}"]
    return cmd


def write_json_atomically(path, obj):
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=1, sort_keys=True)
        f.write("\n")
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def read_done(folder):
    """done.json's record, or None when it is missing, cut off or not a JSON object."""
    try:
        with open(os.path.join(folder, "done.json")) as f:
            done = json.load(f)
    except (OSError, ValueError):
        return None
    return done if isinstance(done, dict) else None


def has_done_marker(folder):
    """Cheap (no stats.json read): for progress lines polled while runs are going."""
    return os.path.exists(os.path.join(folder, "done.json"))


def is_done(folder):
    """Done means a whole done.json and a finished stats.json. A cut-off marker, or a marker
    whose stats.json became unreadable, is not done: the run runs again."""
    return read_done(folder) is not None and read_finished_stats(folder) is not None


def not_done_reason(folder):
    """Why a run with a done.json is nonetheless not done, or None."""
    marker = os.path.join(folder, "done.json")
    if not os.path.exists(marker):
        return None
    if read_done(folder) is None:
        return f"{marker} is cut off or not a JSON object: the run runs again"
    if read_finished_stats(folder) is None:
        return (f"{os.path.join(folder, 'out', 'stats.json')} is missing, cut off or not a finished frame "
                "although done.json exists: the run runs again")
    return None


def read_finished_stats(folder):
    """stats.json of a finished run, or None if it is missing, cut off or not a whole frame."""
    try:
        with open(os.path.join(folder, "out", "stats.json")) as f:
            stats = json.load(f)
    except (OSError, ValueError):
        return None
    if not isinstance(stats, dict) or stats.get("interrupted") or "frame" not in stats:
        return None
    return stats


def execute(params, root, timeout, sim=None):
    """Runs one frame into its folder, unless it is done. Returns (stats, error).

    The run holds an exclusive lock on its folder while it runs, so two sweeps sharing an
    output folder (or a local sweep and a Slurm task) never run one frame at once: the second
    waits for the first, then finds it done and counts it once."""
    folder = folder_of(root, params)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if read_done(folder) is not None:
            stats = read_finished_stats(folder)
            if stats is not None:
                return stats, None
        return _execute_locked(params, folder, timeout, sim)


def _execute_locked(params, folder, timeout, sim):
    write_json_atomically(os.path.join(folder, "params.json"), params)
    for stale in ("error.json", "done.json"):
        try:
            os.remove(os.path.join(folder, stale))
        except FileNotFoundError:
            pass
    env = dict(os.environ, SC_COPYRIGHT_MESSAGE="DISABLE")
    t0 = time.monotonic()
    error = None
    try:
        with open(os.path.join(folder, "log.txt"), "w") as log:
            p = subprocess.run(command(params, os.path.join(folder, "out"), sim), stdout=log,
                               stderr=subprocess.STDOUT, env=env, timeout=timeout)
        if p.returncode != 0:
            with open(os.path.join(folder, "log.txt"), errors="replace") as f:
                tail = [line for line in f.read().strip().splitlines() if line.strip()][-2:]
            error = f"strata-sim exited with {p.returncode}: " + " | ".join(tail)
    except subprocess.TimeoutExpired:
        error = f"timed out after {timeout} s"
    except OSError as e:
        error = f"cannot start strata-sim: {e}"
    wall = time.monotonic() - t0
    stats = None
    if error is None:
        stats = read_finished_stats(folder)
        if stats is None:
            error = "stats.json is missing, cut off or not a finished frame"
    if error is not None:
        write_json_atomically(os.path.join(folder, "error.json"), {"error": error, "wall_seconds": wall})
        return None, error
    write_json_atomically(os.path.join(folder, "done.json"),
                          {"wall_seconds": wall, "finished": time.strftime("%Y-%m-%dT%H:%M:%S"),
                           "host": os.uname().nodename, "simulator_sha256": simulator_digest(sim)})
    return stats, None


def load_result(root, params):
    """(stats, done_info, error) of a run from its folder, whatever ran it."""
    folder = folder_of(root, params)
    done = read_done(folder)
    stats = read_finished_stats(folder) if done is not None else None
    if stats is not None:
        return stats, done, None
    reason = not_done_reason(folder)
    if reason is not None:
        return None, None, reason
    try:
        with open(os.path.join(folder, "error.json")) as f:
            return None, None, json.load(f)["error"]
    except (OSError, ValueError, KeyError):
        return None, None, None
