#!/usr/bin/python3
"""Tests of the experiment commands' argument checks (experiments/arguments.py; issue 39, F15):
experiments/paper.py, experiments/fidelity.py and the scripts/fidelity wrapper, each run as a
subprocess with bad arguments, must exit with status 2 and an argparse-style message naming the
option, with no traceback, and before anything is built, created or run (the stand-in simulator
records every call; there must be none). No simulator runs. Run by CTest (Experiments.Arguments)
or directly: python3 experiments/test_arguments.py"""
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PAPER = os.path.join(HERE, "paper.py")
FIDELITY = os.path.join(HERE, "fidelity.py")

# Stand-in for strata-sim: records the call and fails, so a frame launched by mistake is seen
# (calls.log) and costs nothing.
FAKE_SIM = textwrap.dedent("""\
    #!/usr/bin/python3
    import os, sys
    with open(os.path.join(os.path.dirname(__file__), "calls.log"), "a") as f:
        f.write(" ".join(sys.argv[1:]) + "\\n")
    sys.exit("stand-in strata-sim: not to be run by these tests")
""")


def executable(path, text):
    with open(path, "w") as f:
        f.write(text)
    os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)


class Fixture(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.sim = os.path.join(self.dir, "strata-sim")
        executable(self.sim, FAKE_SIM)
        self.out = os.path.join(self.dir, "out")  # never created by a refused command
        self.file = os.path.join(self.dir, "a-file")
        open(self.file, "w").close()
        self.env = dict(os.environ, STRATA_SIM=self.sim)

    def tearDown(self):
        self.tmp.cleanup()

    def run_command(self, command, *args):
        return subprocess.run([*command, *args], env=self.env, capture_output=True, text=True, timeout=120)

    def calls(self):
        p = os.path.join(self.dir, "calls.log")
        if not os.path.exists(p):
            return []
        with open(p) as f:
            return f.read().splitlines()

    def assert_refused(self, result, option):
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        self.assertIn(f"error: argument {option}: ", result.stderr)
        self.assertEqual(self.calls(), [])
        self.assertFalse(os.path.exists(self.out))


class PaperTest(Fixture):
    def paper(self, *args):
        return self.run_command([sys.executable, PAPER], *args)

    def test_a_resolution_that_is_not_wxh_with_sides_strata_sim_takes_is_refused(self):
        for res in ("abc", "0x0", "128x0", "16385x128", "128", "128x128x2", " 128x128", "+128x128", "1e3x128"):
            with self.subTest(res=res):
                result = self.paper("all", "--res", res, "--out", self.out)
                self.assert_refused(result, "--res")
                self.assertIn(repr(res), result.stderr)
        self.assert_refused(self.paper("--list", "--res", "abc"), "--res")

    def test_a_resolution_an_experiment_would_scale_past_the_limit_is_refused(self):
        # size-check runs twice the resolution too: 16384 is fine alone, not doubled.
        result = self.paper("size-check", "--res", "16384x16384", "--out", self.out)
        self.assert_refused(result, "--res")
        self.assertIn("32768x32768", result.stderr)

    def test_jobs_must_be_a_positive_whole_number(self):
        for jobs in ("-1", "0", "two"):
            with self.subTest(jobs=jobs):
                self.assert_refused(self.paper("all", "--jobs", jobs, "--out", self.out), "--jobs")

    def test_an_output_folder_that_cannot_be_one_is_refused(self):
        for out in (self.file, os.path.join(self.file, "sub")):
            with self.subTest(out=out):
                result = self.paper("all", "--out", out)
                self.assert_refused(result, "--out")
                self.assertIn("not a folder", result.stderr)

    def test_scenes_must_name_some_none_twice(self):
        for scenes in (",", "sibenik,hairball,sibenik"):
            with self.subTest(scenes=scenes):
                self.assert_refused(self.paper("all", "--scenes", scenes, "--out", self.out), "--scenes")

    def test_an_error_target_must_be_a_relative_half_width_for_sampled_mode(self):
        for target in ("0", "0.6", "two", "-0.02"):
            with self.subTest(target=target):
                self.assert_refused(self.paper("all", "--mode", "sampled", "--target-error", target, "--out", self.out),
                                    "--target-error")
        result = self.paper("all", "--mode", "lt", "--target-error", "0.02", "--out", self.out)
        self.assert_refused(result, "--target-error")
        self.assertIn("for --mode sampled", result.stderr)

    def test_target_statistics_need_a_target_and_name_each_once(self):
        result = self.paper("all", "--mode", "sampled", "--target-stats", "frame.cycles", "--out", self.out)
        self.assert_refused(result, "--target-stats")
        self.assertIn("give --target-error too", result.stderr)
        self.assert_refused(self.paper("all", "--mode", "sampled", "--target-error", "0.02", "--target-stats",
                                       "frame.cycles,frame.cycles", "--out", self.out), "--target-stats")

    def test_good_arguments_pass(self):
        result = self.paper("--list", "--res", "256x256", "--jobs", "1", "--scenes", "sibenik", "--out", self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("size-check", result.stdout)


class FidelityTest(Fixture):
    def fidelity(self, *args):
        return self.run_command([sys.executable, FIDELITY], *args)

    def test_a_resolution_that_is_not_wxh_is_refused(self):
        for res in ("abc", "0x0", "16385x16385"):
            with self.subTest(res=res):
                self.assert_refused(self.fidelity("sibenik", "strata-pipelines", res, "--out", self.out), "res")

    def test_jobs_must_be_a_positive_whole_number(self):
        for jobs in ("-1", "0"):
            with self.subTest(jobs=jobs):
                self.assert_refused(self.fidelity("--jobs", jobs, "--out", self.out), "--jobs")

    def test_an_output_folder_that_cannot_be_one_is_refused(self):
        self.assert_refused(self.fidelity("--out", self.file), "--out")

    def test_an_unknown_design_is_refused(self):
        self.assert_refused(self.fidelity("sibenik", "no-such-design", "--out", self.out), "design")


class FidelityWrapperTest(Fixture):
    """scripts/fidelity builds strata-sim, then runs fidelity.py; the arguments must be checked
    before the build. Run from a copy of the checkout's relevant parts whose scripts/build is a
    stand-in, so these tests can never start a real build."""

    def setUp(self):
        super().setUp()
        self.tree = os.path.join(self.dir, "tree")
        for part in ("scripts", "experiments"):
            os.makedirs(os.path.join(self.tree, part))
        shutil.copy2(os.path.join(ROOT, "scripts", "fidelity"), os.path.join(self.tree, "scripts"))
        for name in os.listdir(HERE):
            if name.endswith(".py"):
                shutil.copy2(os.path.join(HERE, name), os.path.join(self.tree, "experiments"))
        for part in ("sweep", "sim"):  # strata-sweep's runner, and sim/configs for the designs
            os.symlink(os.path.join(ROOT, part), os.path.join(self.tree, part))
        self.built = os.path.join(self.dir, "built")
        executable(os.path.join(self.tree, "scripts", "build"), f"#!/bin/sh\ntouch '{self.built}'\n")

    def wrapper(self, *args):
        return self.run_command([os.path.join(self.tree, "scripts", "fidelity")], *args)

    def test_bad_arguments_are_refused_before_the_build(self):
        for args, option in ((("sibenik", "strata-pipelines", "0x0"), "res"), (("--jobs", "0"), "--jobs"),
                             (("--out", self.file), "--out")):
            with self.subTest(args=args):
                result = self.wrapper(*args, *(() if "--out" in args else ("--out", self.out)))
                self.assert_refused(result, option)
                self.assertFalse(os.path.exists(self.built))

    def test_help_needs_no_build(self):
        result = self.wrapper("--help")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("--jobs", result.stdout)
        self.assertFalse(os.path.exists(self.built))

    def test_good_arguments_build_then_run(self):
        result = self.wrapper("sibenik", "strata-pipelines", "8x8", "--jobs", "1", "--out", self.out)
        self.assertTrue(os.path.exists(self.built))
        self.assertEqual(len(self.calls()), 8, result.stderr)  # every mode's frame was launched
        self.assertEqual(result.returncode, 1)  # the stand-in fails each one
        self.assertIn("the precise frame failed", result.stderr)
        self.assertNotIn("Traceback", result.stderr)


if __name__ == "__main__":
    unittest.main()
