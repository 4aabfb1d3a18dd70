"""results.csv and results.json: one row per run, its parameters first, then every statistic
of its stats.json flattened to "dotted.path [unit]" (units from stats.json's own map)."""
import csv
import json
import os

from . import run as run_mod


def flatten(stats, prefix=""):
    units = stats.get("units", {})
    out = {}

    def walk(node, path):
        if isinstance(node, dict):
            for k, v in node.items():
                if k in ("config", "units") and not path:
                    continue
                walk(v, f"{path}.{k}" if path else k)
        elif isinstance(node, (int, float)) and not isinstance(node, bool):
            unit = units.get(path)
            out[f"{prefix}{path}" + (f" [{unit}]" if unit else "")] = node

    walk(stats, "")
    return out


def param_columns(params):
    cols = {"run": run_mod.run_key(params)}
    for k, v in params.items():
        if k == "set":
            for path, value in sorted(v.items()):
                cols[f"set {path}"] = value
        elif k != "config_sha256":
            cols[k] = v
    return cols


def collect(runs, root):
    """Rows for every run (in order, each once), with status done, failed or pending."""
    rows, seen = [], set()
    for params in runs:
        key = run_mod.run_key(params)
        if key in seen:
            continue
        seen.add(key)
        stats, done, error = run_mod.load_result(root, params)
        row = param_columns(params)
        row["status"] = "done" if stats is not None else ("failed" if error else "pending")
        row["error"] = error or ""
        if stats is not None:
            row["simulator wall [s]"] = done.get("wall_seconds")
            row["simulator"] = done.get("simulator_sha256", "")
            # The kernel image that ran (absent from runs made before 2026-12-07): frames are
            # comparable only under the same one, as a kernel's code layout moves its timing.
            kernel = stats.get("simulation", {}).get("kernel") or {}
            row["kernel"] = f"{kernel['elf']} {kernel['image_digest']}" if "image_digest" in kernel else ""
            row.update(flatten(stats))
        rows.append(row)
    return rows


def write(rows, root):
    columns = []
    for r in rows:
        for k in r:
            if k not in columns:
                columns.append(k)
    csv_path, json_path = os.path.join(root, "results.csv"), os.path.join(root, "results.json")
    tmp = f"{csv_path}.tmp.{os.getpid()}"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        for r in rows:
            w.writerow({k: json.dumps(v) if isinstance(v, (dict, list)) else v for k, v in r.items()})
    os.replace(tmp, csv_path)
    run_mod.write_json_atomically(json_path, rows)
    return csv_path, json_path
