#!/usr/bin/env bash
# The Slurm launcher (scripts/slurm-sweep.sh) on a real, single-node Slurm cluster brought up here: munged, slurmctld
# and slurmd as root in the background, every file of theirs in a temporary directory, their own ports and munge
# socket (so a cluster already on the machine is not touched). The ci suite runs split by repetition as a 3-task job
# array plus the dependent merge; the merged result must equal the unsharded run in every deterministic field
# (`tcsb compare`: N, L, I, operations, statuses, final-state hashes, case by case and repetition by repetition), name
# the shard that measured each repetition, and conform to the result schema (`tcsb export` checks its input against
# it). The daemons it started are stopped on exit.
# Installs slurm-wlm and munge when missing (as scripts/install-deps.sh does). Without root it cannot start the
# daemons: it says so, prints SKIPPED and exits 0.
# Usage: bash scripts/test-slurm.sh [TCSB]     (default build/tcsb)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tcsb=${1:-$root/build/tcsb}
timeout_s=${TCSB_SLURM_TIMEOUT:-600}

if [ "$(id -u)" -ne 0 ]; then
  echo "test-slurm: SKIPPED: starting munged, slurmctld and slurmd needs root (this is uid $(id -u))"
  exit 0
fi
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null; then
  bash "$root/scripts/install-deps.sh" slurm-wlm munge
fi
[ -x "$tcsb" ] || { echo "test-slurm: no tcsb executable at $tcsb" >&2; exit 1; }

tmp=$(mktemp -d /tmp/tcsb-slurm.XXXXXX)
chmod 755 "$tmp"
pids=()
cleanup() {
  local status=$?
  for pid in "${pids[@]+"${pids[@]}"}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]+"${pids[@]}"}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  if [ "$status" -ne 0 ]; then
    echo "test-slurm: failed; the daemons' logs:" >&2
    for log in "$tmp"/*.log "$tmp"/out/*.log; do [ -f "$log" ] && { echo "== $log" >&2; tail -20 "$log" >&2; }; done
  fi
  rm -rf "$tmp"
  exit "$status"
}
trap cleanup EXIT

# munge: its own key, socket and files; slurm finds the socket through AuthInfo.
mkdir -p "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 700 "$tmp/munge"
chmod 400 "$tmp/munge/munge.key"
munged --foreground --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munge/seed" >>"$tmp/munged.log" 2>&1 &
pids+=($!)

# Ports from this process's id, so two runs (or a real cluster's 6817/6818) do not collide.
port=$((20000 + ($$ % 20000) * 2))
host=$(hostname -s)
mkdir -p "$tmp/state" "$tmp/spool"
cat >"$tmp/slurm.conf" <<CONF
ClusterName=tcsbtest
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=tcsb Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf

for _ in $(seq 50); do [ -S "$tmp/munge/munge.socket" ] && break; sleep 0.1; done
[ -S "$tmp/munge/munge.socket" ] || { echo "test-slurm: munged did not start" >&2; exit 1; }
slurmctld -D -i -f "$SLURM_CONF" >>"$tmp/slurmctld.log" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >>"$tmp/slurmd.log" 2>&1 &
pids+=($!)
state=""
for _ in $(seq 120); do
  state=$(sinfo -h -n "$host" -o %T 2>/dev/null || true)
  [ "$state" = "idle" ] && break
  sleep 0.5
done
[ "$state" = "idle" ] || { echo "test-slurm: the node did not come up (state '$state')" >&2; exit 1; }
echo "test-slurm: single-node cluster up ($host, slurm $(sinfo -V | awk '{print $2}'))" >&2

# The ci suite (four nets, nine repetitions, so `tcsb compare` can decide: it needs nine samples), split by
# repetition: every shard holds repetitions of several nets, and each net's repetitions lie in several shards.
"$tcsb" run ci --quiet --out "$tmp/whole.json" 2>"$tmp/whole.log"

timeout "$timeout_s" bash "$root/scripts/slurm-sweep.sh" --wait --tcsb "$tcsb" --split repetitions ci 3 "$tmp/out"
for k in 1 2 3; do
  grep -q '"split": "repetitions"' "$tmp/out/shard-$k.json" ||
    { echo "test-slurm: shard-$k.json is not a shard split by repetition" >&2; exit 1; }
done
# Every repetition of the merged result names its shard, and the nets' repetitions came from more than one.
processes=$(grep -o '"process": [0-9]*' "$tmp/out/merged.json" | sort -u | wc -l)
[ "$processes" -eq 3 ] || { echo "test-slurm: merged.json names $processes processes, not 3" >&2; exit 1; }

# Same behaviour: no deterministic field differs (timings are not judged here: --threshold 100 = +10000 %).
"$tcsb" compare --threshold 100 --summary "$tmp/summary.md" "$tmp/whole.json" "$tmp/out/merged.json" 2>"$tmp/compare.log" ||
  { cat "$tmp/compare.log" "$tmp/summary.md" >&2; exit 1; }
grep -q ", 0 behaviour changes" "$tmp/summary.md" || { cat "$tmp/summary.md" >&2; exit 1; }
# The schema: export reads only results that conform to it.
"$tcsb" export "$tmp/out/merged.json" --format markdown >/dev/null
cases=$(grep -c '"label"' "$tmp/out/merged.json")
echo "test-slurm: ok: 3 array tasks (the ci suite split by repetition) and the merge ran on Slurm; merged.json" \
  "($cases cases) equals the unsharded run in every deterministic field and conforms to the schema"
