#!/usr/bin/python3
"""The STRaTA paper's experiments (Kopta et al., HPG 2013), each one command that runs its
frames (on strata-sweep's runner through experiments/sweep.py: resumable, one folder per frame),
writes a CSV with one row per frame (its parameters, then every statistic with its unit), and
draws the figure as a PNG. Each experiment's frames are a sweep spec in experiments/specs/, so
`scripts/strata-sweep experiments/specs/<spec>.json` runs the same frames (locally or on Slurm)
into the same run folders, with the spec's generic plots; this command draws the paper's.

    experiments/paper.py EXPERIMENT|all [--res 128x128] [--scenes sibenik,hairball,vegetation]
                         [--jobs N] [--out out/experiments] [--mode lt]
                         [--target-error E [--target-stats S,...]] [--list]

Experiments:
    fig3-fps-vs-tms      frames/s against TMs (16..128), trax and strata-streams, per scene
    fig4-traffic-vs-size L1 misses (= L2 accesses) and stream accesses against L2/stream size
    fig5-7-energy        L2/stream and DRAM energy per frame against L2/stream size, per scene
    table2-fetch-rf      instruction-fetch and register-file energy, 3 designs, 8 MB, 128 TMs
    dram-by-class        DRAM bytes per frame by data class, 3 designs
    size-check           fig3's Sibenik trax series at the chosen and at twice the resolution

Output: <out>/<experiment>.csv, .json and .png; the frames under <out>/runs/.
The paper uses 1024x1024 frames: pass --res 1024x1024 (and --mode sampled) on a cluster.
--mode sampled --target-error 0.02 sets every frame's error target (timing.sample_target_error:
the 95% intervals of frame cycles, DRAM bytes and L2 accesses within 2%); --target-stats names
other statistics for it (timing.sample_target_stats, e.g. frame.cycles,memory.l2.accesses: a
DRAM target that cannot be met drives a STRaTA frame's windows to their densest). Sampled
figures are estimates: the plots draw their 95% intervals as error bars.
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import arguments  # noqa: E402
import sweep  # noqa: E402

DESIGNS = {"trax": "trax", "streams": "strata-streams", "pipelines": "strata-pipelines"}
SIZES = [512 << 10, 1 << 20, 2 << 20, 4 << 20, 8 << 20, 16 << 20]
CLASSES = ["nodes", "triangles", "scene", "path_state", "framebuffer", "thread_data", "instructions", "rays",
           "other"]
SPECS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "specs")


def from_spec(name, args):
    """The frames of experiments/specs/<name>.json, with this command's scenes, resolution and
    timing mode in place of the spec's: the same parameter sets strata-sweep makes of the spec,
    so the two share frames. A resolution axis of several values keeps its ratios to the first."""
    path = os.path.join(SPECS, name + ".json")
    with open(path) as f:
        data = json.load(f)
    axes = data["axes"]
    if "scene" in axes:  # a spec that fixes its scene (size-check) keeps it
        axes["scene"] = list(args.scenes)
    w, h = (int(x) for x in args.res.split("x"))
    w0, h0 = (int(x) for x in axes["res"][0].split("x"))
    axes["res"] = [f"{int(r.split('x')[0]) * w // w0}x{int(r.split('x')[1]) * h // h0}" for r in axes["res"]]
    for r in axes["res"]:  # size-check also runs twice --res: that must be a frame strata-sim takes
        if not all(arguments.side_ok(int(x)) for x in r.split("x")):
            raise sweep.spec.SpecError(f"argument --res: '{args.res}': experiments/specs/{name}.json would also "
                                       f"run {r}; width and height must be 1..{arguments.MAX_SIDE}")
    data["timing_mode"] = args.mode
    if args.target_error:
        data.setdefault("fixed", {}).setdefault("set", {})["timing.sample_target_error"] = args.target_error
    if args.target_stats:
        data["fixed"]["set"]["timing.sample_target_stats"] = ",".join(args.target_stats)
    return [sweep.with_digest(p) for p in sweep.spec.Spec(path, data).runs()]


# ---- Plots ---------------------------------------------------------------------------------

def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def design_of(r):
    name = os.path.basename(r.params["config"]).removesuffix(".json")
    return {v: k for k, v in DESIGNS.items()}[name]


def scene_of(r):
    return r.params["scene"]


def val(r, path):
    return sweep.get(r.stats, path)


def err(r, path, scale=1.0):
    """The 95% half-width of a sampled estimate (stats.json's intervals.stats mirrors the tree),
    times `scale`; 0 for an exact figure or another timing mode."""
    try:
        return sweep.get(r.stats, "intervals.stats." + path + ".half_width") * scale
    except (KeyError, TypeError):
        return 0.0


def line(ax, xs, rs, path, scale=1.0, **kw):
    """A series with its intervals as error bars (none drawn where every figure is exact)."""
    ys = [val(r, path) * scale for r in rs]
    es = [err(r, path, scale) for r in rs]
    if any(es):
        ax.errorbar(xs, ys, yerr=es, capsize=3, **kw)
    else:
        ax.plot(xs, ys, **kw)


def style(design):
    return {"trax": dict(ls="-", marker="o"), "streams": dict(ls="--", marker="s"),
            "pipelines": dict(ls=":", marker="^")}[design]


def title(args, what):
    mode = args.mode + (f", target \u00b1{100 * args.target_error:g}%, 95% CI bars" if args.target_error else
                        ", 95% CI bars" if args.mode == "sampled" else "")
    return f"{what} ({args.res}, {mode})"


def tms_of(r):
    return r.params["set"]["tms"]


def plot_fig3(results, args, png):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for s in args.scenes:
        for d in ("trax", "streams"):
            rs = sorted((r for r in results if scene_of(r) == s and design_of(r) == d), key=tms_of)
            if rs:
                line(ax, [tms_of(r) for r in rs], rs, "frame.frames_per_second", label=f"{s}, {DESIGNS[d]}",
                     **style(d))
    ax.set_xlabel("TMs (32 TPs each)")
    ax.set_ylabel("frames per second [1/s]")
    ax.set_title(title(args, "Frame rate against chip size (paper Fig. 3)"))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def size_label(z):
    return f"{z >> 20} MB" if z >= 1 << 20 else f"{z >> 10} KB"


def size_of(r):
    s = r.params["set"]
    return s.get("memory.l2.size_bytes", s.get("memory.stream.size_bytes"))


def size_panels(results, args, png, suptitle, ylabel, draw, log_y=False):
    """One panel per scene, L2/stream size on the x axis; draw(ax, design, xs, runs) plots a design."""
    plt = pyplot()
    fig, axes = plt.subplots(1, len(args.scenes), figsize=(max(7.5, 5 * len(args.scenes)), 4.2), squeeze=False)
    for ax, s in zip(axes[0], args.scenes):
        for d in ("trax", "streams"):
            rs = sorted((r for r in results if scene_of(r) == s and design_of(r) == d), key=size_of)
            if rs:
                draw(ax, d, [size_of(r) for r in rs], rs)
        ax.set_xscale("log", base=2)
        ax.set_xticks(SIZES, [size_label(z) for z in SIZES])
        if log_y:
            ax.set_yscale("log")
        ax.set_xlabel("L2 (trax) or stream memory (strata) size")
        ax.set_ylabel(ylabel)
        ax.set_title(s)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.suptitle(title(args, suptitle), fontsize=10, wrap=True)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def plot_fig4(results, args, png):
    def draw(ax, d, xs, rs):
        line(ax, xs, rs, "memory.l2.accesses", label=f"{DESIGNS[d]}: L1 misses (L2 accesses)", **style(d))
        if d == "streams":
            line(ax, xs, rs, "memory.stream.accesses", label=f"{DESIGNS[d]}: stream accesses", ls="-.", marker="x")
    size_panels(results, args, png, "On-chip traffic against L2 / stream size (paper Fig. 4)",
                "accesses per frame [count]", draw, log_y=True)


def plot_fig5_7(results, args, png):
    def draw(ax, d, xs, rs):
        line(ax, xs, rs, "energy_nj.l2_and_stream", 1e-6,
             label=f"{DESIGNS[d]}: {'L2' if d == 'trax' else 'L2 + stream'}", **style(d))
        line(ax, xs, rs, "energy_nj.dram", 1e-6, label=f"{DESIGNS[d]}: DRAM", ls=style(d)["ls"], marker="D",
             alpha=0.7)
    size_panels(results, args, png, "Memory energy against L2 / stream size (paper Figs. 5-7)",
                "energy per frame [mJ]", draw)


def plot_table2(results, args, png):
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    width = 0.8 / len(DESIGNS)
    for ax, (key, label) in zip(axes, (("instruction_fetch", "instruction fetch"), ("register_file", "register file"))):
        for i, d in enumerate(DESIGNS):
            ys, es, pct = [], [], []
            for s in args.scenes:
                r = next(r for r in results if scene_of(r) == s and design_of(r) == d)
                base = next(r for r in results if scene_of(r) == s and design_of(r) == "trax")
                ys.append(val(r, f"energy_nj.{key}") * 1e-9)
                es.append(err(r, f"energy_nj.{key}", 1e-9))
                pct.append(100.0 * val(r, f"energy_nj.{key}") / val(base, f"energy_nj.{key}"))
            xs = [j + i * width for j in range(len(args.scenes))]
            bars = ax.bar(xs, ys, width, label=DESIGNS[d], yerr=es if any(es) else None, capsize=3)
            for b, p in zip(bars, pct):
                ax.annotate(f"{p:.0f}%", (b.get_x() + b.get_width() / 2, b.get_height()), ha="center",
                            va="bottom", fontsize=7)
        ax.set_xticks([j + width for j in range(len(args.scenes))], args.scenes)
        ax.set_ylabel("energy per frame [J]")
        ax.set_title(f"{label} (% of trax)")
        ax.legend(fontsize=8)
    fig.suptitle(title(args, "Instruction-fetch and register-file energy, 128 TMs, 8 MB (paper Table 2)"))
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def plot_dram_by_class(results, args, png):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 4.5))
    labels, bottoms = [], []
    bars, runs = [], []
    for s in args.scenes:
        for d in DESIGNS:
            r = next(r for r in results if scene_of(r) == s and design_of(r) == d)
            runs.append(r)
            labels.append(f"{s}\n{d}")
            bars.append([val(r, f"memory.dram.by_data.{c}.bytes") * 1e-6 for c in CLASSES])
    bottoms = [0.0] * len(bars)
    for ci, c in enumerate(CLASSES):
        heights = [b[ci] for b in bars]
        if not any(heights):
            continue
        ax.bar(range(len(bars)), heights, bottom=bottoms, label=c.replace("_", " "))
        bottoms = [x + y for x, y in zip(bottoms, heights)]
    # The total's interval on top of each stack (the classes' own are in the CSV).
    es = [err(r, "memory.dram.bytes", 1e-6) for r in runs]
    if any(es):
        ax.errorbar(range(len(bars)), [val(r, "memory.dram.bytes") * 1e-6 for r in runs], yerr=es, fmt="none",
                    ecolor="black", capsize=3, label="total, 95% CI")
    ax.set_xticks(range(len(bars)), labels, fontsize=8)
    ax.set_ylabel("DRAM traffic per frame [MB]")
    ax.set_title(title(args, "DRAM traffic by data class"))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def plot_size_check(results, args, png):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    for res in sorted({r.params["res"] for r in results}):
        rs = sorted((r for r in results if r.params["res"] == res), key=tms_of)
        base = rs[-1]
        fps = "frame.frames_per_second"
        ys = [val(r, fps) / val(base, fps) for r in rs]
        # A ratio of two independent estimates: their relative half-widths added in quadrature.
        rel = [math.hypot(err(r, fps) / val(r, fps), err(base, fps) / val(base, fps)) if r is not base
               else 0.0 for r in rs]
        es = [y * e for y, e in zip(ys, rel)]
        ax.errorbar([tms_of(r) for r in rs], ys, yerr=es if any(es) else None, capsize=3, marker="o",
                    label=f"{res}")
    ax.set_xlabel("TMs")
    ax.set_ylabel("frame rate, relative to 128 TMs")
    ax.set_title(title(args, "Sibenik, trax: does the trend hold at 2x the resolution?"))
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)


EXPERIMENTS = {  # name: (its spec in experiments/specs, the paper-style figure)
    "fig3-fps-vs-tms": ("fps-vs-tms", plot_fig3),
    "fig4-traffic-vs-size": ("equal-sram", plot_fig4),
    "fig5-7-energy": ("equal-sram", plot_fig5_7),
    "table2-fetch-rf": ("fetch-rf", plot_table2),
    "dram-by-class": ("dram-by-class", plot_dram_by_class),
    "size-check": ("size-check", plot_size_check),
}


# ---- Tables --------------------------------------------------------------------------------

def write_tables(name, results, out):
    rows = []
    for r in results:
        if r.stats is None:
            continue
        row = {"run": os.path.basename(r.folder), "config": r.params["config"], "scene": r.params["scene"],
               "res": r.params["res"], "mode": r.params.get("mode", "")}
        for k, v in sorted(r.params.get("set", {}).items()):
            row["set " + k] = v
        row["simulator wall [s]"] = round(r.wall, 3)
        row.update(sweep.flatten(r.stats))
        rows.append(row)
    columns = []
    for row in rows:
        columns += [c for c in row if c not in columns]
    with open(os.path.join(out, name + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump(rows, f, indent=1)
    return len(rows)


def plan(names, args, ap):
    """{spec name: its frames} for the experiments `names`; what the specs cannot take from
    --res or --scenes is an argument error (exit 2), before anything runs."""
    try:
        return {EXPERIMENTS[n][0]: from_spec(EXPERIMENTS[n][0], args) for n in names}
    except sweep.spec.SpecError as e:
        ap.error(str(e))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("experiment", nargs="?", help="one of the experiments, or 'all'")
    # The arguments are checked as they are parsed (experiments/arguments.py): a bad one is an
    # argparse error naming it, before any frame runs or any folder is made.
    ap.add_argument("--res", default="128x128", type=arguments.resolution,
                    help=f"frame size WxH, 1..{arguments.MAX_SIDE} each (default 128x128; the paper: 1024x1024)")
    ap.add_argument("--mode", default="lt", choices=["lt", "precise", "sampled"], help="timing mode")
    ap.add_argument("--scenes", default="sibenik,hairball,vegetation", type=arguments.name_list,
                    help="comma-separated scene specs, each once")
    ap.add_argument("--jobs", type=arguments.positive_int, default=os.cpu_count(),
                    help="frames run at once, 1 or more (default: the number of cores)")
    ap.add_argument("--out", default=os.path.join(sweep.ROOT, "out", "experiments"), type=arguments.output_folder,
                    help="output folder")
    ap.add_argument("--target-error", type=arguments.target_error, default=None,
                    help="sampled mode: every frame's error target, the 95%% relative half-width asked of frame "
                         "cycles, DRAM bytes and L2 accesses (0.001..0.5, e.g. 0.02)")
    ap.add_argument("--target-stats", type=arguments.name_list, default=None,
                    help="with --target-error: the statistics it holds for, comma-separated "
                         "(timing.sample_target_stats; default frame cycles, DRAM bytes and L2 accesses)")
    ap.add_argument("--list", action="store_true", help="list the experiments and their frame counts")
    ap.add_argument("--collect", action="store_true",
                    help="run nothing: write the tables of the frames that finished (plots only when all did)")
    args = ap.parse_args()
    if args.target_error and args.mode != "sampled":
        ap.error(f"argument --target-error: an error target is for --mode sampled, not {args.mode}")
    if args.target_stats and not args.target_error:
        ap.error("argument --target-stats: names the statistics of an error target: give --target-error too")
    if args.list or not args.experiment:
        frames = plan(EXPERIMENTS, args, ap)
        for name, (spec, _) in EXPERIMENTS.items():
            print(f"{name:22} {len(frames[spec]):3} frames  (experiments/specs/{spec}.json)")
        return 0
    names = list(EXPERIMENTS) if args.experiment == "all" else [args.experiment]
    unknown = [n for n in names if n not in EXPERIMENTS]
    if unknown:
        ap.error(f"unknown experiment {unknown[0]!r}; --list shows them")
    frames = plan(names, args, ap)
    if not os.access(sweep.SIM, os.X_OK):
        sys.exit(f"paper.py: {sweep.SIM} not found: build first (scripts/build)")
    os.makedirs(args.out, exist_ok=True)
    plans = {n: (frames[EXPERIMENTS[n][0]], EXPERIMENTS[n][1]) for n in names}
    # Every frame of every experiment in one sweep: shared frames run once, all cores stay busy.
    everything = [p for runs, _ in plans.values() for p in runs]
    results = sweep.collect(everything, args.out) if args.collect else \
        sweep.sweep(everything, args.out, args.jobs, label="experiments")
    by_key = {sweep.run_key(r.params): r for r in results}
    failed = 0
    for name, (runs, plot) in plans.items():
        rs = [by_key[sweep.run_key(p)] for p in runs]
        bad = [r for r in rs if r.error]
        failed += len(bad)
        n = write_tables(name, rs, args.out)
        if bad:
            print(f"{name}: {len(bad)} of {len(rs)} frames failed; no plot (the CSV has the {n} that ran)",
                  file=sys.stderr)
            continue
        png = os.path.join(args.out, name + ".png")
        plot(rs, args, png)
        print(f"{name}: {n} frames -> {os.path.join(args.out, name)}.csv, .png")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
