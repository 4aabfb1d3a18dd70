"""strata-sweep: parameter sweeps of strata-sim frames, on this machine or on a Slurm cluster.

spec.py      the sweep specification (JSON) and its expansion into runs
run.py       one run: its folder (a stable hash of its parameters), the command, the done marker
local.py     the local backend: N worker processes, a progress line, Ctrl-C
slurm.py     the Slurm backend: an sbatch job array over the pending runs, followed with squeue
results.py   results.csv and results.json from the finished runs
plot.py      PNG plots from the spec's plot entries (matplotlib)
cli.py       the command line (scripts/strata-sweep)
"""
