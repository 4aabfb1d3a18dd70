"""Plots from the spec's "plots" entries, each drawn from the finished rows as a PNG with matplotlib:
    name     the PNG's name: a plain file name, no folders (spec.check_plots refuses others)
    x        a column, or a list of columns: a row's x is the first of them it has (for cases
             that vary different parameters, e.g. TRaX's L2 size and STRaTA's stream size)
    y        a column, or a list of columns: one line per column and series
    series   columns whose values tell the lines apart (optional)
    panels   a column: one panel per value, side by side (optional)
    log_x, log_y, title (optional)
Columns are named as in results.csv; a name without its unit matches the column with it."""
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


def unit_of(col):
    """"[bytes]" of "memory.dram.bytes [bytes]": the label of an axis that carries several columns."""
    return "[" + col.split(" [", 1)[1] if " [" in col else ""


def as_list(v):
    return v if isinstance(v, list) else [v]


def short(value):
    return os.path.basename(str(value)).removesuffix(".json")


def draw(entry, rows, root):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for field in ("name", "x", "y"):
        if field not in entry:
            raise PlotError(f"plot entry {entry}: '{field}' is required")
    name = entry["name"]
    done = [r for r in rows if r.get("status") == "done"]
    if not done:
        raise PlotError(f"plot {name}: no finished runs to draw")
    xs = [column(done, c, name + ": x") for c in as_list(entry["x"])]
    ys = [column(done, c, name + ": y") for c in as_list(entry["y"])]
    series_cols = [column(done, s, name + ": series") for s in entry.get("series", [])]
    panel_col = column(done, entry["panels"], name + ": panels") if entry.get("panels") else None
    panels = {}
    for r in done:
        x = next((r[c] for c in xs if r.get(c) not in (None, "")), None)
        if x is None:
            continue
        lines = panels.setdefault(short(r[panel_col]) if panel_col else "", {})
        for y in ys:
            label = ", ".join(f"{s.removeprefix('set ')}={short(r[s])}" for s in series_cols)
            if len(ys) > 1 or not label:
                label = f"{label}: {y.split(' [')[0]}" if label else y.split(" [")[0]
            if entry.get("log_y") and not r[y] > 0:
                continue  # a zero has no place on a log axis (e.g. TRaX's stream accesses)
            lines.setdefault(label, []).append((x, r[y]))
    if not panels:
        raise PlotError(f"plot {name}: no finished run has any of the x columns {xs}")
    fig, axes = plt.subplots(1, len(panels), figsize=(max(6.4, 4.8 * len(panels)), 4.2), squeeze=False)
    for ax, (panel, lines) in zip(axes[0], sorted(panels.items())):
        for label, points in sorted(lines.items()):
            points.sort(key=lambda p: (isinstance(p[0], str), p[0]))
            ax.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=label)
        ax.set_xlabel(" or ".join(x.removeprefix("set ") for x in xs))
        ax.set_ylabel(ys[0] if len(ys) == 1 else unit_of(ys[0]))
        if entry.get("log_x"):
            ax.set_xscale("log", base=2)
        if entry.get("log_y"):
            ax.set_yscale("log")
        if panel:
            ax.set_title(f"{panel_col.removeprefix('set ')}={panel}", fontsize=9)
        ax.grid(True, alpha=0.3, which="both")
        if len(lines) > 1:
            ax.legend(fontsize=7)
    mode = sorted({str(r.get("mode")) for r in done})
    fig.suptitle(f"{entry.get('title', name)} [{', '.join(mode)}]")
    fig.tight_layout()
    path = os.path.join(root, name + ".png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
