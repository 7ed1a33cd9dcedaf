#!/bin/bash
# A real one-node Slurm cluster on this machine, for the `scale` tests (tests/scale/slurm_class.sh).
#
#   tests/scale/slurm_one_node.sh STATE [start]   start it (idempotent: what already runs is kept)
#   tests/scale/slurm_one_node.sh STATE stop      stop exactly the daemons this script started
#   tests/scale/slurm_one_node.sh STATE status    say what runs
#
# Everything of the cluster lives in the private folder STATE: slurm.conf, the controller's state,
# the node's spool, the logs and the pid files. Run as root (the daemons run as root, the jobs too),
# without systemd: the daemons are started directly with `-f STATE/slurm.conf`. The client commands
# (sbatch, squeue, sinfo, scancel, scontrol) find the cluster through SLURM_CONF: after a start,
#   export SLURM_CONF=STATE/slurm.conf     (the line is also written to STATE/slurm.env, to source)
# Needs Debian's packages: slurmctld slurmd munge (slurm-client comes with them).
#
# Munge (Slurm's authentication) is machine-wide: the key /etc/munge/munge.key is made if it is
# missing, and munged is started on its usual socket only if no munged answers there already; the
# script then remembers that it started it (STATE/munged.ours) and stops it again with the rest.
set -euo pipefail

state=${1:?usage: slurm_one_node.sh STATE [start|stop|status]}
mode=${2:-start}
mkdir -p "$state"
state=$(cd "$state" && pwd)
conf=$state/slurm.conf
node=$(hostname -s 2>/dev/null || echo localhost)
[ -n "$node" ] || node=localhost
wait_idle=${SLURM_ONE_NODE_TIMEOUT:-60}  # seconds for the node to become idle

say() { echo "slurm_one_node: $*" >&2; }
die() { say "$*"; exit 1; }

# The pid in a pid file, if that process still runs the program named (a pid file left behind by a
# daemon that died may name a pid reused by something else: that one is never touched).
live_pid() {  # FILE PROGRAM
  local pid
  [ -s "$1" ] || return 1
  pid=$(tr -dc 0-9 < "$1")
  [ -n "$pid" ] && [ -d "/proc/$pid" ] || return 1
  [ "$(cat "/proc/$pid/comm" 2>/dev/null || true)" = "$2" ] || return 1
  echo "$pid"
}

running() {  # PID: still there, and not a zombie that nobody has reaped yet
  [ -r "/proc/$1/stat" ] && [ "$(sed 's/.*) \(.\).*/\1/' "/proc/$1/stat" 2>/dev/null)" != Z ]
}

stop_pid() {  # FILE PROGRAM: TERM, then KILL after 20 s
  local pid i
  pid=$(live_pid "$1" "$2") || { rm -f "$1"; return 0; }
  say "stopping $2 (pid $pid)"
  kill -TERM "$pid" 2>/dev/null || true
  for i in $(seq 1 200); do
    running "$pid" || break
    sleep 0.1
  done
  if running "$pid"; then
    say "$2 (pid $pid) did not stop in 20 s: killing it"
    kill -KILL "$pid" 2>/dev/null || true
  fi
  rm -f "$1"
}

descendants() {  # PID: every process below it
  local c
  for c in $(pgrep -P "$1"); do echo "$c"; descendants "$c"; done
}

munge_works() { munge -n 2>/dev/null | unmunge >/dev/null 2>&1; }

if [ "$mode" = stop ]; then
  export SLURM_CONF=$conf
  # The jobs of this private cluster first, so that no job step outlives its slurmd.
  if live_pid "$state/slurmctld.pid" slurmctld >/dev/null; then
    scancel --quiet --user=root 2>/dev/null || true
  fi
  stop_pid "$state/slurmd.pid" slurmd
  stop_pid "$state/slurmctld.pid" slurmctld
  # Job steps left behind (a slurmctld that had died could not cancel them): only the slurmstepd
  # processes of this cluster, known by this state folder's log that they hold open, and the
  # processes of their jobs (their descendants).
  for d in /proc/[0-9]*; do
    [ "$(cat "$d/comm" 2>/dev/null)" = slurmstepd ] || continue
    ours=no
    for fd in "$d"/fd/*; do
      if [ "$(readlink "$fd" 2>/dev/null)" = "$state/log/slurmd.log" ]; then ours=yes; break; fi
    done 2>/dev/null
    [ $ours = yes ] || continue
    pid=${d#/proc/}
    say "ending a left-over slurmstepd (pid $pid) and its job"
    kill -KILL $(descendants "$pid") "$pid" 2>/dev/null || true
  done
  if [ -e "$state/munged.ours" ]; then
    stop_pid "$state/munge/munged.pid" munged
    rm -f "$state/munged.ours"
  fi
  exit 0
fi

if [ "$mode" = status ]; then
  for p in slurmctld slurmd; do
    if pid=$(live_pid "$state/$p.pid" $p); then echo "$p: running (pid $pid)"; else echo "$p: not running"; fi
  done
  if munge_works; then echo "munged: answering"; else echo "munged: not answering"; fi
  exit 0
fi

[ "$mode" = start ] || die "unknown mode '$mode' (start, stop or status)"
[ "$(id -u)" = 0 ] || die "run as root (the daemons and the jobs run as root)"
for p in slurmctld slurmd munged sinfo; do
  command -v $p >/dev/null || [ -x /usr/sbin/$p ] || die "$p is not installed: apt-get install -y --no-install-recommends slurmctld slurmd munge"
done
export PATH=$PATH:/usr/sbin

# --- munge ----------------------------------------------------------------------------------------
if [ ! -s /etc/munge/munge.key ]; then
  say "creating the munge key /etc/munge/munge.key"
  install -d -o munge -g munge -m 0700 /etc/munge
  mungekey --create --keyfile=/etc/munge/munge.key
  chown munge:munge /etc/munge/munge.key
  chmod 0400 /etc/munge/munge.key
fi
if ! munge_works; then
  # munged runs as its own user, on its usual socket (Slurm's clients and daemons look there), with
  # its pid file and log in STATE/munge.
  install -d -o munge -g munge -m 0755 /run/munge
  install -d -o munge -g munge -m 0700 "$state/munge"
  say "starting munged"
  runuser -u munge -- munged --pid-file="$state/munge/munged.pid" --log-file="$state/munge/munged.log" \
    --seed-file="$state/munge/munged.seed"
  touch "$state/munged.ours"
  for i in $(seq 1 50); do munge_works && break; sleep 0.1; done
  munge_works || die "munged does not answer (log: $state/munge/munged.log)"
fi

# --- slurm.conf -----------------------------------------------------------------------------------
mkdir -p "$state/ctld" "$state/spool" "$state/log"
chmod 0755 "$state"
cpus=$(nproc)
hw_mem=$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' | head -n1)
[ -n "$hw_mem" ] || die "slurmd -C printed no RealMemory"
mem=$((hw_mem - hw_mem / 20 - 64))  # 5 % and 64 MiB below what slurmd sees: the node never looks smaller than configured
[ "$mem" -gt 0 ] || mem=1

new_conf=$(cat <<EOF
# Written by tests/scale/slurm_one_node.sh: a private one-node cluster for tests. Edits are lost.
# The cluster's name (slurmctld requires one; it is kept in the state folder).
ClusterName=geomech-scale
# The controller runs on this machine, reached on the loopback address only.
SlurmctldHost=$node(127.0.0.1)
# Daemons and jobs run as root (a test machine; no slurm user needed).
SlurmUser=root
SlurmdUser=root
# Authentication between the commands and the daemons: munge (the machine's munged).
AuthType=auth/munge
CredType=cred/munge
# Where the controller keeps its state (jobs, the cluster's name) and the node its spool.
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
# The daemons' logs and pid files, all in the state folder (stop mode reads the pid files).
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
# Processes of a job are tracked through their parent pids (/proc), not cgroups: none are set up.
ProctrackType=proctrack/linuxproc
# No task binding or confinement plugin (task/cgroup and task/affinity would need cgroups or cpusets).
TaskPlugin=task/none
# No per-job resource accounting, no accounting database.
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
# Cores are what jobs are given (several jobs share the node, each with its --cpus-per-task);
# memory is not a consumable resource.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
# No MPI plugin: the jobs are plain scripts.
MpiDefault=none
# A node that was down (a stopped slurmd) comes back by itself when its slurmd registers again.
ReturnToService=2
# Finished jobs stay visible to squeue/scontrol for 5 min (no accounting database to ask after).
MinJobAge=300
# The one node: this machine, with its cores and a little less memory than slurmd -C sees.
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
# One partition holding it, used by default, with no time limit of its own.
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
)

ctld_pid=$(live_pid "$state/slurmctld.pid" slurmctld || true)
slurmd_pid=$(live_pid "$state/slurmd.pid" slurmd || true)
if [ -n "$ctld_pid$slurmd_pid" ] && [ -f "$conf" ]; then
  [ "$new_conf" = "$(cat "$conf")" ] ||
    die "the cluster in $state runs with another slurm.conf: stop it first ($0 $state stop)"
else
  printf '%s\n' "$new_conf" > "$conf"
fi
echo "export SLURM_CONF=$conf" > "$state/slurm.env"
export SLURM_CONF=$conf

# --- the daemons ----------------------------------------------------------------------------------
# Started directly (they fork into the background and write their pid files); -f names the
# configuration. A daemon of this state folder that runs already is kept.
if [ -z "$ctld_pid" ]; then
  say "starting slurmctld"
  slurmctld -f "$conf" || die "slurmctld did not start (log: $state/log/slurmctld.log)"
fi
for i in $(seq 1 100); do scontrol ping 2>/dev/null | grep -q UP && break; sleep 0.2; done
scontrol ping 2>/dev/null | grep -q UP || die "slurmctld does not answer (log: $state/log/slurmctld.log)"
if [ -z "$slurmd_pid" ]; then
  say "starting slurmd for node $node"
  slurmd -f "$conf" -N "$node" || die "slurmd did not start (log: $state/log/slurmd.log)"
fi

# --- wait for the node to be idle -----------------------------------------------------------------
deadline=$((SECONDS + wait_idle))
node_state=
while [ $SECONDS -lt $deadline ]; do
  node_state=$(sinfo -h -n "$node" -o %T 2>/dev/null | head -n1 || true)
  case "$node_state" in
    idle|mixed|allocated) break ;;  # up (mixed/allocated: a run of the cluster that is still busy)
  esac
  sleep 0.5
done
case "$node_state" in
  idle|mixed|allocated) ;;
  *) die "node $node is not idle after ${wait_idle} s (sinfo says '${node_state:-nothing}'; logs: $state/log/)" ;;
esac
say "node $node is $node_state; export SLURM_CONF=$conf"
