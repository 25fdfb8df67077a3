#!/usr/bin/env bash
# A one-node Slurm on this machine (Debian's slurm-wlm and munge), for the sweep's Slurm executor
# and its test (docs/cluster.md). Idempotent; needs root (munged runs as munge, the daemons as root).
#   tools/slurm_local.sh start   write the configuration, start munged, slurmctld and slurmd
#   tools/slurm_local.sh stop    stop the daemons this script started
#   tools/slurm_local.sh env     print the SLURM_CONF line to export
# The configuration and the daemons' state and logs live in $SILODEM_SLURM_DIR (default
# /tmp/silodem-slurm); the cluster is one node with every core, one partition "debug".
set -euo pipefail
dir=${SILODEM_SLURM_DIR:-/tmp/silodem-slurm}
conf="$dir/slurm.conf"
node=$(hostname -s)

fail() { echo "slurm_local: $*" >&2; exit 1; }
# Whether the daemon this script started (its pid file) still runs.
running() { [ -f "$dir/$1.pid" ] && kill -0 "$(cat "$dir/$1.pid")" 2>/dev/null; }

start() {
  for c in munged slurmctld slurmd sbatch squeue; do
    command -v "$c" >/dev/null || [ -x "/usr/sbin/$c" ] || fail "$c not found: install slurm-wlm and munge (tools/setup.sh)"
  done
  [ "$(id -u)" = 0 ] || fail "needs root to start munged and the Slurm daemons"
  mkdir -p "$dir"/{state,spool,log}
  cat > "$conf" <<CONF
# Written by tools/slurm_local.sh: a one-node cluster for silodem's sweeps.
ClusterName=silodem
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
MpiDefault=none
NodeName=$node CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
  # munge: its key and folders must belong to it, or munged refuses to start.
  mkdir -p /run/munge /var/log/munge /var/lib/munge /etc/munge
  [ -s /etc/munge/munge.key ] || dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 status=none
  chown -R munge:munge /run/munge /var/log/munge /var/lib/munge /etc/munge
  chmod 0700 /var/log/munge /var/lib/munge /etc/munge
  chmod 0755 /run/munge
  chmod 0400 /etc/munge/munge.key
  pgrep -x munged >/dev/null || runuser -u munge -- /usr/sbin/munged || fail "munged did not start (/var/log/munge/munged.log)"
  export SLURM_CONF="$conf"
  running slurmctld || /usr/sbin/slurmctld -f "$conf" || fail "slurmctld did not start ($dir/log/slurmctld.log)"
  running slurmd || /usr/sbin/slurmd -f "$conf" || fail "slurmd did not start ($dir/log/slurmd.log)"
  for _ in $(seq 1 30); do
    if sinfo -h -o %T 2>/dev/null | grep -q -E "idle|mixed|alloc"; then echo "slurm_local: up; export SLURM_CONF=$conf"; return 0; fi
    sleep 1
  done
  fail "the node did not come up in 30 s: $(sinfo 2>&1 | tail -2); see $dir/log"
}

stop() {
  for d in slurmd slurmctld; do
    [ -f "$dir/$d.pid" ] && kill "$(cat "$dir/$d.pid")" 2>/dev/null || true
  done
  echo "slurm_local: stopped (munged left running)"
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  env) echo "export SLURM_CONF=$conf" ;;
  *) echo "usage: tools/slurm_local.sh start|stop|env" >&2; exit 2 ;;
esac
