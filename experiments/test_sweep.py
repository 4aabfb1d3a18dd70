#!/usr/bin/python3
"""Tests of the experiment runner (experiments/sweep.py), with a stand-in for strata-sim: a
small script that writes a stats.json, fails, or dies, as each test needs. Run by CTest
(Experiments.Sweep) or directly: python3 experiments/test_sweep.py"""
import json
import os
import stat
import sys
import tempfile
import textwrap
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sweep  # noqa: E402

FAKE_SIM = textwrap.dedent("""\
    #!/usr/bin/python3
    # Stand-in for strata-sim run: --out DIR; the scene name says what to do.
    import json, os, sys
    a = sys.argv
    out = a[a.index("--out") + 1]
    scene = a[a.index("--scene") + 1]
    with open(os.path.join(os.path.dirname(__file__), "calls.log"), "a") as f:
        f.write(scene + "\\n")
    if scene == "broken":
        print("strata-sim: error: scene broken: no triangles", file=sys.stderr)
        sys.exit(1)
    os.makedirs(out, exist_ok=True)
    if scene == "cut":
        open(os.path.join(out, "stats.json"), "w").write('{"frame": {"cyc')
        sys.exit(0)
    stats = {"frame": {"cycles": 1000 + len(a)}, "memory": {"dram": {"bytes": 64}},
             "design": {"name": "x"}, "units": {"frame.cycles": "cycles", "memory.dram.bytes": "bytes"}}
    json.dump(stats, open(os.path.join(out, "stats.json"), "w"))
""")


class SweepTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.root = os.path.join(self.dir.name, "out")
        self.sim = os.path.join(self.dir.name, "strata-sim")
        with open(self.sim, "w") as f:
            f.write(FAKE_SIM)
        os.chmod(self.sim, os.stat(self.sim).st_mode | stat.S_IEXEC)
        self.saved = sweep.SIM
        sweep.SIM = self.sim

    def tearDown(self):
        sweep.SIM = self.saved
        self.dir.cleanup()

    def calls(self):
        path = os.path.join(self.dir.name, "calls.log")
        return open(path).read().split() if os.path.exists(path) else []

    def run_sweep(self, scenes):
        runs = [{"config": "trax", "scene": s, "res": "8x8", "set": {"tms": 2}} for s in scenes]
        return sweep.sweep(runs, self.root, jobs=2, label="test")

    def test_the_folder_is_a_stable_hash_of_the_parameters(self):
        a = {"config": "trax", "scene": "s", "res": "8x8", "set": {"tms": 2, "x.y": 1}}
        b = {"set": {"x.y": 1, "tms": 2}, "res": "8x8", "scene": "s", "config": "trax"}
        self.assertEqual(sweep.run_key(a), sweep.run_key(b))
        self.assertNotEqual(sweep.run_key(a), sweep.run_key(dict(a, res="16x16")))

    def test_finished_runs_are_skipped_and_duplicates_run_once(self):
        first = self.run_sweep(["a", "b", "a"])
        self.assertEqual(sorted(self.calls()), ["a", "b"])
        self.assertTrue(all(r.error is None for r in first))
        self.assertIs(first[0], first[2])
        again = self.run_sweep(["a", "b"])
        self.assertEqual(sorted(self.calls()), ["a", "b"])  # nothing ran again
        self.assertTrue(all(r.cached for r in again))
        self.assertEqual(again[0].stats["frame"]["cycles"], first[0].stats["frame"]["cycles"])
        params = json.load(open(os.path.join(again[0].folder, "params.json")))
        self.assertEqual(params["scene"], "a")

    def test_a_failed_or_cut_off_run_is_recorded_not_marked_done_and_retried(self):
        results = self.run_sweep(["ok", "broken", "cut"])
        by_scene = {r.params["scene"]: r for r in results}
        self.assertIsNone(by_scene["ok"].error)
        self.assertIn("no triangles", by_scene["broken"].error)
        self.assertIsNotNone(by_scene["cut"].error)
        for s in ("broken", "cut"):
            folder = by_scene[s].folder
            self.assertFalse(os.path.exists(os.path.join(folder, "done.json")))
            self.assertTrue(os.path.exists(os.path.join(folder, "error.json")))
        self.run_sweep(["ok", "broken", "cut"])
        self.assertEqual(sorted(self.calls()), ["broken", "broken", "cut", "cut", "ok"])

    def test_frames_of_another_build_are_forgotten_and_run_again(self):
        self.run_sweep(["a", "b"])
        runs = [{"config": "trax", "scene": s, "res": "8x8", "set": {"tms": 2}} for s in ("a", "b")]
        self.assertEqual(sweep.run_mod.forget_other_builds(self.root, runs, self.sim), 0)  # same build
        with open(self.sim, "a") as f:
            f.write("# rebuilt\n")  # another binary: another digest
        self.assertEqual(sweep.run_mod.forget_other_builds(self.root, runs, self.sim), 2)
        folder = sweep.run_mod.folder_of(self.root, runs[0])
        self.assertFalse(sweep.run_mod.is_done(folder))
        self.assertTrue(os.path.exists(os.path.join(folder, "done-other-build.json")))
        again = self.run_sweep(["a", "b"])
        self.assertEqual(sorted(self.calls()), ["a", "a", "b", "b"])
        self.assertFalse(any(r.cached for r in again))
        self.assertEqual(sweep.run_mod.forget_other_builds(self.root, runs, self.sim), 0)

    def test_flatten_puts_the_unit_in_the_column_name(self):
        stats = {"frame": {"cycles": 5, "seconds": 1e-6}, "memory": {"dram": {"bytes": 7}},
                 "design": {"name": "x", "streams": True}, "config": {"tms": 128},
                 "units": {"frame.cycles": "cycles", "memory.dram.bytes": "bytes"}}
        flat = sweep.flatten(stats)
        self.assertEqual(flat["frame.cycles [cycles]"], 5)
        self.assertEqual(flat["memory.dram.bytes [bytes]"], 7)
        self.assertIn("frame.seconds", flat)  # no unit known: the bare path
        self.assertNotIn("config.tms", flat)  # the config is not a statistic
        self.assertFalse(any(k.startswith("design.streams") for k in flat))  # booleans are not numbers here


if __name__ == "__main__":
    unittest.main()
