#!/usr/bin/env bash
# Runs a tcsb suite on a Slurm cluster as a job array: array task K runs shard K of N (`tcsb run SUITE --shard K/N`),
# and a merge job that depends on the whole array (afterok) joins the shards (`tcsb merge`) once every task has
# succeeded. A net's cases of a repetition stay in one task, so every same-run ratio is measured within one process.
#
# Usage: scripts/slurm-sweep.sh [--wait] [--tcsb PATH] [--split repetitions|nets] [--sbatch "FLAGS"] SUITE N OUTDIR
#                               [-- RUN FLAGS...]
#   SUITE     a suite file or a bundled suite name (ci, paper, scaling, ...)
#   N         the number of shards = array tasks (more than the units of the split leaves some shards empty)
#   OUTDIR    a directory every node can write (created): shard-K.json and shard-K.log per task, merged.json and
#             merge.log, and the two job scripts (shard.sbatch, merge.sbatch)
#   --tcsb    the tcsb executable the nodes run (default: build/tcsb of this checkout, else `tcsb` on PATH)
#   --split   what the shards split (`tcsb run --split`, docs/sweeps.md): repetitions (default: a net's repetitions
#             spread over the tasks) or nets (each net with all its repetitions in one task)
#   --sbatch  extra flags for both sbatch calls, e.g. "--partition=short --time=01:00:00 --account=me"
#   --wait    block until the merge job ends and exit with its status (a failed shard cancels the merge: exit 1)
#   RUN FLAGS are passed to every `tcsb run`, e.g. -- --repetitions 3
# Prints the array's and the merge's job ids. Example:
#   scripts/slurm-sweep.sh --sbatch "--time=02:00:00" scaling 4 "$HOME/sweeps/scaling" -- --repetitions 3
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
wait_for_merge=0
tcsb=""
split=repetitions
sbatch_flags=""
while [ $# -gt 0 ]; do
  case "$1" in
    --wait) wait_for_merge=1; shift ;;
    --tcsb) tcsb=${2:?--tcsb needs a path}; shift 2 ;;
    --split) split=${2:?--split needs repetitions or nets}; shift 2 ;;
    --sbatch) sbatch_flags=${2?--sbatch needs flags}; shift 2 ;;
    -h|--help) usage ;;
    *) break ;;
  esac
done
[ $# -ge 3 ] || usage
suite=$1 shards=$2 outdir=$3
shift 3
if [ $# -gt 0 ]; then
  [ "$1" = "--" ] || usage
  shift
fi
run_flags=("$@")
if ! [[ "$shards" =~ ^[1-9][0-9]*$ ]]; then
  echo "slurm-sweep: N must be a whole number >= 1, got '$shards'" >&2
  exit 2
fi
case "$split" in
  repetitions|nets) ;;
  *) echo "slurm-sweep: --split must be repetitions or nets, got '$split'" >&2; exit 2 ;;
esac
if [ -z "$tcsb" ]; then
  if [ -x "$root/build/tcsb" ]; then tcsb="$root/build/tcsb"; else tcsb=$(command -v tcsb || true); fi
fi
[ -n "$tcsb" ] && [ -x "$tcsb" ] || { echo "slurm-sweep: no tcsb executable (build it, or give --tcsb PATH)" >&2; exit 2; }
tcsb=$(cd "$(dirname "$tcsb")" && pwd)/$(basename "$tcsb")
# A suite file becomes an absolute path (the jobs start elsewhere); a bundled name stays a name.
[ -e "$suite" ] && suite=$(cd "$(dirname "$suite")" && pwd)/$(basename "$suite")
mkdir -p "$outdir"
outdir=$(cd "$outdir" && pwd)
# Check the suite and the flags now, not in N failed tasks: validate parses the suite as every shard will.
"$tcsb" validate "$suite" >/dev/null

# Each argument shell-quoted for the job scripts (nothing at all for no arguments).
quoted() { local a; for a in "$@"; do printf '%q ' "$a"; done; }
cat >"$outdir/shard.sbatch" <<JOB
#!/usr/bin/env bash
#SBATCH --job-name=tcsb-shard
#SBATCH --output=$outdir/shard-%a.log
#SBATCH --ntasks=1
# One array task: shard \$SLURM_ARRAY_TASK_ID of $shards, split by $split.
set -euo pipefail
k=\$SLURM_ARRAY_TASK_ID
exec $(quoted "$tcsb") run $(quoted "$suite") --quiet --split $split --shard "\$k/$shards" --out $(printf %q "$outdir")/shard-\$k.json $(quoted "${run_flags[@]+"${run_flags[@]}"}")
JOB
merge_inputs=()
for k in $(seq 1 "$shards"); do merge_inputs+=("$outdir/shard-$k.json"); done
cat >"$outdir/merge.sbatch" <<JOB
#!/usr/bin/env bash
#SBATCH --job-name=tcsb-merge
#SBATCH --output=$outdir/merge.log
#SBATCH --ntasks=1
# Joins the $shards shards (each exactly once) into merged.json.
set -euo pipefail
exec $(quoted "$tcsb") merge $(quoted "${merge_inputs[@]}") --out $(printf %q "$outdir")/merged.json
JOB

# shellcheck disable=SC2086  # --sbatch FLAGS are meant to be split into words
array_job=$(sbatch --parsable $sbatch_flags --array="1-$shards" "$outdir/shard.sbatch")
array_job=${array_job%%;*}  # "jobid;cluster" on multi-cluster setups
echo "slurm-sweep: shards: job array $array_job (tasks 1-$shards), logs $outdir/shard-K.log" >&2
# A failed task leaves afterok unsatisfiable: --kill-on-invalid-dep cancels the merge instead of leaving it pending.
merge_flags=(--parsable --dependency="afterok:$array_job" --kill-on-invalid-dep=yes)
if [ "$wait_for_merge" -eq 1 ]; then
  echo "slurm-sweep: waiting for the merge" >&2
  # shellcheck disable=SC2086
  if sbatch "${merge_flags[@]}" --wait $sbatch_flags "$outdir/merge.sbatch"; then
    echo "slurm-sweep: merged into $outdir/merged.json" >&2
    exit 0
  fi
  echo "slurm-sweep: the merge did not succeed (a failed shard cancels it); see $outdir/*.log" >&2
  exit 1
fi
# shellcheck disable=SC2086
merge_job=$(sbatch "${merge_flags[@]}" $sbatch_flags "$outdir/merge.sbatch")
echo "slurm-sweep: merge: job ${merge_job%%;*} after $array_job, into $outdir/merged.json" >&2
echo "$array_job ${merge_job%%;*}"
