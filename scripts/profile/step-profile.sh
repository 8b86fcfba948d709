#!/usr/bin/env bash
# The tax of adaptivity, in deterministic counts: instructions and simulated cache misses per step of a TC-SB body
# against a static plain body of the budget's node count (plain_equal, the fidelity pass's uniform grid), counted by
# callgrind with a 48 KiB L1 and a 2 MiB last-level cache (the development VM's L2), not in seconds.
# One net of the scaling suite's settings (suites/scaling.json: 4 solver iterations, any number of operations per
# step, evaluation every step), narrowed to one width and one budget, with the feedback evaluated on the simulation
# thread ("parallel": false): a spinning worker would add instructions that depend on the machine's load.
# Only the steps are counted (callgrind collects inside the case body's step alone). Steady state, not warm-up: each
# method runs twice, 10 and 30 timed steps after the same 30 warm-up steps, and the difference of the two counts is
# divided by the 20 steps between them (the convergence to the budget falls in the warm-up and cancels).
# Prints per step: Ir, D1 misses (reads + writes), LL misses (reads + writes), and their ratios TC-SB / plain_equal;
# then the inclusive instructions and LL misses per step of the functions a TC-SB step spends them in.
# Usage: bash scripts/profile/step-profile.sh [build-dir] [width] [compression]   (defaults: build 129 0.3; needs valgrind)
#   TCSB_PROFILE_SUITE=paper takes the net's settings from suites/paper.json instead (2 solver iterations, evaluation
#   every 4 steps); TCSB_PROFILE_TCSB='{"restore_order": false}' overrides TC-SB settings (here: Bullet's arrays left
#   in the order operations leave them, for the profile before restore_order).
#   TCSB_PROFILE_EVALUATION_INTERVAL=k evaluates the feedback every k steps instead of the suite's every step: a
#   callgrind run simulates one cache for everything, so the evaluation (on a worker thread and its core in real
#   runs) evicts Bullet's data here; a sparse evaluation shows what the step misses without that.
#   TCSB_PROFILE_WARMUP=w and TCSB_PROFILE_STEPS="a b" replace the 30 warm-up steps and the 10 and 30 timed steps
#   (the paper suite warms up for 120); TCSB_PROFILE_KEEP=DIR keeps the dumps there as METHOD-short.out and
#   METHOD-long.out, for scripts/profile/callgrind_functions.py DIR (b - a) (per-function calls and costs per step).
#   TCSB_PROFILE_VALGRIND_ARGS adds options to callgrind's, e.g. --branch-sim=yes (simulated mispredictions).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
width=${2:-129}
compression=${3:-0.3}
command -v valgrind >/dev/null || { echo "step-profile: valgrind is not installed" >&2; exit 2; }
if [ ! -x "$build/tcsb" ]; then
  [ -f "$build/build.ninja" ] || { echo "step-profile: $build is not a configured build directory" >&2; exit 2; }
  cmake --build "$build" --target tcsb >&2
fi
warmup=${TCSB_PROFILE_WARMUP:-30}
read -r short long <<<"${TCSB_PROFILE_STEPS:-10 30}"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

python3 - "$dir" "$width" "$compression" "${TCSB_PROFILE_EVALUATION_INTERVAL:-}" "${TCSB_PROFILE_SUITE:-scaling}" \
  "${TCSB_PROFILE_TCSB:-}" "$warmup" "$short" "$long" <<'EOF'
import json, sys
out, width, compression, interval, suite_name, tcsb = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), *sys.argv[4:7]
warmup, short, long = (int(v) for v in sys.argv[7:10])
with open(f"suites/{suite_name}.json") as f:
    scaling = json.load(f)
net = dict(scaling["nets"][0], name=f"n{width}", width=width, height=width)
for method in ("tcsb", "plain_equal"):
    for tag, steps in (("short", short), ("long", long)):
        suite = dict(scaling, name=f"step-profile-{method}-{steps}", methods=[method], compression=[compression],
                     nets=[net], repetitions=1, steps=steps, warmup_steps=warmup)
        suite["feedback"] = dict(scaling["feedback"], parallel=False)
        if interval:
            suite["feedback"]["evaluation_interval"] = int(interval)
        if tcsb:
            suite["tcsb"] = dict(scaling.get("tcsb", {}), **json.loads(tcsb))
        suite["fidelity"] = dict(scaling["fidelity"], enabled=False)
        with open(f"{out}/{method}-{tag}.json", "w") as f:
            json.dump(suite, f)
EOF

for method in tcsb plain_equal; do
  case $method in
    tcsb) toggle='*TreeCutBody::step*' ;;
    plain_equal) toggle='*StockBody::step*' ;;
  esac
  for steps in short long; do
    valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --LL=2097152,16,64 --toggle-collect="$toggle" \
      ${TCSB_PROFILE_VALGRIND_ARGS:-} --callgrind-out-file="$dir/$method-$steps.out" \
      "$build/tcsb" run "$dir/$method-$steps.json" --quiet --out "$dir/$method-$steps.result.json" >/dev/null 2>&1
  done
done
if [ -n "${TCSB_PROFILE_KEEP:-}" ]; then
  mkdir -p "$TCSB_PROFILE_KEEP"
  cp "$dir"/*.out "$dir"/*.json "$TCSB_PROFILE_KEEP"/
fi

python3 - "$dir" "$width" "$compression" "$((long - short))" <<'EOF'
import collections, json, sys
sys.path.insert(0, "scripts/profile")
from callgrind_calls import read_dump

d, width, compression = sys.argv[1], sys.argv[2], sys.argv[3]
STEPS = int(sys.argv[4])  # long - short timed steps


def totals(path):
    events = values = None
    for line in open(path):
        if line.startswith("events:"):
            events = line.split()[1:]
        elif line.startswith(("summary:", "totals:")):
            values = [int(v) for v in line.split()[1:]]
    values += [0] * (len(events) - len(values))  # callgrind leaves trailing zero counts out
    return dict(zip(events, values))


def per_step(method):
    a, b = totals(f"{d}/{method}-short.out"), totals(f"{d}/{method}-long.out")
    diff = {k: (b[k] - a[k]) / STEPS for k in b}
    result = json.load(open(f"{d}/{method}-long.result.json"))
    nodes = result["cases"][0]["mean_nodes"]
    return {"Ir": diff["Ir"], "D1": diff["D1mr"] + diff["D1mw"], "LL": diff["DLmr"] + diff["DLmw"], "nodes": nodes}


def functions(method):
    """Inclusive cost per step of named functions, from the difference of the two dumps."""
    out = {}
    for steps in ("short", "long"):
        calls, inclusive = collections.Counter(), collections.Counter()
        read_dump(f"{d}/{method}-{steps}.out", calls, inclusive)
        out[steps] = inclusive
    return out


tc, pe = per_step("tcsb"), per_step("plain_equal")
print(f"net {width}^2, budget {compression}: per timed step (steady state, difference of two runs {STEPS} timed "
      f"steps apart)")
print(f"{'':12s} {'nodes':>8s} {'Ir':>12s} {'Ir/node':>8s} {'D1 miss':>10s} {'LL miss':>10s} {'LL/node':>8s}")
for name, r in (("tcsb", tc), ("plain_equal", pe)):
    print(f"{name:12s} {r['nodes']:8.0f} {r['Ir']:12.0f} {r['Ir'] / r['nodes']:8.1f} {r['D1']:10.0f} {r['LL']:10.0f} "
          f"{r['LL'] / r['nodes']:8.3f}")
ll_ratio = f"{tc['LL'] / pe['LL']:10.3f}" if pe["LL"] >= 1 else f"{'-':>10s}"  # a body that fits misses nothing
print(f"{'ratio':12s} {tc['nodes'] / pe['nodes']:8.3f} {tc['Ir'] / pe['Ir']:12.3f} {'':8s} "
      f"{tc['D1'] / pe['D1']:10.3f} {ll_ratio}")

# Where the instructions and misses go (inclusive, per step). Names are matched as substrings of callgrind's.
# SaliencyController::evaluate runs on the worker thread in the bundled suites ("parallel": true); here it runs
# inside before_step, so before_step minus evaluate is what stays on the simulation thread.
parts = ["TcSoftBody::advance_blends", "SaliencyController::before_step", "SaliencyController::evaluate",
         "take_snapshot", "apply_evaluation", "SaliencyController::after_step",
         "TcSoftBody::begin_refine", "TcSoftBody::begin_coarse", "TcSoftBody::end_refine", "TcSoftBody::end_coarse",
         "SceneWorld::step", "btSoftBody::predictMotion", "btDbvt::update", "btSoftBody::solveConstraints",
         "btSoftBody::PSolve_Links", "btSoftBody::integrateMotion", "btSoftBody::applyClusters"]
print("inclusive per step        tcsb Ir   plain_equal Ir     tcsb D1  plain_equal D1     tcsb LL  plain_equal LL")
dumps = {m: functions(m) for m in ("tcsb", "plain_equal")}
for part in parts:
    row = []
    for method in ("tcsb", "plain_equal"):
        cost = {}
        for ev in ("Ir", "D1mr", "D1mw", "DLmr", "DLmw"):
            vals = {}
            for steps in ("short", "long"):
                vals[steps] = sum(v for (name, e), v in dumps[method][steps].items() if e == ev and part + "(" in name)
            cost[ev] = (vals["long"] - vals["short"]) / STEPS
        row.append(cost)
    if all(c["Ir"] == 0 for c in row):
        continue
    print(f"{part:32s} {row[0]['Ir']:12.0f} {row[1]['Ir']:12.0f} {row[0]['D1mr'] + row[0]['D1mw']:10.0f} "
          f"{row[1]['D1mr'] + row[1]['D1mw']:10.0f} {row[0]['DLmr'] + row[0]['DLmw']:10.0f} "
          f"{row[1]['DLmr'] + row[1]['DLmw']:10.0f}")
EOF
