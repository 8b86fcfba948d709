#!/usr/bin/env bash
# Callgrind over real `tcsb run`s of the paper's smallest and largest nets (n45, n81 of suites/paper.json), for the
# two questions the wall-time claims cannot answer on a noisy VM (deterministic counts, not seconds):
#  1. plain Bullet: instructions of a whole run, and of its node-DBVT upkeep (btDbvt::update, inside
#     predictMotion), per net — is plain Bullet's step superlinear in its work, or only in its memory traffic?
#     (plain only, the suite's 400 + 120 steps, 1 repetition)
#  2. TC-SB at 75 % and 30 %: instructions and cache lines fetched from beyond a simulated 2 MiB cache per
#     operation, between real steps (200 + 60 steps, 1 repetition, synchronous feedback so one thread does it all).
# The suites are copies of suites/paper.json narrowed as said (the plain ones by scripts/profile/plain_paper_suites.py),
# written to a temporary directory.
# Usage: bash scripts/profile/profile-paper-nets.sh [build-dir] [net...]   (default: n45 n81; needs valgrind; takes
# about 10 minutes with the default nets)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
shift || true
nets=("$@")  # net names of suites/paper.json
[ ${#nets[@]} -gt 0 ] || nets=(n45 n81)
command -v valgrind >/dev/null || { echo "profile-paper-nets: valgrind is not installed" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

python3 scripts/profile/plain_paper_suites.py "$dir" "${nets[@]}"
python3 - "$dir" "${nets[@]}" <<'EOF'
import json, sys
out, nets = sys.argv[1], sys.argv[2:]
paper = json.load(open("suites/paper.json"))
t = dict(paper, name="tcsb-ops", methods=["tcsb"], compression=[0.75, 0.3], repetitions=1, steps=200,
         warmup_steps=60, nets=[n for n in paper["nets"] if n["name"] in nets])
t["feedback"] = dict(paper["feedback"], parallel=False)
t["fidelity"] = dict(paper["fidelity"], enabled=False)
json.dump(t, open(f"{out}/tcsb-ops.json", "w"))
EOF
inclusive() {  # inclusive instructions of the functions whose names match $2, in callgrind file $1
  callgrind_annotate --inclusive=yes --threshold=100 "$1" 2>/dev/null | grep -E "$2" | head -3
}
for net in "${nets[@]}"; do
  valgrind --tool=callgrind --callgrind-out-file="$dir/$net.out" \
    "$build/tcsb" run "$dir/$net.json" --quiet --out "$dir/$net.result.json" >/dev/null 2>&1
  echo "plain Bullet, $net (instructions, inclusive):"
  inclusive "$dir/$net.out" 'PROGRAM TOTALS|btSoftBody::predictMotion|btDbvt::update\(btDbvtNode\*, btDbvtAabbMm&\) '
done

valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --LL=2097152,16,64 \
  --callgrind-out-file="$dir/tcsb.out" \
  "$build/tcsb" run "$dir/tcsb-ops.json" --quiet --out "$dir/tcsb.result.json" >/dev/null 2>&1
echo "TC-SB operations between real steps (${nets[*]}, 75 % and 30 %):"
python3 scripts/profile/callgrind_calls.py "$dir/tcsb.out"
