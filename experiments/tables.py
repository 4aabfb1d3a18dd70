#!/usr/bin/python3
"""Markdown tables of the paper experiments' CSVs (out/experiments/*.csv), for
docs/paper-reproduction.md: experiments/tables.py [OUT_DIR]. Standard library only."""
import csv
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DESIGN = {"trax": "trax", "strata-streams": "streams", "strata-pipelines": "pipelines"}
CLASSES = ["nodes", "triangles", "scene", "path_state", "framebuffer", "thread_data", "instructions", "rays"]


def rows(out, name):
    with open(os.path.join(out, name + ".csv")) as f:
        return list(csv.DictReader(f))


def num(r, prefix):
    for k, v in r.items():
        if k == prefix or k.startswith(prefix + " ["):
            return float(v)
    raise KeyError(prefix)


def design(r):
    return DESIGN[os.path.basename(r["config"]).removesuffix(".json")]


def scenes_of(rs):
    seen = []
    for r in rs:
        if r["scene"] not in seen:
            seen.append(r["scene"])
    return seen


def fig3(out):
    rs = rows(out, "fig3-fps-vs-tms")
    tms = sorted({int(r["set tms"]) for r in rs})
    print("| scene | design | " + " | ".join(f"{t} TMs" for t in tms) + " |")
    print("|---|---|" + "---|" * len(tms))
    for s in scenes_of(rs):
        for d in ("trax", "streams"):
            by = {int(r["set tms"]): num(r, "frame.frames_per_second") for r in rs if r["scene"] == s and design(r) == d}
            print(f"| {s} | {d} | " + " | ".join(f"{by[t]:,.0f}" if t in by else "-" for t in tms) + " |")


def size_of(r):
    return int(r.get("set memory.l2.size_bytes") or r.get("set memory.stream.size_bytes"))


def label(z):
    return f"{z >> 20} MB" if z >= 1 << 20 else f"{z >> 10} KB"


def size_table(rs, caption, second):
    """Prints the caption and the header of a table with one column per L2/stream size."""
    sizes = sorted({size_of(r) for r in rs})
    print(caption + "\n")
    print(f"| scene | {second} | " + " | ".join(label(z) for z in sizes) + " |")
    print("|---|---|" + "---|" * len(sizes))
    return sizes


def fig4(out):
    rs = rows(out, "fig4-traffic-vs-size")
    sizes = size_table(rs, "L2 accesses (= L1 misses), and for STRaTA the stream accesses, in millions per frame:",
                       "series")
    for s in scenes_of(rs):
        for d, path, what in (("trax", "memory.l2.accesses", "trax L2"), ("streams", "memory.l2.accesses", "streams L2"),
                              ("streams", "memory.stream.accesses", "streams stream")):
            by = {size_of(r): num(r, path) for r in rs if r["scene"] == s and design(r) == d}
            print(f"| {s} | {what} | " + " | ".join(f"{by[z] / 1e6:.2f}" if z in by else "-" for z in sizes) + " |")


def fig5_7(out):
    rs = rows(out, "fig5-7-energy")
    sizes = size_table(rs, "Memory energy per frame in mJ (L2 or L2 + stream memory / DRAM):", "design")
    for s in scenes_of(rs):
        for d in ("trax", "streams"):
            by = {size_of(r): (num(r, "energy_nj.l2_and_stream") / 1e6, num(r, "energy_nj.dram") / 1e6)
                  for r in rs if r["scene"] == s and design(r) == d}
            print(f"| {s} | {d} | " + " | ".join(f"{by[z][0]:.2f} / {by[z][1]:.2f}" if z in by else "-" for z in sizes)
                  + " |")


def table2(out):
    rs = rows(out, "table2-fetch-rf")
    print("| scene | design | fetch [mJ] | % of trax | register file [mJ] | % of trax | instructions [M] |")
    print("|---|---|---|---|---|---|---|")
    for s in scenes_of(rs):
        base = next(r for r in rs if r["scene"] == s and design(r) == "trax")
        for d in ("trax", "streams", "pipelines"):
            r = next(r for r in rs if r["scene"] == s and design(r) == d)
            f, rf = num(r, "energy_nj.instruction_fetch"), num(r, "energy_nj.register_file")
            print(f"| {s} | {d} | {f / 1e6:.2f} | {100 * f / num(base, 'energy_nj.instruction_fetch'):.0f}% | "
                  f"{rf / 1e6:.2f} | {100 * rf / num(base, 'energy_nj.register_file'):.0f}% | "
                  f"{num(r, 'instructions.retired') / 1e6:.1f} |")


def dram_by_class(out):
    rs = rows(out, "dram-by-class")
    print("| scene | design | frames/s | L1 hit | L2 accesses [M] | DRAM [MB] | " +
          " | ".join(c.replace("_", " ") for c in CLASSES) + " | energy [mJ] |")
    print("|---|---|---|---|---|---|" + "---|" * len(CLASSES) + "---|")
    for s in scenes_of(rs):
        for d in ("trax", "streams", "pipelines"):
            r = next(r for r in rs if r["scene"] == s and design(r) == d)
            total = num(r, "memory.dram.bytes")
            shares = [num(r, f"memory.dram.by_data.{c}.bytes") / total if total else 0 for c in CLASSES]
            print(f"| {s} | {d} | {num(r, 'frame.frames_per_second'):,.0f} | {100 * num(r, 'memory.l1d.hit_rate'):.2f}% | "
                  f"{num(r, 'memory.l2.accesses') / 1e6:.2f} | {total / 1e6:.1f} | " +
                  " | ".join(f"{100 * x:.0f}%" if x >= 0.005 else "-" for x in shares) +
                  f" | {num(r, 'energy_nj.total') / 1e6:.1f} |")


def size_check(out):
    rs = rows(out, "size-check")
    print("| TMs | " + " | ".join(sorted({r["res"] for r in rs}, key=lambda x: int(x.split("x")[0]))) +
          " | relative to 128 TMs, each size | difference |")
    print("|---|---|---|---|---|")
    res = sorted({r["res"] for r in rs}, key=lambda x: int(x.split("x")[0]))
    fps = {(r["res"], int(r["set tms"])): num(r, "frame.frames_per_second") for r in rs}
    for t in sorted({int(r["set tms"]) for r in rs}):
        rel = [fps[(x, t)] / fps[(x, 128)] for x in res]
        print(f"| {t} | " + " | ".join(f"{fps[(x, t)]:,.0f} fps" for x in res) + " | " +
              " / ".join(f"{v:.3f}" for v in rel) + f" | {100 * (rel[0] - rel[1]) / rel[1]:+.1f}% |")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "out", "experiments")
    for name, f in (("Fig. 3", fig3), ("Fig. 4", fig4), ("Figs. 5-7", fig5_7), ("Table 2", table2),
                    ("DRAM by class", dram_by_class), ("size check", size_check)):
        print(f"\n### {name}\n")
        try:
            f(out)
        except (OSError, KeyError, StopIteration) as e:
            print(f"(not available: {e})")


if __name__ == "__main__":
    main()
