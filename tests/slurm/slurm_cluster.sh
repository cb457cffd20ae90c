#!/usr/bin/env bash
# A private one-node Slurm cluster for the slurm-labelled tests: munged, slurmctld and slurmd from
# Debian's munge and slurm-wlm packages, started in the foreground-mode daemons' own background
# processes (no systemd), with a generated munge key and slurm.conf in a fresh temporary directory.
#
#   slurm_cluster.sh start ENV_FILE   starts the cluster; ENV_FILE then holds either
#                                       SLURM_CONF=<path> (ready) or UNAVAILABLE=<why Slurm cannot start>
#   slurm_cluster.sh stop ENV_FILE    cancels its jobs and stops the daemons it started
#
# The daemons run as root (SlurmUser=root) with ProctrackType=proctrack/linuxproc and
# TaskPlugin=task/none: no cgroups, which sandboxes and containers often lack. Both commands exit 0
# when they did what they could: the tests read ENV_FILE and skip, naming the reason, when Slurm is
# unavailable.
set -uo pipefail

command=${1:?start or stop}
env_file=${2:?the environment file}

unavailable() {
  echo "slurm_cluster.sh: Slurm cannot start here: $*" >&2
  echo "UNAVAILABLE=$*" >"$env_file"
  exit 0
}

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

start() {
  rm -f "$env_file"
  [ "$(id -u)" -eq 0 ] || unavailable "the test cluster's slurmd must run as root (running as $(id -un))"
  for tool in munged mungekey slurmctld slurmd sbatch squeue scancel sinfo python3; do
    command -v "$tool" >/dev/null || unavailable "$tool is not installed (Debian packages munge, slurm-wlm)"
  done
  local dir
  dir=$(mktemp -d /tmp/saasgaps-slurm.XXXXXX)
  chmod 755 "$dir"
  mkdir -p "$dir/munge" "$dir/socket" "$dir/state" "$dir/spool" "$dir/log"
  chmod 700 "$dir/munge"
  # munged insists on a world-searchable socket directory and a private key.
  chmod 755 "$dir/socket"
  mungekey --create --keyfile="$dir/munge/munge.key" >/dev/null 2>&1 || unavailable "mungekey failed"
  chmod 600 "$dir/munge/munge.key"
  munged --socket="$dir/socket/munge.sock" --key-file="$dir/munge/munge.key" --pid-file="$dir/munge/munged.pid" \
    --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munged.seed" --force \
    || unavailable "munged did not start: $(tail -3 "$dir/log/munged.log" 2>/dev/null | tr '\n' ' ')"

  local host cpus ctld_port slurmd_port
  host=$(hostname -s)
  cpus=$(nproc)
  ctld_port=$(free_port)
  slurmd_port=$(free_port)
  cat >"$dir/slurm.conf" <<CONF
ClusterName=saasgapstest
SlurmctldHost=${host}(127.0.0.1)
SlurmctldPort=${ctld_port}
SlurmdPort=${slurmd_port}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=${dir}/socket/munge.sock
StateSaveLocation=${dir}/state
SlurmdSpoolDir=${dir}/spool
SlurmctldPidFile=${dir}/slurmctld.pid
SlurmdPidFile=${dir}/slurmd.pid
SlurmctldLogFile=${dir}/log/slurmctld.log
SlurmdLogFile=${dir}/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
MinJobAge=600
KillWait=5
SchedulerType=sched/backfill
SchedulerParameters=sched_min_interval=0,sched_interval=1,default_queue_depth=1000
NodeName=${host} NodeAddr=127.0.0.1 CPUs=${cpus} RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=${host} Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$dir/slurm.conf"
  # -D: stay in the foreground, so $! is the daemon's pid.
  slurmctld -D -f "$SLURM_CONF" >"$dir/log/slurmctld.out" 2>&1 &
  echo $! >"$dir/slurmctld.ownpid"
  slurmd -D -f "$SLURM_CONF" -N "$host" >"$dir/log/slurmd.out" 2>&1 &
  echo $! >"$dir/slurmd.ownpid"
  echo "CLUSTER_DIR=$dir" >"$env_file.dir"
  for _ in $(seq 1 150); do
    if [ "$(sinfo --noheader --format=%T 2>/dev/null)" = "idle" ]; then
      echo "SLURM_CONF=$SLURM_CONF" >"$env_file"
      echo "CLUSTER_DIR=$dir" >>"$env_file"
      echo "slurm_cluster.sh: node $host idle (SLURM_CONF=$SLURM_CONF)"
      exit 0
    fi
    sleep 0.2
  done
  local why
  why="the node did not become idle within 30 s: $(tail -2 "$dir/log/slurmctld.out" "$dir/log/slurmd.out" 2>/dev/null | tr '\n' ' ')"
  stop_daemons "$dir"
  unavailable "$why"
}

stop_daemons() {
  local dir=$1
  export SLURM_CONF="$dir/slurm.conf"
  # Our cluster, our jobs: cancel them all so no worker outlives the tests.
  scancel --full --partition=debug >/dev/null 2>&1 || true
  for daemon in slurmd slurmctld; do
    if [ -f "$dir/$daemon.ownpid" ]; then
      kill "$(cat "$dir/$daemon.ownpid")" 2>/dev/null || true
    fi
  done
  sleep 1
  for daemon in slurmd slurmctld; do
    if [ -f "$dir/$daemon.ownpid" ]; then
      kill -9 "$(cat "$dir/$daemon.ownpid")" 2>/dev/null || true
    fi
  done
  [ -f "$dir/munge/munged.pid" ] && kill "$(cat "$dir/munge/munged.pid")" 2>/dev/null || true
}

stop() {
  [ -f "$env_file.dir" ] || exit 0
  local dir
  dir=$(sed -n 's/^CLUSTER_DIR=//p' "$env_file.dir")
  [ -n "$dir" ] && [ -d "$dir" ] && stop_daemons "$dir" && rm -rf "$dir"
  rm -f "$env_file" "$env_file.dir"
  echo "slurm_cluster.sh: stopped"
}

case "$command" in
  start) start ;;
  stop) stop ;;
  *) echo "usage: $0 start|stop ENV_FILE" >&2; exit 64 ;;
esac
