#!/usr/bin/env python3
"""The tables of issues 34 (the ray budget) and 35 (the paper's scale) from the sweeps'
results, as Markdown:

  experiments/ray_budget_tables.py budget [OUT]    ray-budget: stream memory size x path state
  experiments/ray_budget_tables.py scale [OUT]     scale-check (sampled) and scale-check-lt
  experiments/ray_budget_tables.py headline [OUT]  headline-1024: Sibenik 1024x1024, every design
                                                   and path state (the frames finished so far)

OUT is the experiments folder (default out/experiments). Each table names its timing mode; a
sampled figure carries its 95% half-width where the run reported one. Standard library only.
"""
import csv
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
    """A sampled run's 95% relative half-width of `path` (results.csv's intervals columns), or
    None (an exact figure, or another timing mode)."""
    return col(row, "intervals.stats." + path + ".relative")


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


def headline(out):
    table = [r for r in rows(out, "headline-1024") if r.get("status", "done") == "done" and col(r, "frame.cycles")]
    print("Sibenik 1024x1024, 128 TMs, shipped configs, sampled timing at a 2% error target on frame cycles, "
          "DRAM bytes and L2 accesses (`experiments/specs/headline-1024.json`); each estimate with its 95% "
          "half-width. Rays per session are the sampled run's own (its fast-forward's sessions; "
          "docs/sampled-timing.md, \"Treelet sessions\").\n")
    print("| design | path state | frame [M cycles] | DRAM [MB] | L2 accesses [M] | stream accesses [M] "
          "| rays in flight: mean / steady | rays / session | energy [mJ] | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    order = {"trax": 0, "strata-streams": 1, "strata-pipelines": 2}
    states = {"compact": 0, "on-chip": 1, "dram": 2}
    table.sort(key=lambda r: (order.get(design_of(r), 9), states.get(param(r, "design.path_state"), 9)))

    def est(r, path, digits, scale):
        v, hw = col(r, path), half_width(r, path)
        return fmt(v, digits, scale) + ("" if not hw else " ±<0.1%" if hw < 0.0005 else f" ±{100 * hw:.1f}%")
    for r in table:
        streams = design_of(r) != "trax"
        print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |".format(
            design_of(r), param(r, "design.path_state") or "-", est(r, "frame.cycles", 3, 1e-6),
            est(r, "memory.dram.bytes", 1, 1e-6), est(r, "memory.l2.accesses", 2, 1e-6),
            est(r, "memory.stream.accesses", 2, 1e-6) if streams else "-",
            (fmt(col(r, "treelets.rays_in_flight.mean"), 0) + " / " +
             fmt(col(r, "treelets.rays_in_flight.steady_state"), 0)) if streams else "-",
            est(r, "treelets.sessions.rays_per_session", 1, 1.0) if streams else "-",
            est(r, "energy_nj.total", 1, 1e-6), fmt(col(r, "simulator wall"), 0)))


TABLES = {"budget": budget, "scale": scale, "headline": headline}


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in TABLES:
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "out", "experiments")
    TABLES[sys.argv[1]](out)


if __name__ == "__main__":
    main()
