#!/usr/bin/env bash
# Work and memory traffic of plain Bullet's step, per node, for every net of suites/paper.json, counted by
# callgrind (deterministic, unlike wall time on a shared VM): instructions, and cache lines read or written from
# beyond a simulated 2 MiB last-level cache (the per-core L2 of the development VM; 48 KiB L1 in front of it).
# It answers whether a step in the per-node cost between two nets of the suite comes from the body outgrowing that
# cache: the instructions per node-step stay about level, the lines per node-step jump where the body no longer fits.
# Only the steps are counted (callgrind collects inside the plain body's step function alone), not building the
# body. Plain only, 1 repetition, the suite's own 120 warm-up + 400 timed steps per net.
# Usage: bash scripts/profile/plain-cache-profile.sh [build-dir] [net...]   (default: every net of the suite; needs
# valgrind; a few minutes per net)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
shift || true  # the rest: net names of suites/paper.json
command -v valgrind >/dev/null || { echo "plain-cache-profile: valgrind is not installed" >&2; exit 2; }
[ -x "$build/tcsb" ] || { echo "plain-cache-profile: $build/tcsb not found; build first" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# One suite per net: the paper suite narrowed to plain Bullet on that net.
python3 scripts/profile/plain_paper_suites.py "$dir" "$@"
printf '%-6s %7s %14s %18s %18s\n' net nodes "instr/node-step" "LL reads/node-step" "LL writes/node-step"
for suite in "$dir"/*.json; do
  name=$(basename "$suite" .json)
  valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --LL=2097152,16,64 \
    --toggle-collect='*StockBody::step*' --callgrind-out-file="$dir/$name.out" \
    "$build/tcsb" run "$suite" --quiet --out "$dir/$name.result.json" >/dev/null 2>&1
  python3 - "$dir/$name.out" "$suite" <<'EOF'
import json, sys
path, suite = sys.argv[1], json.load(open(sys.argv[2]))
net = suite["nets"][0]
name, nodes, steps = net["name"], net["width"] * net["height"], suite["warmup_steps"] + suite["steps"]
events = totals = None
for line in open(path):
    if line.startswith("events:"):
        events = line.split()[1:]
    elif line.startswith(("summary:", "totals:")):
        totals = [int(v) for v in line.split()[1:]]
count = dict(zip(events, totals))
node_steps = nodes * steps  # warm-up and timed steps, all collected
print(f"{name:<6} {nodes:7d} {count['Ir'] / node_steps:14.0f} {count['DLmr'] / node_steps:18.3f} "
      f"{count['DLmw'] / node_steps:18.3f}")
EOF
done
