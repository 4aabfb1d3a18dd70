#!/usr/bin/python3
"""Tests of strata-sweep (sweep/strata_sweep) with a stand-in for strata-sim: a script that
writes a stats.json, fails, hangs or writes half a file, as the scene name says. The real
Slurm cluster test is test_slurm_cluster.py. Run by CTest (Sweep.Runner) or directly."""
import csv
import json
import os
import stat
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from strata_sweep import cli, run as run_mod, slurm, spec as spec_mod  # noqa: E402

FAKE_SIM = textwrap.dedent("""\
    #!/usr/bin/python3
    import json, os, sys, time
    a = sys.argv
    out = a[a.index("--out") + 1]
    scene = a[a.index("--scene") + 1]
    with open(os.path.join(os.path.dirname(__file__), "calls.log"), "a") as f:
        f.write(" ".join(a[1:]) + "\\n")
    if scene == "broken":
        print("strata-sim: error: scene broken: no triangles", file=sys.stderr)
        sys.exit(1)
    if scene == "hang":
        time.sleep(60)
    os.makedirs(out, exist_ok=True)
    if scene == "cut":
        open(os.path.join(out, "stats.json"), "w").write('{"frame": {"cyc')
        sys.exit(0)
    if scene == "flaky" and not os.path.exists(os.path.join(os.path.dirname(__file__), "flaky.ok")):
        sys.exit(-9 % 256)
    sets = [a[i + 1] for i in range(len(a)) if a[i] == "--set"]
    stats = {"frame": {"cycles": 1000 + len(" ".join(sets)), "frames_per_second": 5.0},
             "memory": {"dram": {"bytes": 64 * len(sets)}},
             "simulation": {"kernel": {"elf": "k.elf", "image_digest": "00ff"}},
             "units": {"frame.cycles": "cycles", "frame.frames_per_second": "1/s", "memory.dram.bytes": "bytes"}}
    json.dump(stats, open(os.path.join(out, "stats.json"), "w"))
""")


class Fixture(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.sim = os.path.join(self.dir, "strata-sim")
        with open(self.sim, "w") as f:
            f.write(FAKE_SIM)
        os.chmod(self.sim, os.stat(self.sim).st_mode | stat.S_IEXEC)

    def tearDown(self):
        self.tmp.cleanup()

    def write_spec(self, name="spec.json", **fields):
        data = {"axes": {"design": ["trax"], "scene": ["a", "b"], "memory.l2.size_bytes": [524288, 1048576]},
                "timing_mode": "lt", "output": "out"}
        data.update(fields)
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            json.dump(data, f)
        return path

    def sweep(self, spec, *extra):
        return cli.main([spec, "--sim", self.sim, "--jobs", "2", *extra])

    def calls(self):
        p = os.path.join(self.dir, "calls.log")
        return open(p).read().splitlines() if os.path.exists(p) else []

    def rows(self):
        with open(os.path.join(self.dir, "out", "results.csv")) as f:
            return list(csv.DictReader(f))


class SpecTest(Fixture):
    def test_product_and_zip(self):
        s = spec_mod.load(self.write_spec())
        self.assertEqual(len(s.runs()), 4)
        z = spec_mod.load(self.write_spec(combine="zip", axes={"design": ["trax", "strata-streams"],
                                                                 "scene": ["a", "b"]}))
        runs = z.runs()
        self.assertEqual([(os.path.basename(r["config"]), r["scene"]) for r in runs],
                         [("trax.json", "a"), ("strata-streams.json", "b")])

    def test_errors_name_the_file_and_field(self):
        cases = [({"combine": "cross"}, "combine: 'cross'"),
                 ({"timing_mode": "fast"}, "timing_mode: 'fast'"),
                 ({"output": ""}, "output:"),
                 ({"axes": {"design": ["nope"], "scene": ["a"]}}, "axes.design: 'nope'"),
                 ({"axes": {"design": ["trax"], "scene": []}}, "axes.scene: must be a non-empty list"),
                 ({"axes": {"design": ["trax"]}}, "axes.scene: every run needs a scene"),
                 ({"combine": "zip", "axes": {"design": ["trax"], "scene": ["a", "b"]}}, "same number of values"),
                 ({"colour": 1}, "unknown key 'colour'")]
        for fields, expected in cases:
            with self.subTest(expected=expected):
                with self.assertRaises(spec_mod.SpecError) as e:
                    spec_mod.load(self.write_spec(**fields)).runs()
                self.assertIn("spec.json: ", str(e.exception))
                self.assertIn(expected, str(e.exception))

    def test_bad_spec_exits_2(self):
        with open(os.path.join(self.dir, "bad.json"), "w") as f:
            f.write("{")
        self.assertEqual(cli.main([os.path.join(self.dir, "bad.json"), "--sim", self.sim]), 2)

    def test_keys_are_stable_and_follow_the_config_content(self):
        s = spec_mod.load(self.write_spec())
        a = [run_mod.run_key(run_mod.with_digest(p)) for p in s.runs()]
        b = [run_mod.run_key(run_mod.with_digest(p)) for p in spec_mod.load(self.write_spec()).runs()]
        self.assertEqual(a, b)
        self.assertEqual(len(set(a)), 4)
        cfg = os.path.join(self.dir, "mine.json")
        with open(cfg, "w") as f:
            f.write('{"tms": 4}')
        p = {"config": cfg, "scene": "a"}
        before = run_mod.run_key(run_mod.with_digest(p))
        with open(cfg, "w") as f:
            f.write('{"tms": 8}')
        self.assertNotEqual(before, run_mod.run_key(run_mod.with_digest(p)))


    def test_a_case_sets_several_parameters_at_once(self):
        cases = [{"design": "trax", "memory.l2.size_bytes": 1 << 20},
                 {"design": "strata-streams", "memory.stream.size_bytes": 2 << 20, "seed": 3}]
        runs = spec_mod.load(self.write_spec(axes={"scene": ["a", "b"], "sram": cases})).runs()
        self.assertEqual(len(runs), 4)
        self.assertEqual([(os.path.basename(r["config"]), r["scene"], r["set"], r.get("seed")) for r in runs],
                         [("trax.json", "a", {"memory.l2.size_bytes": 1 << 20}, None),
                          ("strata-streams.json", "a", {"memory.stream.size_bytes": 2 << 20}, 3),
                          ("trax.json", "b", {"memory.l2.size_bytes": 1 << 20}, None),
                          ("strata-streams.json", "b", {"memory.stream.size_bytes": 2 << 20}, 3)])
        for bad, expected in (([{}], "axes.sram[0]: a case object"),
                              ([{"design": "nope"}], "axes.sram.design: 'nope'")):
            with self.subTest(expected=expected):
                with self.assertRaises(spec_mod.SpecError) as e:
                    spec_mod.load(self.write_spec(axes={"scene": ["a"], "sram": bad})).runs()
                self.assertIn(expected, str(e.exception))

    def test_a_plot_name_must_be_a_plain_file_name(self):
        # The PNG is <output>/<name>.png: a name with a folder in it would write elsewhere.
        for name in ("../../x", "sub/x", "/tmp/x", ".", "..", "", 7, "a\0b"):
            with self.subTest(name=name):
                with self.assertRaises(spec_mod.SpecError) as e:
                    spec_mod.load(self.write_spec(plots=[{"name": "ok", "x": "scene", "y": "frame.cycles"},
                                                         {"name": name, "x": "scene", "y": "frame.cycles"}]))
                self.assertIn("spec.json: plots[1].name", str(e.exception))
        with self.assertRaises(spec_mod.SpecError) as e:
            spec_mod.load(self.write_spec(plots=[{"x": "scene", "y": "frame.cycles"}]))
        self.assertIn("plots[0].name", str(e.exception))
        # Through the command: a spec error (exit 2) before anything runs or is written.
        spec = self.write_spec(plots=[{"name": "../escaped", "x": "scene", "y": "frame.cycles"}])
        self.assertEqual(self.sweep(spec), 2)
        self.assertEqual(self.calls(), [])
        self.assertFalse(os.path.exists(os.path.join(self.dir, "escaped.png")))

    def test_a_value_repeated_on_an_axis_is_refused(self):
        # A repeated value makes the same run twice, which the runner does once: the sweep would
        # silently have fewer runs than the spec seems to ask for.
        cases = [({"design": ["trax"], "scene": ["a"], "seed": [1, 2, 1]}, "axes.seed: the value 1"),
                 ({"design": ["trax"], "scene": ["a", "b", "a"]}, "axes.scene: the value \"a\""),
                 ({"scene": ["a"], "sram": [{"design": "trax", "seed": 1}, {"seed": 1, "design": "trax"}]},
                  "axes.sram: the value {\"design\": \"trax\", \"seed\": 1}")]
        for axes, expected in cases:
            with self.subTest(expected=expected):
                with self.assertRaises(spec_mod.SpecError) as e:
                    spec_mod.load(self.write_spec(axes=axes)).runs()
                self.assertIn("spec.json: ", str(e.exception))
                self.assertIn(expected, str(e.exception))
                self.assertIn("appears twice", str(e.exception))
        # Values equal to Python but not as parameters are different runs (1 and 1.0 are two keys).
        self.assertEqual(len(spec_mod.load(self.write_spec(axes={"design": ["trax"], "scene": ["a"],
                                                                 "x.y": [1, 1.0, True]})).runs()), 3)
        # With zip, a value may repeat on an axis; a whole repeated combination may not.
        zipped = {"design": ["trax", "trax"], "scene": ["a", "b"]}
        self.assertEqual(len(spec_mod.load(self.write_spec(combine="zip", axes=zipped)).runs()), 2)
        with self.assertRaises(spec_mod.SpecError) as e:
            spec_mod.load(self.write_spec(combine="zip", axes={"design": ["trax", "trax"], "scene": ["a", "a"]}))
        self.assertIn("axes: with combine 'zip', values 0 and 1", str(e.exception))
        # Through the command: a spec error (exit 2), nothing run.
        self.assertEqual(self.sweep(self.write_spec(axes={"design": ["trax"], "scene": ["a"], "seed": [1, 1]})), 2)
        self.assertEqual(self.calls(), [])


class LocalTest(Fixture):
    def test_runs_writes_results_with_units_and_resumes(self):
        spec = self.write_spec(plots=[{"name": "fps", "x": "set memory.l2.size_bytes", "y": "frame.frames_per_second",
                                       "series": ["scene"], "log_x": True}])
        self.assertEqual(self.sweep(spec), 0)
        self.assertEqual(len(self.calls()), 4)
        rows = self.rows()
        self.assertEqual(len(rows), 4)
        self.assertIn("frame.cycles [cycles]", rows[0])
        self.assertIn("memory.dram.bytes [bytes]", rows[0])
        self.assertEqual({r["status"] for r in rows}, {"done"})
        self.assertEqual({r["kernel"] for r in rows}, {"k.elf 00ff"})
        for r in rows:
            folder = os.path.join(self.dir, "out", "runs", r["run"])
            with open(os.path.join(folder, "params.json")) as f:
                self.assertEqual(run_mod.run_key(json.load(f)), r["run"])
        self.assertTrue(os.path.getsize(os.path.join(self.dir, "out", "fps.png")) > 1000)
        with open(os.path.join(self.dir, "out", "results.json")) as f:
            self.assertEqual(len(json.load(f)), 4)
        # Resumed: nothing runs again, and nothing is counted twice.
        self.assertEqual(self.sweep(spec), 0)
        self.assertEqual(len(self.calls()), 4)
        self.assertEqual(len(self.rows()), 4)

    def test_specs_sharing_a_run_folder_run_a_common_frame_once(self):
        one = self.write_spec("one.json", output="one", runs="store",
                              axes={"design": ["trax"], "scene": ["a", "b"]})
        two = self.write_spec("two.json", output="two", runs="store",
                              axes={"design": ["trax"], "scene": ["b", "c"]},
                              plots=[{"name": "p", "x": "scene", "y": ["frame.cycles", "memory.dram.bytes"],
                                      "panels": "config", "log_y": True}])
        self.assertEqual(self.sweep(one), 0)
        self.assertEqual(self.sweep(two), 0)
        self.assertEqual(sorted(c.split("--scene ")[1].split()[0] for c in self.calls()), ["a", "b", "c"])
        for name, scenes in (("one", ["a", "b"]), ("two", ["b", "c"])):
            with open(os.path.join(self.dir, name, "results.csv")) as f:
                rows = list(csv.DictReader(f))
            self.assertEqual([r["scene"] for r in rows], scenes)
            self.assertEqual({r["simulator"] for r in rows}, {run_mod.simulator_digest(self.sim)})
        self.assertFalse(os.path.exists(os.path.join(self.dir, "two", "runs")))
        self.assertTrue(os.path.getsize(os.path.join(self.dir, "two", "p.png")) > 1000)

    def test_a_plot_takes_its_x_from_the_first_column_a_row_has(self):
        from strata_sweep import plot
        rows = [{"status": "done", "set a": 1, "y [s]": 2.0, "config": "x"},
                {"status": "done", "set b": 4, "y [s]": 3.0, "config": "z"}]
        self.assertTrue(os.path.getsize(plot.draw({"name": "xy", "x": ["set a", "set b"], "y": "y", "series": ["config"]},
                                                  rows, self.dir)) > 1000)
        with self.assertRaises(plot.PlotError) as e:
            plot.draw({"name": "none", "x": "set a", "y": "missing"}, rows, self.dir)
        self.assertIn("no column 'missing'", str(e.exception))

    def test_the_command_carries_mode_and_sets(self):
        self.assertEqual(self.sweep(self.write_spec(timing_mode="precise")), 0)
        call = self.calls()[0]
        self.assertIn("--set timing.mode=precise", call)
        self.assertIn("--set memory.l2.size_bytes=", call)
        self.assertIn("sim/configs/trax.json", call)

    def test_failures_are_recorded_and_the_others_go_on(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["a", "broken", "cut", "b"]})
        self.assertEqual(self.sweep(spec), 1)
        rows = {r["scene"]: r for r in self.rows()}
        self.assertEqual(rows["a"]["status"], "done")
        self.assertEqual(rows["b"]["status"], "done")
        self.assertEqual(rows["broken"]["status"], "failed")
        self.assertIn("exited with 1", rows["broken"]["error"])
        self.assertIn("no triangles", rows["broken"]["error"])
        self.assertIn("cut off", rows["cut"]["error"])
        # A failed run has no done marker: the next invocation tries it again, and only it.
        n = len(self.calls())
        self.assertEqual(self.sweep(spec), 1)
        self.assertEqual(len(self.calls()) - n, 2)

    def test_a_timeout_is_a_failure_with_its_reason(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["hang", "a"]}, timeout_seconds=1)
        self.assertEqual(self.sweep(spec), 1)
        rows = {r["scene"]: r for r in self.rows()}
        self.assertIn("timed out after 1 s", rows["hang"]["error"])
        self.assertEqual(rows["a"]["status"], "done")

    def test_a_crashed_run_is_retried_and_then_counted_once(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["flaky", "a"]})
        self.assertEqual(self.sweep(spec), 1)
        open(os.path.join(self.dir, "flaky.ok"), "w").close()
        self.assertEqual(self.sweep(spec), 0)
        self.assertEqual([r["status"] for r in self.rows()], ["done", "done"])

    def finished_folders(self):
        runs = os.path.join(self.dir, "out", "runs")
        return [os.path.join(runs, r) for r in sorted(os.listdir(runs))]

    def test_a_cut_off_done_marker_names_the_file_and_the_run_runs_again(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["a", "b"]})
        self.assertEqual(self.sweep(spec), 0)
        cut = self.finished_folders()[0]
        with open(os.path.join(cut, "done.json"), "w") as f:
            f.write('{"wall_sec')
        # --collect runs nothing: the run is failed, with the file named, and no traceback.
        self.assertEqual(self.sweep(spec, "--collect"), 1)
        failed = [r for r in self.rows() if r["status"] == "failed"]
        self.assertEqual(len(failed), 1)
        self.assertIn(os.path.join(cut, "done.json"), failed[0]["error"])
        # The next sweep runs it again, once.
        self.assertEqual(self.sweep(spec), 0)
        self.assertEqual(len(self.calls()), 3)
        self.assertEqual([r["status"] for r in self.rows()], ["done", "done"])
        for empty in ("", "[]"):  # empty, or JSON that is not a record
            with open(os.path.join(cut, "done.json"), "w") as f:
                f.write(empty)
            self.assertFalse(run_mod.is_done(cut))

    def test_a_done_run_whose_stats_became_unreadable_runs_again(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["a", "b"]})
        self.assertEqual(self.sweep(spec), 0)
        broken = self.finished_folders()[1]
        with open(os.path.join(broken, "out", "stats.json"), "w") as f:
            f.write('{"frame": {')
        self.assertEqual(self.sweep(spec, "--collect"), 1)
        self.assertIn("stats.json", [r for r in self.rows() if r["status"] == "failed"][0]["error"])
        self.assertEqual(self.sweep(spec), 0)
        self.assertEqual(len(self.calls()), 3)
        self.assertEqual([r["status"] for r in self.rows()], ["done", "done"])

    def test_an_output_that_is_a_file_is_an_argument_error(self):
        blocker = os.path.join(self.dir, "blocker")
        open(blocker, "w").close()
        for field in ("output", "runs"):
            spec = self.write_spec(name=f"{field}.json", **{field: "blocker/out"})
            self.assertEqual(self.sweep(spec), 2, field)
        self.assertEqual(self.calls(), [])
        # A read-only output folder, where permissions apply (root bypasses them).
        if os.geteuid() != 0:
            ro = os.path.join(self.dir, "ro")
            os.makedirs(ro)
            os.chmod(ro, 0o555)
            self.assertEqual(self.sweep(self.write_spec(name="ro.json", output="ro")), 2)

    def test_ctrl_c_keeps_finished_runs(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["a", "hang"]})
        env = dict(os.environ, PYTHONPATH=HERE)
        p = subprocess.Popen([sys.executable, "-m", "strata_sweep", spec, "--sim", self.sim, "--jobs", "2"],
                             env=env, stderr=subprocess.PIPE, text=True, start_new_session=True)
        # Wait until the good run is done, then Ctrl-C the whole group as a terminal would.
        import time
        for _ in range(200):
            if any(run_mod.is_done(os.path.join(self.dir, "out", "runs", d))
                   for d in os.listdir(os.path.join(self.dir, "out", "runs"))
                   if os.path.isdir(os.path.join(self.dir, "out", "runs", d))) if os.path.isdir(
                    os.path.join(self.dir, "out", "runs")) else False:
                break
            time.sleep(0.05)
        os.killpg(p.pid, 2)
        _, err = p.communicate(timeout=30)
        self.assertEqual(p.returncode, 130, err)
        self.assertIn("interrupted", err)
        statuses = {r["scene"]: r["status"] for r in self.rows()}
        self.assertEqual(statuses["a"], "done")
        self.assertNotEqual(statuses["hang"], "done")


class FaultTest(Fixture):
    def sweep_process(self, spec):
        env = dict(os.environ, PYTHONPATH=HERE)
        return subprocess.Popen([sys.executable, "-m", "strata_sweep", spec, "--sim", self.sim, "--jobs", "2"],
                                env=env, stderr=subprocess.DEVNULL, start_new_session=True)

    def test_two_sweeps_on_one_output_folder_run_each_frame_once(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["a", "b", "c", "d", "e", "f"]})
        first, second = self.sweep_process(spec), self.sweep_process(spec)
        self.assertEqual(first.wait(timeout=120), 0)
        self.assertEqual(second.wait(timeout=120), 0)
        self.assertEqual(len(self.calls()), 6)  # each frame simulated exactly once
        self.assertEqual([r["status"] for r in self.rows()], ["done"] * 6)

    def test_a_sweep_killed_half_way_resumes_and_counts_each_run_once(self):
        spec = self.write_spec(axes={"design": ["trax"], "scene": ["a", "hang", "b"]})
        p = self.sweep_process(spec)
        import time
        runs = os.path.join(self.dir, "out", "runs")
        for _ in range(400):  # until two runs are done and "hang" is in flight
            if os.path.isdir(runs) and sum(run_mod.is_done(os.path.join(runs, d)) for d in os.listdir(runs)) >= 2:
                break
            time.sleep(0.05)
        os.killpg(p.pid, 9)  # no clean-up at all: the machine went away
        p.wait()
        n = len(self.calls())
        with open(self.sim) as f:
            text = f.read()
        with open(self.sim, "w") as f:  # the frame that was killed now finishes
            f.write(text.replace('if scene == "hang":', 'if scene == "never":'))
        self.assertEqual(self.sweep(spec), 0)
        self.assertEqual(len(self.calls()) - n, 1)  # only the killed run ran again
        self.assertEqual([r["status"] for r in self.rows()], ["done"] * 3)


class SlurmScriptTest(Fixture):
    def test_dry_run_writes_an_array_over_the_pending_runs_only(self):
        spec = self.write_spec()
        self.assertEqual(self.sweep(self.write_spec("one.json", axes={"design": ["trax"], "scene": ["a"],
                                                                      "memory.l2.size_bytes": [524288]})), 0)
        rc = cli.main([spec, "--sim", self.sim, "--backend", "slurm", "--dry-run", "--partition", "fast",
                       "--time", "01:00:00", "--mem", "2G", "--max-running", "3"])
        self.assertEqual(rc, 0)
        d = os.path.join(self.dir, "out", "slurm")
        script = [f for f in os.listdir(d) if f.startswith("job-")][0]
        text = open(os.path.join(d, script)).read()
        self.assertIn("#SBATCH --array=0-2%3", text)  # 4 runs, one already done
        self.assertIn("#SBATCH --partition=fast", text)
        self.assertIn("#SBATCH --time=01:00:00", text)
        self.assertIn("#SBATCH --mem=2G", text)
        self.assertIn("-m strata_sweep.task", text)
        batch = [f for f in os.listdir(d) if f.startswith("batch-")][0]
        with open(os.path.join(d, batch)) as f:
            self.assertEqual(len(json.load(f)["runs"]), 3)

    def test_a_task_runs_its_entry_and_never_a_finished_one_twice(self):
        from strata_sweep import task
        runs = [run_mod.with_digest(p) for p in spec_mod.load(self.write_spec()).runs()]
        root = os.path.join(self.dir, "out")
        batch = os.path.join(self.dir, "batch.json")
        with open(batch, "w") as f:
            json.dump({"runs": runs, "timeout_seconds": 60, "sim": self.sim}, f)
        self.assertEqual(task.main(["task", root, batch, "1"]), 0)
        self.assertTrue(run_mod.is_done(run_mod.folder_of(root, runs[1])))
        self.assertEqual(task.main(["task", root, batch, "1"]), 0)
        self.assertEqual(len(self.calls()), 1)

    def test_missing_sbatch_is_a_clear_error(self):
        env_path = os.environ.get("PATH", "")
        os.environ["PATH"] = self.dir
        try:
            with self.assertRaises(slurm.SlurmError) as e:
                slurm.submit(os.path.join(self.dir, "x.sh"))
            self.assertIn("sbatch not found", str(e.exception))
        finally:
            os.environ["PATH"] = env_path


if __name__ == "__main__":
    unittest.main()
