#!/usr/bin/python3
"""The fidelity report: one frame in every timing mode, each measured against precise.

    scripts/fidelity [scene] [design] [WxH] [--out DIR] [--jobs N]
    (defaults: sibenik strata-pipelines 128x128, out/fidelity/<scene>-<design>-<WxH>, one
    frame per core)

Runs the frame in precise timing, loosely timed at quanta of 100, 1,000 and 10,000 cycles (and at
1,000 with stream and global-register operations in arrival order), and
sampled at error targets of 1%, 2% and 5% (on strata-sweep's runner: resumable, one folder per
frame), then writes fidelity.csv and fidelity.md (a table: each mode's wall time, speed, and its
error against precise in frame cycles, L1 data hit rate, L2 accesses, DRAM bytes and total
energy, with the sampled runs' own 95% intervals) and fidelity.png (wall time against each
error). The README points here for choosing a mode. Debian's Python: standard library and
matplotlib."""
import argparse
import csv
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "sweep"))
from strata_sweep import local, run as run_mod  # noqa: E402
import arguments  # noqa: E402  (experiments/, this script's folder)

MODES = [("precise", {"timing.mode": "precise"}),
         ("lt q=100", {"timing.mode": "lt", "timing.quantum_cycles": 100}),
         ("lt q=1000", {"timing.mode": "lt", "timing.quantum_cycles": 1000}),
         # Stream and global-register operations in arrival order: faster, and the TMs' ray
         # schedule is no longer precise mode's (docs/memory-system.md).
         ("lt q=1000 arrival", {"timing.mode": "lt", "timing.quantum_cycles": 1000, "timing.sync_shared_ops": False}),
         ("lt q=10000", {"timing.mode": "lt", "timing.quantum_cycles": 10000}),
         ("sampled 1%", {"timing.mode": "sampled", "timing.sample_target_error": 0.01}),
         ("sampled 2%", {"timing.mode": "sampled", "timing.sample_target_error": 0.02}),
         ("sampled 5%", {"timing.mode": "sampled", "timing.sample_target_error": 0.05})]
METRICS = [("frame.cycles", "frame cycles", "%"), ("memory.l1d.hit_rate", "L1 data hit rate", "points"),
           ("memory.l2.accesses", "L2 accesses", "%"), ("memory.dram.bytes", "DRAM bytes", "%"),
           ("energy_nj.total", "energy", "%")]


def get(stats, path):
    node = stats
    for part in path.split("."):
        node = node[part]
    return node


def half_width(stats, path):
    node = stats.get("intervals", {}).get("stats", {})
    for part in path.split("."):
        node = node.get(part, {}) if isinstance(node, dict) else {}
    return node.get("half_width") if isinstance(node, dict) else None


def error(value, reference, unit):
    return 100.0 * (value - reference) if unit == "points" else 100.0 * (value / reference - 1.0)


def build():
    """scripts/build, its output on stdout dropped as the wrapper always did. Here rather than in
    scripts/fidelity, so that a mistyped argument is refused before a build, not after one."""
    status = subprocess.run([os.path.join(ROOT, "scripts", "build")], stdout=subprocess.DEVNULL).returncode
    if status != 0:
        sys.exit(status)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    # The arguments are checked as they are parsed (experiments/arguments.py): a bad one is an
    # argparse error naming it (exit 2), before any build, folder or frame.
    ap.add_argument("scene", nargs="?", default="sibenik")
    ap.add_argument("design", nargs="?", default="strata-pipelines")
    ap.add_argument("res", nargs="?", default="128x128", type=arguments.resolution,
                    help=f"frame size WxH, 1..{arguments.MAX_SIDE} each (default 128x128)")
    ap.add_argument("--out", type=arguments.output_folder,
                    help="output folder (default out/fidelity/<scene>-<design>-<WxH>)")
    ap.add_argument("--jobs", type=arguments.positive_int,
                    help="frames at once, 1 or more (default: the number of cores)")
    ap.add_argument("--build", action="store_true",
                    help="build strata-sim first (scripts/build), once the arguments are checked; "
                         "scripts/fidelity passes it")
    a = ap.parse_args()
    try:
        config = run_mod.resolve_config(a.design, ROOT, "argument design")
    except ValueError as e:
        ap.error(str(e))
    out = a.out or os.path.join(ROOT, "out", "fidelity", f"{a.scene.split(':')[0]}-{a.design}-{a.res}")
    if not a.out:  # the default is made of the arguments: checked as --out would be
        try:
            arguments.output_folder(out)
        except argparse.ArgumentTypeError as e:
            ap.error(f"argument --out (default): {e}")
    if a.build:
        build()
    os.makedirs(out, exist_ok=True)
    runs = [run_mod.with_digest({"config": config, "scene": a.scene, "res": a.res, "set": dict(sets)})
            for _, sets in MODES]
    # Every error is against the precise frame, so all frames must come from this build.
    rebuilt = run_mod.forget_other_builds(out, runs)
    if rebuilt:
        print(f"fidelity: {rebuilt} finished frame(s) were made by another strata-sim build "
              f"({run_mod.SIM}): running them again", file=sys.stderr)
    pending = [p for p in runs if not run_mod.is_done(run_mod.folder_of(out, p))]
    print(f"fidelity: {len(runs)} frames, {len(runs) - len(pending)} already done", file=sys.stderr)
    if pending:
        if not os.access(run_mod.SIM, os.X_OK):
            sys.exit(f"fidelity: {run_mod.SIM} not found: build first (scripts/build)")
        local.run_pending(pending, out, a.jobs, 12 * 3600, "fidelity")
    results = []
    for (label, _), p in zip(MODES, runs):
        stats, done, err = run_mod.load_result(out, p)
        if stats is None:
            sys.exit(f"fidelity: the {label} frame failed: {err or 'did not finish'} ({run_mod.folder_of(out, p)})")
        results.append((label, stats, done["wall_seconds"]))
    ref = results[0][1]
    rows = []
    for label, stats, wall in results:
        row = {"mode": label, "wall [s]": round(wall, 2),
               "speed [M instructions/s]": round(get(stats, "instructions.retired") / wall * 1e-6, 2),
               "timed share": round(get(stats, "sampling.timed_instructions") / get(stats, "instructions.retired"), 4)
               if "sampling" in stats else 1.0}
        for path, name, unit in METRICS:
            v, r = get(stats, path), get(ref, path)
            row[f"{name} error [{unit}]"] = round(error(v, r, unit), 3)
            hw = half_width(stats, path)
            row[f"{name} 95% half-width [{unit}]"] = "" if hw is None else round(
                100.0 * hw if unit == "points" else 100.0 * hw / abs(v), 3)
        rows.append(row)
    with open(os.path.join(out, "fidelity.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    lines = [f"Fidelity of the timing modes: {a.scene}, {a.design}, {a.res}; errors against precise "
             f"({ref['frame']['cycles']:,} cycles, L1 hit {100 * get(ref, 'memory.l1d.hit_rate'):.2f}%, "
             f"{get(ref, 'memory.l2.accesses') / 1e6:.2f} M L2 accesses, {get(ref, 'memory.dram.bytes') / 1e6:.1f} MB "
             f"DRAM, {get(ref, 'energy_nj.total') / 1e6:.1f} mJ).", "",
             "| mode | wall [s] | x precise | M instr/s | timed | " + " | ".join(n for _, n, _ in METRICS) + " |",
             "|---|---|---|---|---|" + "---|" * len(METRICS)]
    for row in rows:
        cells = []
        for _, name, unit in METRICS:
            e, hw = row[f"{name} error [{unit}]"], row[f"{name} 95% half-width [{unit}]"]
            suffix = " pt" if unit == "points" else "%"
            cells.append(f"{e:+.2f}{suffix}" + (f" (± {hw:.2f})" if hw != "" else ""))
        lines.append(f"| {row['mode']} | {row['wall [s]']:.1f} | {rows[0]['wall [s]'] / row['wall [s]']:.1f} | "
                     f"{row['speed [M instructions/s]']:.1f} | {100 * row['timed share']:.0f}% | " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "fidelity.md"), "w") as f:
        f.write(text)
    print(text)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(METRICS), figsize=(4 * len(METRICS), 3.8))
    for ax, (_, name, unit) in zip(axes, METRICS):
        for row in rows[1:]:
            ax.scatter(row["wall [s]"], abs(row[f"{name} error [{unit}]"]), label=row["mode"],
                       marker="o" if row["mode"].startswith("lt") else "s")
        ax.axvline(rows[0]["wall [s]"], color="grey", ls=":", lw=1)
        ax.set_xscale("log")
        ax.set_xlabel("wall time [s] (dotted: precise)")
        ax.set_ylabel(f"|error| against precise [{'points' if unit == 'points' else '%'}]")
        ax.set_title(name)
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"Speed against error: {a.scene}, {a.design}, {a.res}")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fidelity.png"), dpi=110)
    print(f"fidelity: {out}/fidelity.md, .csv, .png", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
