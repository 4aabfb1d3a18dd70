"""The Slurm backend: one sbatch job array, one task per pending run, with a concurrency limit
(--array=0-N%K) and the partition, time and memory options passed through. Each task runs
strata_sweep.task, which writes the same run folder and done marker as the local backend, so
the results are collected the same way and a re-run submits only the runs still missing.

Runs share the scene cache: strata-sim writes a cache entry to a temporary named by host and
process and renames it into place, so two tasks building the same scene never corrupt it."""
import fcntl
import json
import os
import re
import shlex
import subprocess
import sys
import time

from . import run as run_mod
from .progress import Progress
from .task import SLURM_RECORD

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class SlurmError(RuntimeError):
    pass


def write_job(pending, root, timeout, options, sim=None):
    """Writes the batch file and the sbatch script for `pending`; returns the script's path."""
    d = os.path.join(root, "slurm")
    os.makedirs(d, exist_ok=True)
    stamp = time.strftime("%Y%m%d-%H%M%S") + f"-{os.getpid()}"
    batch = os.path.join(d, f"batch-{stamp}.json")
    run_mod.write_json_atomically(batch, {"runs": pending, "timeout_seconds": timeout, "sim": sim})
    limit = options.get("max_running") or len(pending)
    lines = ["#!/bin/bash",
             f"#SBATCH --job-name={options.get('job_name', 'strata-sweep')}",
             f"#SBATCH --array=0-{len(pending) - 1}%{limit}",
             f"#SBATCH --output={d}/task-%A_%a.out",
             "#SBATCH --cpus-per-task=1"]
    for flag in ("partition", "time", "mem", "account", "qos"):
        if options.get(flag):
            lines.append(f"#SBATCH --{flag}={options[flag]}")
    for extra in options.get("sbatch_args", []):
        lines.append(f"#SBATCH {extra}")
    lines += ["set -euo pipefail",
              f"cd {shlex.quote(PACKAGE_DIR)}",
              f"exec {shlex.quote(sys.executable)} -m strata_sweep.task {shlex.quote(root)} {shlex.quote(batch)} "
              "\"$SLURM_ARRAY_TASK_ID\""]
    script = os.path.join(d, f"job-{stamp}.sh")
    with open(script, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.chmod(script, 0o755)
    return script


def submit(script):
    try:
        p = subprocess.run(["sbatch", "--parsable", script], capture_output=True, text=True)
    except FileNotFoundError:
        raise SlurmError("sbatch not found: the slurm backend needs the Slurm client commands on PATH")
    if p.returncode != 0:
        raise SlurmError(f"sbatch {script} failed ({p.returncode}): {p.stderr.strip()}")
    return p.stdout.strip().split(";")[0]


def tasks_in_queue(job_id):
    p = subprocess.run(["squeue", "-h", "-r", "-j", job_id, "-o", "%i %T"], capture_output=True, text=True)
    if p.returncode != 0:
        # A job that left the queue long ago is unknown to squeue; anything else is an error.
        if "Invalid job id" in p.stderr:
            return {}
        raise SlurmError(f"squeue -j {job_id} failed ({p.returncode}): {p.stderr.strip()}")
    states = {}
    for line in p.stdout.split("\n"):
        if line.strip():
            task, state = line.split()[:2]
            states[task] = state
    return states


def job_end(job_id):
    """(state, exit code) of a finished job from Slurm, or None if Slurm no longer knows it.
    scontrol answers for MinJobAge after the end (no accounting needed); sacct answers later
    where the cluster keeps accounting (slurmdbd), or a job completion log (--completion)."""
    p = subprocess.run(["scontrol", "-o", "show", "job", job_id], capture_output=True, text=True)
    if p.returncode == 0:
        state, code = re.search(r"JobState=(\S+)", p.stdout), re.search(r"\bExitCode=(\S+)", p.stdout)
        if state:
            return state.group(1), code.group(1) if code else "?"
    for extra in ([], ["--completion"]):
        p = subprocess.run(["sacct", *extra, "-n", "-P", "-X", "-j", job_id, "--format=JobID,State,ExitCode"],
                           capture_output=True, text=True)
        for line in p.stdout.splitlines() if p.returncode == 0 else []:
            fields = line.split("|")
            if len(fields) == 3 and fields[0] == job_id:
                return fields[1].split()[0], fields[2]
    return None


def explain(code):
    """Slurm's "status:signal" exit code in words."""
    status, _, signal = code.partition(":")
    if signal not in ("", "0"):
        return f"killed by signal {signal}"
    return f"exit status {status}"


def record_lost_tasks(job_id, pending, root):
    """A task that ended without writing done.json or error.json (killed by a signal, its time
    or memory limit, a node failure, or cancelled) gets an error.json saying what Slurm says of
    it, so the summary gives the reason rather than a silent 'missing'. Returns how many."""
    lost = 0
    for params in pending:
        folder = run_mod.folder_of(root, params)
        if run_mod.is_done(folder) or os.path.exists(os.path.join(folder, "error.json")):
            continue
        try:
            with open(os.path.join(folder, SLURM_RECORD)) as f:
                record = json.load(f)
        except (OSError, ValueError):
            record = None
        if record is None or record.get("array_job_id") != job_id:
            why = f"Slurm job {job_id} ended and its task for this run never started (cancelled, or the job failed)"
        else:
            end = job_end(record["job_id"]) if record.get("job_id") else None
            task = f"{record['array_job_id']}_{record['array_task_id']}"
            why = (f"Slurm task {task} (job {record['job_id']}, {record['host']}) ended {end[0]}, "
                   f"{explain(end[1])}, without a result" if end else
                   f"Slurm task {task} ({record['host']}) ended without a result, and Slurm no longer says why")
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "lock"), "w") as lock:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                continue  # another sweep is running this frame now: its outcome will say
            if not run_mod.is_done(folder):
                run_mod.write_json_atomically(os.path.join(folder, "error.json"), {"error": why, "wall_seconds": 0})
                lost += 1
    return lost


def follow(job_id, pending, root, label="sweep", poll_seconds=2.0):
    """Waits until no task of the job is queued or running, with the progress line over the
    run folders' markers. Ctrl-C cancels the job (scancel) and re-raises."""
    progress = Progress(label, len(pending))
    keys = [run_mod.folder_of(root, p) for p in pending]
    since = time.time()  # an error.json from an earlier submission is not this job's failure

    def failed_now(folder):
        try:
            return os.path.getmtime(os.path.join(folder, "error.json")) >= since
        except OSError:
            return False

    last = None
    try:
        while True:
            queued = tasks_in_queue(job_id)
            done = sum(run_mod.has_done_marker(k) for k in keys)
            failed = sum(failed_now(k) for k in keys)
            running = sum(1 for s in queued.values() if s == "RUNNING")
            if not queued:
                lost = record_lost_tasks(job_id, pending, root)
                progress.update(done, failed + lost, final=True, extra=f" (job {job_id} finished)")
                return
            state = (done, failed, running, len(queued))
            if state != last or progress.terminal:  # a log file gets a line per change, not per poll
                progress.update(done, failed, extra=f" ({running} running, {len(queued) - running} waiting in job {job_id})")
                last = state
            time.sleep(poll_seconds)
    except KeyboardInterrupt:
        subprocess.run(["scancel", job_id])
        print(f"\n{label}: cancelled job {job_id}; finished runs are kept, the rest are submitted next time",
              file=sys.stderr)
        raise


def run_pending(pending, root, timeout, options, label="sweep", dry_run=False, sim=None):
    script = write_job(pending, root, timeout, options, sim)
    if dry_run:
        print(f"{label}: wrote {script} ({len(pending)} array tasks); not submitted (--dry-run)", file=sys.stderr)
        return None
    job_id = submit(script)
    print(f"{label}: submitted job {job_id} ({len(pending)} array tasks, script {script})", file=sys.stderr)
    follow(job_id, pending, root, label, options.get("poll_seconds", 2.0))
    return job_id
