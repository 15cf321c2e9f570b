#!/bin/bash
# A single-node Slurm "cluster" on this machine, to try the benchmark's Slurm path (scripts/slurm/submit.sh)
# without a real cluster: installs Debian's slurm-wlm and munge if missing, writes a one-node slurm.conf
# (every core of this machine, state under /var/spool/slurm-asv), and starts munged, slurmctld and slurmd.
# Needs root (or sudo). Not part of make test. Usage: scripts/slurm/local_cluster.sh [start|stop|status]
set -euo pipefail
action=${1:-start}
SUDO=""
[[ $(id -u) -ne 0 ]] && SUDO="sudo"
conf=/etc/slurm/slurm.conf
spool=/var/spool/slurm-asv

install() {
  local missing=()
  for p in slurm-wlm munge; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [[ ${#missing[@]} -gt 0 ]]; then
    echo "local_cluster: installing ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}

configure() {
  local host cpus mem
  host=$(hostname -s)
  cpus=$(nproc)
  mem=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 1024 ))
  $SUDO mkdir -p /etc/slurm "$spool/ctld" "$spool/d" /var/log/slurm-asv
  $SUDO tee "$conf" >/dev/null <<CONF
# Written by asv scripts/slurm/local_cluster.sh: one node, this machine.
ClusterName=asv-local
SlurmctldHost=$host
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$spool/ctld
SlurmdSpoolDir=$spool/d
SlurmctldPidFile=$spool/slurmctld.pid
SlurmdPidFile=$spool/slurmd.pid
SlurmctldLogFile=/var/log/slurm-asv/slurmctld.log
SlurmdLogFile=/var/log/slurm-asv/slurmd.log
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=asv Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  [[ -f /etc/munge/munge.key ]] || $SUDO mungekey --create 2>/dev/null || \
    $SUDO dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 status=none
  $SUDO chown munge:munge /etc/munge/munge.key 2>/dev/null || true
  $SUDO chmod 400 /etc/munge/munge.key
}

start() {
  install
  configure
  $SUDO mkdir -p /run/munge && $SUDO chown munge:munge /run/munge
  pgrep -x munged >/dev/null || $SUDO -u munge munged 2>/dev/null || $SUDO munged --force
  pgrep -x slurmctld >/dev/null || $SUDO slurmctld
  pgrep -x slurmd >/dev/null || $SUDO slurmd
  for _ in $(seq 30); do
    sinfo -h -o "%T" 2>/dev/null | grep -qE "idle|mix|alloc" && break
    sleep 1
  done
  sinfo
}

stop() {
  $SUDO pkill -x slurmd || true
  $SUDO pkill -x slurmctld || true
  $SUDO pkill -x munged || true
  echo "local_cluster: stopped"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  status) sinfo; squeue ;;
  *) echo "usage: $0 [start|stop|status]" >&2; exit 2 ;;
esac
