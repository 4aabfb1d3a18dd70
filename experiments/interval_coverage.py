#!/usr/bin/python3
"""How often does the loosely-timed value lie inside sampled timing's 95% interval?

    experiments/interval_coverage.py [--out out/validate-intervals] [--sampled NAME]

Reads the results of the sweep specs experiments/specs/intervals-lt.json, intervals-sampled.json
and (optionally) intervals-sampled-cold.json, which run the same frames (3 scenes x 3 designs
x 2 seeds) loosely timed, sampled, and sampled without functional warming. Prints, per frame
and metric, the sampled estimate's error against LT and its 95% half-width, then the coverage
(the share of frames whose LT value lies inside the interval) and how wide the intervals are
next to the errors; with the cold runs, the bias before and after functional warming. Writes
the same as coverage.csv in the output folder. --sampled NAME compares the sampled runs in
NAME/ instead of sampled/ (e.g. sampled-batch16k, from intervals-sampled-batch16k.json) and
writes coverage-NAME.csv. Where the sampled runs give the simulated clock
(intervals.simulated_frame_cycles), a last table sets it beside the reported frame time.
The frame time's interval includes the clock's systematic error (frame_time_half_width).
Frames are compared only when both runs executed the same kernel image (the sweep's "kernel"
column, from stats.json's simulation.kernel): a kernel's code layout alone moves frame timing by
a few percent. A pair with different kernels is left out and listed; a run made before the
digest was recorded (2026-12-07) is compared, and listed as unchecked.
Standard library only."""
import argparse
import csv
import json
import os
import sys

METRICS = [("frame.cycles", "cycles"), ("memory.l2.accesses", "L2 accesses"), ("memory.dram.bytes", "DRAM bytes"),
           ("memory.stream.accesses", "stream accesses"), ("energy_nj.total", "energy"),
           ("memory.l1d.hit_rate", "L1 hit rate")]


def load(folder):
    path = os.path.join(folder, "results.json")
    try:
        with open(path) as f:
            rows = json.load(f)
    except OSError:
        return None
    out = {}
    for r in rows:
        if r.get("status") != "done":
            continue
        key = (os.path.basename(r["config"]).removesuffix(".json"), r["scene"], r.get("res"), r.get("seed"))
        out[key] = r
    return out


def value(row, path):
    for col, v in row.items():
        if col.split(" [")[0] == path:
            return v
    return None


def interval(row, path):
    return value(row, f"intervals.stats.{path}.half_width")


CLOCK_BOUND = 0.025  # timing.sample_clock_bound's default (model/sampling/timing_config.h)


def frame_time_half_width(row):
    """The frame time's half-width with the clock's systematic error in it (the larger of its
    disagreement with the samples' estimate and timing.sample_clock_bound, docs/sampled-timing.md,
    "The clock's error in the interval"), and where that came from: "in run" (runs since
    2026-12-07, intervals.frame_time_systematic), "recomputed" (a run that published both frame
    times but not the term: the spread plus that larger one, at the bound's default), or "none"
    (an older run: the spread alone)."""
    hw = interval(row, "frame.cycles") or 0.0
    if value(row, "intervals.frame_time_systematic") is not None:
        return hw, "in run"
    clock, est = value(row, "intervals.simulated_frame_cycles"), value(row, "intervals.samples_frame_cycles")
    if clock and est and value(row, "frame.cycles") == clock:
        return hw + max(abs(est - clock), CLOCK_BOUND * clock), "recomputed"
    return hw, "none"


def same_kernel_pairs(lt, sampled):
    """The frames both sets ran under the same kernel image; those whose kernels differ, with
    the two kernels; and those where either run has no digest (compared, but unchecked)."""
    pairs, mismatched, unchecked = [], [], []
    for key in sorted(set(lt) & set(sampled)):
        a, b = lt[key].get("kernel", ""), sampled[key].get("kernel", "")
        if a and b and a != b:
            mismatched.append((key, (a, b)))
            continue
        if not a or not b:
            unchecked.append(key)
        pairs.append(key)
    return pairs, mismatched, unchecked


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "out",
                                                  "validate-intervals"))
    ap.add_argument("--sampled", default="sampled", help="the folder of the sampled runs, under --out")
    a = ap.parse_args()
    lt, sampled, cold = (load(os.path.join(a.out, n)) for n in ("lt", a.sampled, "sampled-cold"))
    if not lt or not sampled:
        sys.exit(f"interval_coverage: run the specs first (scripts/strata-sweep experiments/specs/intervals-lt.json "
                 f"and intervals-{a.sampled}.json); no results under {a.out}/lt and {a.out}/{a.sampled}")
    pairs, mismatched, unchecked = same_kernel_pairs(lt, sampled)
    for key, kernels in mismatched:
        print(f"left out: {' '.join(map(str, key))}: LT ran {kernels[0]}, sampled ran {kernels[1]} (re-run one of them)")
    for key in unchecked:
        print(f"unchecked: {' '.join(map(str, key))}: a run made before kernel digests were recorded")
    rows, inside, total, ratios, spread_only = [], {}, {}, {}, []
    for key in pairs:
        ref, est = lt[key], sampled[key]
        for path, label in METRICS:
            r, e, hw = value(ref, path), value(est, path), interval(est, path)
            if r is None or e is None:
                continue
            hw = hw or 0.0
            if path == "frame.cycles":
                hw, source = frame_time_half_width(est)
                if source == "none":
                    spread_only.append(key)
                elif source == "recomputed":
                    print(f"recomputed: {' '.join(map(str, key))}: the frame time's interval is the run's spread plus "
                          f"the larger of |samples' estimate - clock| and {CLOCK_BOUND:.1%} of the clock (the run predates "
                          f"intervals.frame_time_systematic)")
            err = e - r
            ok = abs(err) <= hw
            inside[label] = inside.get(label, 0) + ok
            total[label] = total.get(label, 0) + 1
            if hw > 0:
                ratios.setdefault(label, []).append(abs(err) / hw)
            rows.append({"design": key[0], "scene": key[1], "res": key[2], "seed": key[3], "metric": label,
                         "lt": r, "sampled": e, "error": err, "relative error": err / r if r else 0.0,
                         "half width": hw, "relative half width": hw / abs(e) if e else 0.0, "inside": ok})
    for key in spread_only:
        print(f"spread only: {' '.join(map(str, key))}: the run predates intervals.samples_frame_cycles, so its frame-time "
              f"interval lacks the clock's systematic error (re-run it to compare like with like)")
    name = "coverage.csv" if a.sampled == "sampled" else f"coverage-{a.sampled}.csv"
    with open(os.path.join(a.out, name), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("| design | scene | seed | " + " | ".join(l for _, l in METRICS) + " |")
    print("|---|---|---|" + "---|" * len(METRICS))
    by_frame = {}
    for r in rows:
        by_frame.setdefault((r["design"], r["scene"], r["seed"]), {})[r["metric"]] = r
    for (d, s, seed), m in by_frame.items():
        cells = []
        for _, label in METRICS:
            r = m.get(label)
            if r is None:
                cells.append("-")
            elif label == "L1 hit rate":
                cells.append(f"{100 * r['error']:+.2f} ± {100 * r['half width']:.2f} pt{'' if r['inside'] else ' **out**'}")
            else:
                cells.append(f"{100 * r['relative error']:+.1f}% ± {100 * r['relative half width']:.1f}%"
                             f"{'' if r['inside'] else ' **out**'}")
        print(f"| {d} | {s} | {seed} | " + " | ".join(cells) + " |")
    print()
    print("| metric | LT inside the 95% interval | median abs(error) / half-width | mean error | mean abs(error) |")
    print("|---|---|---|---|---|")
    for _, label in METRICS:
        if label in total:
            rs = sorted(ratios.get(label, [0.0]))
            # Relative errors, but points for the hit rate (a ratio already).
            key, unit = ("error", " pt") if label == "L1 hit rate" else ("relative error", "%")
            errs = [100 * r[key] for r in rows if r["metric"] == label]
            print(f"| {label} | {inside[label]} of {total[label]} ({100 * inside[label] / total[label]:.0f}%) | "
                  f"{rs[len(rs) // 2]:.2f} | {sum(errs) / len(errs):+.2f}{unit} | "
                  f"{sum(abs(e) for e in errs) / len(errs):.2f}{unit} |")
    # The samples' own estimate: published beside the clock since 2026-12-07
    # (intervals.samples_frame_cycles); on runs of 2026-12-06 it was frame.cycles itself.
    clocks = [(key, value(sampled[key], "intervals.simulated_frame_cycles"),
               value(sampled[key], "intervals.samples_frame_cycles") or value(sampled[key], "frame.cycles"),
               value(lt[key], "frame.cycles"), frame_time_half_width(sampled[key])[0])
              for key in pairs]
    clocks = [c for c in clocks if c[1] is not None and c[3]]
    if clocks:
        # Runs made while the frame time was the samples' estimate (2026-12-06) report it as
        # frame.cycles; the simulated clock beside it (docs/sampled-timing.md, "The frame time").
        print()
        print("Frame time against LT: the samples' estimate (intervals.samples_frame_cycles; on runs of 2026-12-06 the "
              "reported frame.cycles; on runs between, the clock again) and the simulated clock, each against the reported "
              "interval:")
        print("| design | scene | seed | estimate | clock | half-width |")
        print("|---|---|---|---|---|---|")
        for key, clock, est, ref, hw in clocks:
            hw = hw or 0.0
            cells = [f"{100 * (v / ref - 1):+.2f}%{'' if abs(v - ref) <= hw else ' **out**'}" for v in (est, clock)]
            print(f"| {key[0]} | {key[1]} | {key[3]} | " + " | ".join(cells) + f" | ± {100 * hw / est:.2f}% |")
    if cold:
        print()
        print("Bias against LT before (cold) and after (warm) functional warming, seed 1:")
        print("| design | scene | L2 accesses cold | warm | DRAM bytes cold | warm | cycles cold | warm |")
        print("|---|---|---|---|---|---|---|---|")
        for key in sorted(set(cold) & set(lt)):
            if key not in sampled:
                continue
            cells = []
            for path in ("memory.l2.accesses", "memory.dram.bytes", "frame.cycles"):
                r = value(lt[key], path)
                cells += [f"{100 * (value(cold[key], path) / r - 1):+.1f}%", f"{100 * (value(sampled[key], path) / r - 1):+.1f}%"]
            print(f"| {key[0]} | {key[1]} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
