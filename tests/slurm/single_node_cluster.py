# SPDX-License-Identifier: Apache-2.0
"""A throw-away single-node Slurm cluster for tests: Debian 12's munged
(as the munge user, its own key and socket), slurmctld and slurmd (as
root, proctrack/linuxproc, task/none), every file in one temporary
directory, free non-default ports, this host's name and CPU count. Only the
daemons it started are stopped, by the pids in their pid files."""

import getpass
import os
import pwd
import shutil
import signal
import socket
import subprocess
import tempfile
import time

DAEMONS = ("/usr/sbin/munged", "/usr/sbin/slurmctld", "/usr/sbin/slurmd")
CLIENTS = ("sbatch", "squeue", "sinfo", "scancel")


class Unavailable(Exception):
    """A cluster cannot be started here (the test is skipped, with this reason)."""


def why_unavailable():
    if os.geteuid() != 0:
        return f"not root (user {getpass.getuser()}): slurmd and munged need root to start"
    missing = [d for d in DAEMONS if not os.access(d, os.X_OK)] + [c for c in CLIENTS if not shutil.which(c)]
    if missing:
        return f"missing {', '.join(missing)} (Debian: slurmctld slurmd slurm-client munge; ./glider installs them)"
    try:
        pwd.getpwnam("munge")
    except KeyError:
        return "no 'munge' user (the munge package creates it)"
    return ""


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(what, predicate, timeout_s, log_files=()):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if predicate():
            return
        time.sleep(0.1)
    tails = []
    for path in log_files:
        if os.path.exists(path):
            with open(path, errors="replace") as f:
                tails.append(f"--- {path}:\n" + "".join(f.readlines()[-15:]))
    raise TimeoutError(f"{what}: not within {timeout_s} s\n" + "\n".join(tails))


class Cluster:
    def __init__(self):
        reason = why_unavailable()
        if reason:
            raise Unavailable(reason)
        self.dir = tempfile.mkdtemp(prefix="glider-slurm-")
        os.chmod(self.dir, 0o755)
        self.host = socket.gethostname().split(".")[0]
        self.cpus = os.cpu_count()
        self.conf = os.path.join(self.dir, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.pid_files = []

    def path(self, name):
        return os.path.join(self.dir, name)

    def _start_munge(self):
        munge = pwd.getpwnam("munge")
        mdir = self.path("munge")  # key, seed, log: the munge user's alone
        sdir = self.path("munge-run")  # the socket: everyone may reach it (munged checks)
        os.mkdir(mdir, 0o700)
        os.mkdir(sdir, 0o755)
        with open(os.path.join(mdir, "munge.key"), "wb") as f:
            f.write(os.urandom(128))
        os.chmod(os.path.join(mdir, "munge.key"), 0o600)
        for p in (mdir, sdir, os.path.join(mdir, "munge.key")):
            os.chown(p, munge.pw_uid, munge.pw_gid)
        self.munge_socket = os.path.join(sdir, "munge.socket")
        pid_file = os.path.join(sdir, "munged.pid")
        self.pid_files.append(pid_file)
        proc = subprocess.run(["runuser", "-u", "munge", "--", "/usr/sbin/munged", f"--socket={self.munge_socket}",
                        f"--key-file={mdir}/munge.key", f"--pid-file={pid_file}", f"--log-file={mdir}/munged.log",
                        f"--seed-file={mdir}/munged.seed"], check=False, timeout=30, capture_output=True, text=True)
        if proc.returncode != 0:
            raise RuntimeError(f"munged did not start: {proc.stderr.strip()}")
        wait_for("munged's socket", lambda: os.path.exists(self.munge_socket), 15, [f"{mdir}/munged.log"])

    def _write_conf(self):
        for d in ("state", "spool"):
            os.mkdir(self.path(d))
        conf = f"""# a single-node test cluster (tests/slurm/single_node_cluster.py)
ClusterName=glidertest
SlurmctldHost={self.host}
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket={self.munge_socket}
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
StateSaveLocation={self.path('state')}
SlurmdSpoolDir={self.path('spool')}
SlurmctldPidFile={self.path('slurmctld.pid')}
SlurmdPidFile={self.path('slurmd.pid')}
SlurmctldLogFile={self.path('slurmctld.log')}
SlurmdLogFile={self.path('slurmd.log')}
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
SchedulerParameters=sched_interval=1
NodeName={self.host} CPUs={self.cpus} State=UNKNOWN
PartitionName=test Nodes={self.host} Default=YES MaxTime=INFINITE State=UP
"""
        with open(self.conf, "w") as f:
            f.write(conf)

    def start(self):
        self._start_munge()
        self._write_conf()
        logs = [self.path("slurmctld.log"), self.path("slurmd.log")]
        for daemon, pid_file in (("/usr/sbin/slurmctld", "slurmctld.pid"), ("/usr/sbin/slurmd", "slurmd.pid")):
            self.pid_files.append(self.path(pid_file))
            subprocess.run([daemon, "-f", self.conf], check=True, timeout=30, env=self.env, capture_output=True)
            wait_for(f"{daemon}'s pid file", lambda p=self.path(pid_file): os.path.exists(p), 15, logs)
        wait_for("the node to be idle", lambda: self.run(["sinfo", "-h", "-o", "%T"], check=False).stdout.strip()
                 == "idle", 60, logs)
        return self

    def run(self, cmd, check=True, timeout=60):
        return subprocess.run(cmd, env=self.env, capture_output=True, text=True, check=check, timeout=timeout)

    def stop(self):
        """SIGTERM to the daemons this cluster started (pid files), newest first; SIGKILL after 15 s."""
        pids = []
        for pid_file in reversed(self.pid_files):
            try:
                with open(pid_file) as f:
                    pids.append(int(f.read().split()[0]))
            except (OSError, ValueError, IndexError):
                continue
        for pid in pids:
            try:
                os.kill(pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        deadline = time.monotonic() + 15
        for pid in pids:
            while time.monotonic() < deadline and _alive(pid):
                time.sleep(0.1)
            if _alive(pid):
                os.kill(pid, signal.SIGKILL)
        shutil.rmtree(self.dir, ignore_errors=True)


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # A zombie child of ours would count as alive: the daemons fork away, so none is.
    return True
