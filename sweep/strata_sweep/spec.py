"""The sweep specification: a JSON file naming a base config, axes, how they combine, the timing
mode and an output folder (README, "Sweeps"). Errors name the file and the field.

An axis value may be an object: a case that sets several parameters at once (each key as if it
were its own axis), for runs whose parameters go together, such as the paper's equal-SRAM
comparison where TRaX varies its L2 and STRaTA its stream memory."""
import itertools
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DESIGNS_DIR = os.path.join(ROOT, "sim", "configs")

# Axes that are strata-sim options; any other axis is a --set path (e.g. "memory.l2.size_bytes").
OPTION_AXES = ("design", "config", "scene", "res", "spp", "seed", "max_path_vertices")
TOP_KEYS = {"base_config", "axes", "combine", "timing_mode", "output", "runs", "fixed", "timeout_seconds",
            "plots", "description"}
MODES = ("lt", "precise", "sampled")


class SpecError(ValueError):
    pass


class Spec:
    def __init__(self, path, data):
        self.path = path
        self.data = data
        where = lambda field: f"{path}: {field}"  # noqa: E731
        unknown = set(data) - TOP_KEYS
        if unknown:
            raise SpecError(where(f"unknown key '{sorted(unknown)[0]}' (known: {', '.join(sorted(TOP_KEYS))})"))
        self.combine = data.get("combine", "product")
        if self.combine not in ("product", "zip"):
            raise SpecError(where(f"combine: '{self.combine}' is not 'product' or 'zip'"))
        self.mode = data.get("timing_mode", "lt")
        if self.mode not in MODES:
            raise SpecError(where(f"timing_mode: '{self.mode}' is not one of {', '.join(MODES)}"))
        out = data.get("output")
        if not isinstance(out, str) or not out:
            raise SpecError(where("output: a folder name is required"))
        base = os.path.dirname(os.path.abspath(path))
        self.output = out if os.path.isabs(out) else os.path.normpath(os.path.join(base, out))
        # Where the run folders live (default: the output folder). Specs that share frames share
        # this folder, so a frame two experiments need runs once.
        store = data.get("runs", out)
        if not isinstance(store, str) or not store:
            raise SpecError(where("runs: a folder name is expected"))
        self.store = store if os.path.isabs(store) else os.path.normpath(os.path.join(base, store))
        self.timeout = data.get("timeout_seconds", 6 * 3600)
        if not isinstance(self.timeout, (int, float)) or self.timeout <= 0:
            raise SpecError(where("timeout_seconds: must be a positive number"))
        self.base_config = data.get("base_config")
        if self.base_config is not None:
            self.base_config = resolve_config(self.base_config, base, where("base_config"))
        axes = data.get("axes", {})
        if not isinstance(axes, dict) or not axes:
            raise SpecError(where("axes: a non-empty object of axis name -> list of values"))
        self.axes = []
        for name, values in axes.items():
            if not isinstance(values, list) or not values:
                raise SpecError(where(f"axes.{name}: must be a non-empty list of values"))
            for i, v in enumerate(values):
                if isinstance(v, dict) and (not v or any(not isinstance(k, str) or not k for k in v)):
                    raise SpecError(where(f"axes.{name}[{i}]: a case object needs one or more parameter names"))
            self.axes.append((name, values))
        if self.combine == "zip" and len({len(v) for _, v in self.axes}) != 1:
            raise SpecError(where("axes: with combine 'zip' every axis needs the same number of values (" +
                                  ", ".join(f"{n}: {len(v)}" for n, v in self.axes) + ")"))
        check_no_repeats(self.axes, self.combine, where)
        names = [n for n, _ in self.axes]
        names += sorted({k for _, vs in self.axes for v in vs if isinstance(v, dict) for k in v})
        if "design" in names and "config" in names:
            raise SpecError(where("axes: give 'design' or 'config', not both"))
        if self.base_config is None and "design" not in names and "config" not in names:
            raise SpecError(where("base_config: required unless a 'design' or 'config' axis is given"))
        if "scene" not in names and "scene" not in data.get("fixed", {}):
            raise SpecError(where("axes.scene: every run needs a scene (an axis, or fixed.scene)"))
        self.fixed = data.get("fixed", {})
        if not isinstance(self.fixed, dict):
            raise SpecError(where("fixed: must be an object"))
        self.base_dir = base
        self.plots = data.get("plots", [])
        check_plots(self.plots, where)

    def runs(self):
        """Every run's parameters, in spec order (duplicates kept; the runner runs them once)."""
        names = [n for n, _ in self.axes]
        value_lists = [v for _, v in self.axes]
        combos = itertools.product(*value_lists) if self.combine == "product" else zip(*value_lists)
        runs = []
        for combo in combos:
            params = {"mode": self.mode, "set": {}}
            for k, v in self.fixed.items():
                if k == "set":
                    params["set"].update(v)
                else:
                    params[k] = v
            if self.base_config:
                params["config"] = self.base_config
            for name, value in zip(names, combo):
                if isinstance(value, dict):  # a case: several parameters at once
                    for key, v in value.items():
                        self._apply(params, key, v, f"axes.{name}.{key}")
                else:
                    self._apply(params, name, value, f"axes.{name}")
            if "timing.mode" in params["set"]:
                raise SpecError(f"{self.path}: set timing.mode through timing_mode, not an axis")
            runs.append(params)
        return runs

    def _apply(self, params, name, value, field):
        if name in ("design", "config"):
            params["config"] = resolve_config(value, self.base_dir, f"{self.path}: {field}")
        elif name in OPTION_AXES:
            params[name] = value
        else:
            params["set"][name] = value


def value_key(value):
    """A value as a run's key sees it (run.run_key is JSON with sorted keys): equal keys are one
    run, so 1 and 1.0 differ, and a case's keys may come in any order."""
    return json.dumps(value, sort_keys=True)


def check_no_repeats(axes, combine, where):
    """A repeated value (with zip: a repeated combination) makes the same run twice, and the
    runner does it once: the sweep would silently have fewer runs than its spec lists."""
    if combine == "product":
        for name, values in axes:
            first = {}
            for i, v in enumerate(values):
                j = first.setdefault(value_key(v), i)
                if j != i:
                    raise SpecError(where(f"axes.{name}: the value {value_key(v)} appears twice (axes.{name}[{j}] "
                                          f"and [{i}]): the same run twice is done once, so list it once"))
    else:
        names = [n for n, _ in axes]
        first = {}
        for i, combo in enumerate(zip(*(v for _, v in axes))):
            j = first.setdefault(value_key(combo), i)
            if j != i:
                raise SpecError(where(f"axes: with combine 'zip', values {j} and {i} repeat one combination (" +
                                      ", ".join(f"{n}={value_key(v)}" for n, v in zip(names, combo)) +
                                      "): the same run twice is done once, so list it once"))


def is_plain_file_name(name):
    """True for a name with no folder in it (the plot is written as <output>/<name>.png)."""
    return (isinstance(name, str) and name not in ("", ".", "..") and "\0" not in name
            and os.path.basename(name) == name and not (os.altsep and os.altsep in name))


def check_plots(plots, where):
    if not isinstance(plots, list):
        raise SpecError(where("plots: must be a list of plot objects"))
    for i, entry in enumerate(plots):
        if not isinstance(entry, dict):
            raise SpecError(where(f"plots[{i}]: must be an object"))
        if "name" not in entry:
            raise SpecError(where(f"plots[{i}].name: required (the PNG's file name)"))
        # Refused here, not when drawing: a name like "../../x" would write outside the output
        # folder, and the runs would have been done before the plot is refused.
        if not is_plain_file_name(entry["name"]):
            raise SpecError(where(f"plots[{i}].name: {json.dumps(entry['name'])} is not a plain file name "
                                  "(no folders, not empty, '.' or '..')"))


def resolve_config(value, base_dir, where):
    """A design name (sim/configs/<name>.json) or a path to a config file, made absolute."""
    if not isinstance(value, str) or not value:
        raise SpecError(f"{where}: expected a design name or a config path")
    candidates = [value if os.path.isabs(value) else os.path.join(base_dir, value),
                  os.path.join(ROOT, value), os.path.join(DESIGNS_DIR, value + ".json")]
    for c in candidates:
        if os.path.isfile(c):
            c = os.path.normpath(os.path.abspath(c))
            # Inside the checkout, relative to it: a run's key must not depend on where it lives.
            return os.path.relpath(c, ROOT) if c.startswith(ROOT + os.sep) else c
    raise SpecError(f"{where}: '{value}' is neither a design in sim/configs nor a config file")


def load(path):
    try:
        with open(path) as f:
            data = json.load(f)
    except OSError as e:
        raise SpecError(f"{path}: cannot read: {e.strerror}")
    except json.JSONDecodeError as e:
        raise SpecError(f"{path}: not valid JSON: {e}")
    if not isinstance(data, dict):
        raise SpecError(f"{path}: the spec must be a JSON object")
    return Spec(path, data)
