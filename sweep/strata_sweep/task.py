"""One Slurm array task: python3 -m strata_sweep.task ROOT BATCH INDEX runs the INDEX-th run of
the batch file (a JSON list of parameter sets) into ROOT/runs/<key>, as the local backend would."""
import json
import os
import socket
import sys

from . import run as run_mod

SLURM_RECORD = "slurm-task.json"  # which Slurm job ran the folder last, for asking Slurm why it ended


def main(argv):
    if len(argv) != 4:
        print("usage: python3 -m strata_sweep.task ROOT BATCH INDEX", file=sys.stderr)
        return 2
    root, batch, index = argv[1], argv[2], int(argv[3])
    with open(batch) as f:
        spec = json.load(f)
    params = spec["runs"][index]
    folder = run_mod.folder_of(root, params)
    if run_mod.is_done(folder):
        return 0  # finished by an earlier submission: never run twice
    os.makedirs(folder, exist_ok=True)
    run_mod.write_json_atomically(os.path.join(folder, SLURM_RECORD), {
        "job_id": os.environ.get("SLURM_JOB_ID", ""), "array_job_id": os.environ.get("SLURM_ARRAY_JOB_ID", ""),
        "array_task_id": os.environ.get("SLURM_ARRAY_TASK_ID", ""), "host": socket.gethostname()})
    _, error = run_mod.execute(params, root, spec["timeout_seconds"], spec.get("sim"))
    if error:
        print(f"strata-sweep task {index}: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
