"""Writes one suite per net of suites/paper.json, narrowed to plain Bullet on that net alone: 1 repetition, the
paper suite's own steps and warm-up, no TC-SB cases, no fidelity pass. For the profiling scripts, which run each
under valgrind. Usage: python3 scripts/profile/plain_paper_suites.py OUT_DIR [NET_NAME ...]  (default: every net); writes
OUT_DIR/<net name>.json."""
import json
import sys


def main() -> None:
    out, wanted = sys.argv[1], sys.argv[2:]
    with open("suites/paper.json") as f:
        paper = json.load(f)
    nets = [n for n in paper["nets"] if not wanted or n["name"] in wanted]
    missing = set(wanted) - {n["name"] for n in nets}
    if missing:
        print(f"plain_paper_suites: suites/paper.json has no net named {', '.join(sorted(missing))}", file=sys.stderr)
        sys.exit(2)  # bad input, as everywhere in the project; nothing written
    for net in nets:
        suite = dict(paper, name=f"plain-{net['name']}", methods=["plain"], repetitions=1, nets=[net])
        for key in ("compression", "feedback", "tcsb"):
            suite.pop(key)
        suite["fidelity"] = dict(paper["fidelity"], enabled=False)
        with open(f"{out}/{net['name']}.json", "w") as f:
            json.dump(suite, f)


if __name__ == "__main__":
    main()
