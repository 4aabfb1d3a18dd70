"""strata-sweep SPEC: runs a sweep's pending runs (local or Slurm), then writes results.csv,
results.json and the plots. Exit status 0 when every run is done, 1 when some failed or are
still missing (each failure is listed with its reason), 2 for a bad spec, 130 on Ctrl-C."""
import argparse
import os
import signal
import sys

from . import local, plot, results, slurm
from . import run as run_mod
from .spec import SpecError, load


def parse(argv):
    ap = argparse.ArgumentParser(prog="strata-sweep", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("spec", help="sweep specification (JSON; README, 'Sweeps')")
    ap.add_argument("--backend", choices=("local", "slurm"), default="local")
    ap.add_argument("--jobs", type=int, default=0, help="local: runs at a time (default: the number of cores)")
    ap.add_argument("--collect", action="store_true", help="run nothing: gather the results and plots only")
    ap.add_argument("--dry-run", action="store_true", help="slurm: write the sbatch script, do not submit it")
    ap.add_argument("--partition", help="slurm: partition")
    ap.add_argument("--time", help="slurm: time limit per task (e.g. 02:00:00)")
    ap.add_argument("--mem", help="slurm: memory per task (e.g. 4G)")
    ap.add_argument("--account", help="slurm: account")
    ap.add_argument("--max-running", type=int, default=0, help="slurm: array tasks running at once (the %%K)")
    ap.add_argument("--sbatch-arg", action="append", default=[], help="slurm: any other #SBATCH line (repeatable)")
    ap.add_argument("--poll-seconds", type=float, default=5.0, help="slurm: how often squeue is asked")
    ap.add_argument("--sim", help="strata-sim binary (default: build/sim/strata-sim, or $STRATA_SIM)")
    return ap.parse_args(argv)


def main(argv=None):
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    a = parse(argv if argv is not None else sys.argv[1:])
    if a.jobs < 0 or a.max_running < 0:
        print("strata-sweep: --jobs and --max-running must be >= 0", file=sys.stderr)
        return 2
    try:
        spec = load(a.spec)
        runs = [run_mod.with_digest(p) for p in spec.runs()]
    except (SpecError, OSError) as e:
        print(f"strata-sweep: error: {e}", file=sys.stderr)
        return 2
    sim = os.path.abspath(a.sim) if a.sim else None
    if not a.collect and not a.dry_run and not os.access(sim or run_mod.SIM, os.X_OK):
        print(f"strata-sweep: error: {sim or run_mod.SIM}: strata-sim not found (build it with scripts/build)",
              file=sys.stderr)
        return 2
    root, out = spec.store, spec.output  # the run folders, and the tables and plots
    for folder, field in ((root, "runs"), (out, "output")):
        try:
            os.makedirs(folder, exist_ok=True)
        except OSError as e:
            print(f"strata-sweep: error: {a.spec}: {field}: cannot create the folder {folder}: "
                  f"{e.strerror or e}", file=sys.stderr)
            return 2
        if not os.access(folder, os.W_OK | os.X_OK):
            print(f"strata-sweep: error: {a.spec}: {field}: the folder {folder} is not writable", file=sys.stderr)
            return 2
    label = os.path.basename(out)
    unique = list({run_mod.run_key(p): p for p in runs}.values())
    pending = [p for p in unique if not run_mod.is_done(run_mod.folder_of(root, p))]
    print(f"{label}: {len(unique)} runs, {len(unique) - len(pending)} already done, {len(pending)} to run "
          f"({a.backend})", file=sys.stderr)
    try:
        if pending and not a.collect:
            if a.backend == "local":
                local.run_pending(pending, root, a.jobs, spec.timeout, label, sim)
            else:
                options = {"partition": a.partition, "time": a.time, "mem": a.mem, "account": a.account,
                           "max_running": a.max_running, "sbatch_args": a.sbatch_arg, "poll_seconds": a.poll_seconds}
                slurm.run_pending(pending, root, spec.timeout, options, label, a.dry_run, sim)
                if a.dry_run:
                    return 0
    except KeyboardInterrupt:
        print(f"\n{label}: interrupted; finished runs are kept, the rest run next time", file=sys.stderr)
        rows = results.collect(runs, root)
        results.write(rows, out)
        return 130
    except slurm.SlurmError as e:
        print(f"strata-sweep: error: {e}", file=sys.stderr)
        return 1
    rows = results.collect(runs, root)
    csv_path, json_path = results.write(rows, out)
    simulators = {r["simulator"] for r in rows if r.get("simulator")}
    if len(simulators) > 1:
        print(f"{label}: warning: the finished runs come from {len(simulators)} different strata-sim binaries "
              "(column 'simulator'); compare them only if the model did not change between them", file=sys.stderr)
    for entry in spec.plots:
        try:
            print(f"{label}: plot {plot.draw(entry, rows, out)}", file=sys.stderr)
        except plot.PlotError as e:
            print(f"strata-sweep: plot not drawn: {e}", file=sys.stderr)
    done = sum(r["status"] == "done" for r in rows)
    failed = [r for r in rows if r["status"] == "failed"]
    missing = [r for r in rows if r["status"] == "pending"]
    for r in failed:
        print(f"{label}: FAILED run {r['run']} ({os.path.join(root, 'runs', r['run'])}): {r['error']}", file=sys.stderr)
    print(f"{label}: {done} done, {len(failed)} failed, {len(missing)} missing; results in {csv_path} and "
          f"{json_path}", file=sys.stderr)
    return 0 if done == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
