#!/usr/bin/python3
"""The banked DRAM's loaded latency, from bench_dram's CSV.

    experiments/plot_dram_latency.py [out/bench/dram.csv] [docs/memory-system/dram-loaded-latency.png]

Plots the mean read latency (request to last data, cycles of the 1 GHz chip clock) against the
bandwidth achieved (share of the peak), one line per address pattern, with the random reads'
saturation derived from the timing preset marked (bench_dram prints it). scripts/bench dram
writes the CSV. Needs python3-matplotlib (scripts/install-deps installs it)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "out", "bench", "dram.csv")
    dst = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs", "memory-system", "dram-loaded-latency.png")
    try:
        with open(src, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"plot_dram_latency: {src}: {e.strerror} (run scripts/bench dram first)")
    if not rows:
        sys.exit(f"plot_dram_latency: {src}: no rows")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for pattern, style in (("sequential", "o-"), ("random", "s-")):
        pts = [r for r in rows if r["pattern"] == pattern]
        # Offered loads past saturation pile onto the same bandwidth: keep the points up to the
        # first that fell short of its offer (the knee) and that one.
        shown = []
        for r in pts:
            shown.append(r)
            if float(r["achieved_bytes_per_cycle"]) < 0.98 * float(r["offered_bytes_per_cycle"]):
                break
        x = [100 * float(r["achieved_bytes_per_cycle"]) / float(r["peak_bytes_per_cycle"]) for r in shown]
        y = [float(r["mean_latency_cycles"]) for r in shown]
        ax.plot(x, y, style, label=f"{pattern} 64 B reads", markersize=4)
    bound = 100 * float(rows[0]["derived_random_efficiency"])
    ax.axvline(bound, color="grey", linestyle=":", label=f"random: bound from tRRD, tFAW, tRC, refresh ({bound:.1f}%)")
    ax.set_xlabel("bandwidth achieved (% of the 256 GB/s peak)")
    ax.set_ylabel("mean read latency (cycles at 1 GHz = ns)")
    ax.set_title("Banked DRAM (GDDR5 preset), 8 channels, at most 512 reads in flight", fontsize=9)
    ax.set_xlim(0, 100)
    ax.set_ylim(0, None)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    fig.savefig(dst, dpi=120)
    print(f"wrote {dst}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
