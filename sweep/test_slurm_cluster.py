#!/usr/bin/python3
"""strata-sweep's Slurm backend against a real single-node Slurm cluster started here from
Debian's slurm-wlm and munge (strata_sweep/local_slurm.py), with the real strata-sim: five
Cornell frames as a job array: one fails the first time, and one is killed with its task by a
signal, which Slurm's own record (scontrol or sacct) explains; the re-run submits only those
two; the results equal the local backend's, bit for bit; the scene cache the tasks built at once
holds one entry and no temporaries. Run by CTest (Sweep.SlurmCluster), which passes STRATA_SIM."""
import json
import os
import stat
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from strata_sweep import cli  # noqa: E402
from strata_sweep.local_slurm import LocalSlurm  # noqa: E402

SIM = os.environ.get("STRATA_SIM") or os.path.join(os.path.dirname(HERE), "build", "sim", "strata-sim")

# Until the file "allow" exists beside it, seed 3 fails and seed 5 kills its Slurm task (the
# python3 task process) with SIGKILL, so that nothing can write the run's error.json; otherwise
# the real simulator.
WRAPPER = textwrap.dedent("""\
    #!/bin/bash
    here="$(dirname "$0")"
    if [[ " $* " == *" --seed 3 "* && ! -e "$here/allow" ]]; then
      echo "wrapper: seed 3 fails this time" >&2; exit 3
    fi
    if [[ " $* " == *" --seed 5 "* && ! -e "$here/allow" ]]; then
      kill -9 $PPID; sleep 30; exit 9
    fi
    exec {sim} "$@"
""")

# Every statistic but the host's wall-clock measurements.
def simulated(column):
    return not column.startswith(("simulation.", "simulator wall"))


class SlurmClusterTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not os.access(SIM, os.X_OK):
            raise RuntimeError(f"{SIM}: strata-sim not built")
        cls.cluster = LocalSlurm(cpus=2).start()
        os.environ["SLURM_CONF"] = cls.cluster.conf

    @classmethod
    def tearDownClass(cls):
        cls.cluster.stop()
        os.environ.pop("SLURM_CONF", None)

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        os.chmod(self.dir, 0o755)
        self.cache = os.path.join(self.dir, "cache")
        os.environ["STRATA_CACHE_DIR"] = self.cache
        self.wrapper = os.path.join(self.dir, "sim-wrapper")
        with open(self.wrapper, "w") as f:
            f.write(WRAPPER.format(sim=SIM))
        os.chmod(self.wrapper, os.stat(self.wrapper).st_mode | stat.S_IEXEC)

    def tearDown(self):
        os.environ.pop("STRATA_CACHE_DIR", None)
        self.tmp.cleanup()

    def spec(self, output):
        path = os.path.join(self.dir, output + ".json")
        with open(path, "w") as f:
            json.dump({"axes": {"design": ["trax"], "scene": ["cornell:size=0.2"], "res": ["16x16"],
                                "seed": [1, 2, 3, 4, 5]},
                       "fixed": {"set": {"tms": 1, "tps_per_tm": 8}}, "timing_mode": "lt",
                       "output": output, "timeout_seconds": 300}, f)
        return path

    def results(self, output):
        with open(os.path.join(self.dir, output, "results.json")) as f:
            return {r["run"]: r for r in json.load(f)}

    def batches(self, output):
        d = os.path.join(self.dir, output, "slurm")
        out = []
        for name in sorted(os.listdir(d)):
            if name.startswith("batch-"):
                with open(os.path.join(d, name)) as f:
                    out.append(len(json.load(f)["runs"]))
        return out

    def test_array_resubmits_only_missing_runs_and_matches_local(self):
        args = ["--backend", "slurm", "--sim", self.wrapper, "--max-running", "2", "--poll-seconds", "0.5"]
        spec = self.spec("on-slurm")
        self.assertEqual(cli.main([spec, *args]), 1)  # seeds 3 and 5 failed
        first = self.results("on-slurm")
        self.assertEqual(sorted(r["status"] for r in first.values()), ["done", "done", "done", "failed", "failed"])
        errors = sorted(r["error"] for r in first.values() if r["status"] == "failed")
        self.assertIn("exited with 3", errors[1])
        self.assertRegex(errors[0], r"^Slurm task \d+_\d \(job \d+, .*\) ended FAILED, killed by signal 9, "
                                    "without a result$")
        open(os.path.join(self.dir, "allow"), "w").close()
        self.assertEqual(cli.main([spec, *args]), 0)
        self.assertEqual(self.batches("on-slurm"), [5, 2])  # the second array held only the missing runs
        on_slurm = self.results("on-slurm")
        self.assertEqual({r["status"] for r in on_slurm.values()}, {"done"})
        # The scene was built by concurrent tasks into one cache: one entry, no temporaries.
        entries = os.listdir(self.cache)
        self.assertEqual([e for e in entries if e.endswith(".strs")].__len__(), 1, entries)
        self.assertFalse([e for e in entries if ".tmp." in e], entries)
        # The same sweep on the local backend gives the same statistics, run by run.
        self.assertEqual(cli.main([self.spec("on-local"), "--sim", self.wrapper, "--jobs", "2"]), 0)
        local = self.results("on-local")
        self.assertEqual(set(local), set(on_slurm))
        compared = 0
        for key, row in on_slurm.items():
            for col, value in row.items():
                if " [" in col and simulated(col):
                    self.assertEqual(value, local[key][col], f"{key} {col}")
                    compared += 1
        self.assertGreater(compared, 400)


if __name__ == "__main__":
    unittest.main()
