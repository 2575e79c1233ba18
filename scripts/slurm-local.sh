#!/bin/bash
# A one-node Slurm cluster on 127.0.0.1 for trying and testing `eyehand sweep --slurm`.
#
#   scripts/slurm-local.sh start   starts munged, slurmctld and slurmd (-N localhost) from a
#                                  slurm.conf written into the state folder; prints the
#                                  `export SLURM_CONF=…` line sbatch/squeue/sinfo need
#   scripts/slurm-local.sh stop    waits for the queue to empty, then stops slurmd,
#                                  slurmctld and munged — only the daemons it started
#
# Installs nothing: needs Debian's slurm-wlm and munge (apt-get install slurm-wlm munge).
# EYEHAND_SLURM_DIR   state folder (default ${TMPDIR:-/tmp}/eyehand-slurm)
# EYEHAND_SLURM_PORT  slurmctld's port, slurmd takes the next one (default 6817)
# EYEHAND_SLURM_WAIT  seconds `stop` waits for the queue to empty before cancelling (default 120)
set -euo pipefail

dir="${EYEHAND_SLURM_DIR:-${TMPDIR:-/tmp}/eyehand-slurm}"
port="${EYEHAND_SLURM_PORT:-6817}"
conf="$dir/slurm.conf"

die() { echo "slurm-local: $*" >&2; exit 1; }

# The pid in a pid file, if that process is still alive.
live_pid() {
  local pid
  [ -s "$1" ] || return 1
  pid="$(cat "$1")"
  kill -0 "$pid" 2>/dev/null && echo "$pid"
}

# Waits (bounded) until `$@` succeeds.
wait_for() {
  local seconds="$1" what="$2"; shift 2
  for _ in $(seq $((seconds * 5))); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 0.2
  done
  die "$what did not happen within ${seconds}s (logs in $dir)"
}

# Stops the daemon of a pid file and waits for it to exit.
stop_daemon() {
  local name="$1" pid
  pid="$(live_pid "$2")" || return 0
  kill -TERM "$pid"
  for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || { echo "stopped $name ($pid)"; return 0; }; sleep 0.1; done
  kill -KILL "$pid" 2>/dev/null || true
  echo "killed $name ($pid): it did not stop within 10 s"
}

write_conf() {
  local cpus mem_mb
  cpus="$(nproc)"
  mem_mb=$(( $(awk '/^MemTotal:/ {print $2}' /proc/meminfo) / 1024 - 512 ))
  cat > "$conf" <<CONF
# Written by scripts/slurm-local.sh: a one-node cluster on 127.0.0.1, no accounting.
ClusterName=eyehand
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
}

start() {
  for program in munged slurmctld slurmd sinfo; do
    command -v "$program" >/dev/null || die "$program not found: apt-get install slurm-wlm munge"
  done
  if live_pid "$dir/slurmctld.pid" >/dev/null || live_pid "$dir/munged.pid" >/dev/null; then
    die "a cluster from $dir is running: $0 stop first"
  fi
  mkdir -p "$dir/state" "$dir/spool"
  chmod 700 "$dir"
  if [ ! -s "$dir/munge.key" ]; then
    dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
    chmod 400 "$dir/munge.key"
  fi
  munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed"
  wait_for 10 "munged's socket" test -S "$dir/munge.socket"
  write_conf
  export SLURM_CONF="$conf"
  slurmctld -f "$conf"
  wait_for 30 "slurmctld answering" sinfo
  slurmd -f "$conf" -N localhost
  wait_for 60 "node localhost idle" bash -c "sinfo -h -n localhost -o %T | grep -qx idle"
  echo "export SLURM_CONF=$conf"
}

stop() {
  if [ -s "$conf" ] && live_pid "$dir/slurmctld.pid" >/dev/null; then
    export SLURM_CONF="$conf"
    local waited=0 limit="${EYEHAND_SLURM_WAIT:-120}"
    while [ -n "$(squeue -h 2>/dev/null)" ] && [ "$waited" -lt "$limit" ]; do
      sleep 1; waited=$((waited + 1))
    done
    if [ -n "$(squeue -h 2>/dev/null)" ]; then
      echo "the queue is not empty after ${limit}s: cancelling its jobs"
      scancel --full --user="$(id -un)" || true
      wait_for 30 "the queue emptying" bash -c '[ -z "$(squeue -h)" ]'
    fi
  fi
  stop_daemon slurmd "$dir/slurmd.pid"
  stop_daemon slurmctld "$dir/slurmctld.pid"
  stop_daemon munged "$dir/munged.pid"
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  *) echo "usage: $0 start|stop" >&2; exit 2 ;;
esac
