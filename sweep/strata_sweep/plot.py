"""Plots from the spec's "plots" entries: {"name", "x", "y", "series" (columns, optional),
"log_x", "log_y" (optional)}, each drawn from the finished rows as a PNG with matplotlib.
Columns are named as in results.csv; a y name without its unit matches the column with it."""
import os


class PlotError(ValueError):
    pass


def column(rows, name, what):
    cols = {k for r in rows for k in r}
    if name in cols:
        return name
    matches = sorted(c for c in cols if c.split(" [")[0] == name)
    if len(matches) == 1:
        return matches[0]
    raise PlotError(f"plot {what}: no column '{name}'" + (f" (ambiguous: {', '.join(matches)})" if matches else ""))


def draw(entry, rows, root):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for field in ("name", "x", "y"):
        if field not in entry:
            raise PlotError(f"plot entry {entry}: '{field}' is required")
    done = [r for r in rows if r.get("status") == "done"]
    if not done:
        raise PlotError(f"plot {entry['name']}: no finished runs to draw")
    x = column(done, entry["x"], entry["name"] + ": x")
    y = column(done, entry["y"], entry["name"] + ": y")
    series_cols = [column(done, s, entry["name"] + ": series") for s in entry.get("series", [])]
    groups = {}
    for r in done:
        label = ", ".join(f"{s.removeprefix('set ')}={os.path.basename(str(r[s])).removesuffix('.json')}"
                          for s in series_cols) or y
        groups.setdefault(label, []).append((r[x], r[y]))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for label, points in sorted(groups.items()):
        points.sort(key=lambda p: (isinstance(p[0], str), p[0]))
        ax.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=label)
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    if entry.get("log_x"):
        ax.set_xscale("log", base=2)
    if entry.get("log_y"):
        ax.set_yscale("log")
    mode = sorted({str(r.get("mode")) for r in done})
    ax.set_title(f"{entry['name']} [{', '.join(mode)}]")
    ax.grid(True, alpha=0.3)
    if len(groups) > 1:
        ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(root, entry["name"] + ".png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
