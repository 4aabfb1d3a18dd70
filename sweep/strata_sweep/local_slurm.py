"""A real single-node Slurm cluster on this machine, in a temporary directory, for tests.

Starts munged (with a generated key), slurmctld and slurmd from Debian's slurm-wlm and munge
packages on localhost, with a generated slurm.conf on free ports, and stops them again. The
client commands (sbatch, squeue, scancel) reach it through the SLURM_CONF in `env()`.
Missing packages are an error that names them, never a skip.
"""
import os
import shutil
import socket
import subprocess
import tempfile
import time

DAEMONS = {"munged": "/usr/sbin/munged", "slurmctld": "/usr/sbin/slurmctld", "slurmd": "/usr/sbin/slurmd"}
CLIENTS = ("sbatch", "squeue", "scancel", "sinfo")


def missing_tools():
    missing = [name for name, path in DAEMONS.items() if not os.access(path, os.X_OK)]
    missing += [c for c in CLIENTS if shutil.which(c) is None]
    return missing


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LocalSlurm:
    def __init__(self, cpus=2):
        missing = missing_tools()
        if missing:
            raise RuntimeError("local Slurm cluster: missing " + ", ".join(missing) +
                               " (Debian packages slurm-wlm and munge; scripts/install-deps installs them)")
        self.cpus = cpus
        self.dir = tempfile.mkdtemp(prefix="strata-slurm-")
        os.chmod(self.dir, 0o755)
        self.procs = []
        self.conf = os.path.join(self.dir, "slurm.conf")
        self.munge_socket = os.path.join(self.dir, "munge", "munge.socket")

    def env(self):
        return dict(os.environ, SLURM_CONF=self.conf)

    def _write_munge_key(self):
        d = os.path.join(self.dir, "munge")
        os.makedirs(d, mode=0o700)
        key = os.path.join(d, "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        return key

    def _write_conf(self):
        user = "root" if os.geteuid() == 0 else os.environ.get("USER", "nobody")
        mem = 1024
        for d in ("state", "spool", "log"):
            os.makedirs(os.path.join(self.dir, d), exist_ok=True)
        lines = [
            "ClusterName=strata-test",
            "SlurmctldHost=localhost",
            f"SlurmUser={user}",
            f"SlurmdUser={user}",
            f"SlurmctldPort={free_port()}",
            f"SlurmdPort={free_port()}",
            "AuthType=auth/munge",
            "CredType=cred/munge",
            f"AuthInfo=socket={self.munge_socket}",
            f"StateSaveLocation={self.dir}/state",
            f"SlurmdSpoolDir={self.dir}/spool",
            f"SlurmctldPidFile={self.dir}/slurmctld.pid",
            f"SlurmdPidFile={self.dir}/slurmd.pid",
            f"SlurmctldLogFile={self.dir}/log/slurmctld.log",
            f"SlurmdLogFile={self.dir}/log/slurmd.log",
            "ProctrackType=proctrack/linuxproc",
            "TaskPlugin=task/none",
            "SelectType=select/cons_tres",
            "SelectTypeParameters=CR_Core",
            "SchedulerType=sched/builtin",
            "JobAcctGatherType=jobacct_gather/none",
            "AccountingStorageType=accounting_storage/none",
            # No slurmdbd here: the job completion log is what `sacct --completion` reads, so
            # the sweep can tell why a task ended without a result (killed, timed out, failed).
            "JobCompType=jobcomp/filetxt",
            f"JobCompLoc={self.dir}/log/jobcomp.txt",
            "MpiDefault=none",
            "ReturnToService=2",
            "SlurmdTimeout=30",
            "InactiveLimit=0",
            "MinJobAge=300",
            f"NodeName=localhost NodeHostname={socket.gethostname()} CPUs={self.cpus} RealMemory={mem} State=UNKNOWN",
            "PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP",
        ]
        with open(self.conf, "w") as f:
            f.write("\n".join(lines) + "\n")

    def start(self, timeout=60):
        try:
            return self._start(timeout)
        except BaseException:
            self.stop()  # every daemon started so far, even when starting failed
            raise

    def _start(self, timeout):
        key = self._write_munge_key()
        self._write_conf()
        d = os.path.join(self.dir, "munge")
        self._run_daemon(["munged", "--key-file", key, "--socket", self.munge_socket,
                          "--pid-file", os.path.join(d, "munged.pid"), "--log-file", os.path.join(d, "munged.log"),
                          "--seed-file", os.path.join(d, "munged.seed"), "--force", "--foreground"])
        self._wait(lambda: os.path.exists(self.munge_socket), timeout, "munged")
        self._run_daemon(["slurmctld", "-D", "-i", "-f", self.conf])
        self._run_daemon(["slurmd", "-D", "-f", self.conf, "-N", "localhost"])
        self._wait(self._node_idle, timeout, "slurmd (node never became idle)")
        return self

    def _run_daemon(self, argv):
        path = DAEMONS[argv[0]]
        log = open(os.path.join(self.dir, argv[0] + ".stdout"), "w")
        self.procs.append(subprocess.Popen([path] + argv[1:], stdout=log, stderr=subprocess.STDOUT,
                                           env=self.env(), start_new_session=True))

    def _node_idle(self):
        p = subprocess.run(["sinfo", "-h", "-N", "-o", "%T"], env=self.env(), capture_output=True, text=True)
        return p.returncode == 0 and p.stdout.strip().startswith("idle")

    def _wait(self, ready, timeout, what):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for p in self.procs:
                if p.poll() is not None:
                    raise RuntimeError(f"local Slurm cluster: {os.path.basename(p.args[0])} exited with "
                                       f"{p.returncode}; logs in {self.dir}\n" + self.logs())
            if ready():
                return
            time.sleep(0.2)
        raise RuntimeError(f"local Slurm cluster: {what} not ready after {timeout} s; logs in {self.dir}\n" + self.logs())

    def logs(self):
        out = []
        for root, _, files in os.walk(self.dir):
            for name in files:
                if name.endswith((".log", ".stdout")):
                    with open(os.path.join(root, name), errors="replace") as f:
                        out.append(f"--- {name}\n" + "".join(f.readlines()[-15:]))
        return "\n".join(out)

    def stop(self):
        for p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
        for p in reversed(self.procs):
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        self.procs = []
        shutil.rmtree(self.dir, ignore_errors=True)

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()
