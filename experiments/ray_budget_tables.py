#!/usr/bin/env python3
"""The tables of issue 34 (the ray budget) from the sweeps' results, as Markdown:

  experiments/ray_budget_tables.py budget [OUT]   ray-budget: stream memory size x path state
  experiments/ray_budget_tables.py scale [OUT]    scale-check (sampled) and scale-check-lt

OUT is the experiments folder (default out/experiments). Each table names its timing mode; a
sampled figure carries its 95% half-width where the run reported one. Standard library only.
"""
import csv
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rows(out, spec):
    path = os.path.join(out, spec, "results.csv")
    if not os.path.exists(path):
        sys.exit(f"ray_budget_tables: {path} is missing: run scripts/strata-sweep experiments/specs/{spec}.json")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def col(row, path):
    """The value of statistic `path` (its column is 'path [unit]'), or None."""
    for key, value in row.items():
        if key == path or key.startswith(path + " ["):
            return float(value) if value not in ("", None) else None
    return None


def param(row, name):
    for key in (name, "set " + name):
        if key in row and row[key] != "":
            return row[key]
    return ""


def half_width(row, path):
    """A sampled run's 95% half-width (relative) of `path`, from its stats.json, or None."""
    run = row.get("run_dir") or row.get("run") or ""
    stats = os.path.join(run, "out", "stats.json") if run else ""
    if not stats or not os.path.exists(stats):
        return None
    with open(stats) as f:
        node = json.load(f).get("intervals", {}).get("stats", {})
    for part in path.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node if isinstance(node, (int, float)) else None


def design_of(row):
    name = param(row, "design") or os.path.basename(param(row, "config")).replace(".json", "")
    return name


def fmt(v, digits=1, scale=1.0):
    return "-" if v is None else f"{v * scale:,.{digits}f}"


def budget(out):
    print("Sibenik 256x256, 128 TMs, loosely timed (`experiments/specs/ray-budget.json`):\n")
    print("| design | path state | stream memory | capacity [rays] | SRAM per ray [B] | rays in flight: mean / steady [rays] "
          "| DRAM [MB] | L2 accesses [M] | sessions | rays / session | L1 lines filled / session (L2 hit / DRAM) | frame [M cycles] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    table = rows(out, "ray-budget")
    table.sort(key=lambda r: (design_of(r), param(r, "design.path_state"), float(param(r, "memory.stream.size_bytes") or 0)))
    for r in table:
        streams = design_of(r) != "trax"
        size = param(r, "memory.stream.size_bytes")
        print("| {} | {} | {} | {} | {} | {} / {} | {} | {} | {} | {} | {} ({} / {}) | {} |".format(
            design_of(r), param(r, "design.path_state") or ("-" if not streams else "compact"),
            f"{float(size) / 1048576:g} MB" if size else ("4 MB" if streams else "- (4 MB L2)"),
            fmt(col(r, "memory.stream.capacity"), 0) if streams else "-",
            fmt(col(r, "memory.stream.sram_bytes_per_ray"), 0) if streams else "-",
            fmt(col(r, "treelets.rays_in_flight.mean"), 0) if streams else "-",
            fmt(col(r, "treelets.rays_in_flight.steady_state"), 0) if streams else "-",
            fmt(col(r, "memory.dram.bytes"), 1, 1e-6), fmt(col(r, "memory.l2.accesses"), 2, 1e-6),
            fmt(col(r, "treelets.sessions.sessions"), 0) if streams else "-",
            fmt(col(r, "treelets.sessions.rays_per_session"), 1) if streams else "-",
            fmt(col(r, "treelets.sessions.lines_per_session"), 1) if streams else "-",
            fmt(col(r, "treelets.sessions.l2_hit_lines_per_session"), 1) if streams else "-",
            fmt(col(r, "treelets.sessions.dram_lines_per_session"), 2) if streams else "-",
            fmt(col(r, "frame.cycles"), 3, 1e-6)))


def per_ray(r, path):
    v, rays = col(r, path), col(r, "rays.total")
    return None if v is None or not rays else v / rays


def scale(out):
    sampled = rows(out, "scale-check")
    lt = {(r["scene"], design_of(r), r["res"]): r for r in rows(out, "scale-check-lt")} \
        if os.path.exists(os.path.join(out, "scale-check-lt", "results.csv")) else {}
    print("128 TMs, shipped configs (compact path state, 4 MB stream memory); per-ray figures sampled at a 2% "
          "error target (`experiments/specs/scale-check.json`), rays per session loosely timed "
          "(`scale-check-lt.json`; sampled timing's sessions are not LT's):\n")
    print("| scene | design | frame | rays in flight: mean / steady [rays] | rays / session (LT) | DRAM [B/ray] "
          "| L2 accesses [/ray] | frame [cycles/ray] | vs 1024x1024: DRAM / L2 / cycles |")
    print("|---|---|---|---|---|---|---|---|---|")
    key = lambda r: (r["scene"], design_of(r), int(r["res"].split("x")[0]))
    sampled.sort(key=key)
    full = {(r["scene"], design_of(r)): r for r in sampled if r["res"] == "1024x1024"}
    for r in sampled:
        ref = full.get((r["scene"], design_of(r)))
        rel = []
        for p in ("memory.dram.bytes", "memory.l2.accesses", "frame.cycles"):
            a, b = per_ray(r, p), per_ray(ref, p) if ref else None
            rel.append("-" if a is None or not b else f"{100 * (a / b - 1):+.1f}%")
        ltr = lt.get((r["scene"], design_of(r), r["res"]))

        def pm(path):
            hw = half_width(r, path)
            return f" ±{100 * hw:.1f}%" if hw else ""
        print("| {} | {} | {} | {} / {} | {} | {}{} | {}{} | {}{} | {} |".format(
            r["scene"], design_of(r), r["res"], fmt(col(r, "treelets.rays_in_flight.mean"), 0),
            fmt(col(r, "treelets.rays_in_flight.steady_state"), 0),
            fmt(col(ltr, "treelets.sessions.rays_per_session"), 1) if ltr else "-",
            fmt(per_ray(r, "memory.dram.bytes"), 1), pm("memory.dram.bytes"),
            fmt(per_ray(r, "memory.l2.accesses"), 3), pm("memory.l2.accesses"),
            fmt(per_ray(r, "frame.cycles"), 2), pm("frame.cycles"), " / ".join(rel)))


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ("budget", "scale"):
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "out", "experiments")
    (budget if sys.argv[1] == "budget" else scale)(out)


if __name__ == "__main__":
    main()
