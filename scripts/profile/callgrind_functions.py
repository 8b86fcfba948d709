#!/usr/bin/env python3
"""Per-function costs per step from pairs of callgrind dumps (step-profile.sh with TCSB_PROFILE_KEEP=DIR).

Usage: callgrind_functions.py DIR [STEPS] [PATTERNS] [EVENTS]
DIR holds {tcsb,plain_equal}-{short,long}.out; STEPS (default 20) is the number of timed steps between the short and
the long run, so each figure is (long - short) / STEPS: a steady-state step, warm-up and convergence cancelled.
For every function whose name contains one of PATTERNS (comma-separated; default: btDbvt,btSoftBody,TcSoftBody)
prints, per step and for both bodies: calls, self instructions (Ir), self EVENTS, inclusive Ir and inclusive EVENTS.
EVENTS (default D1mr+D1mw, the D1 misses) sums callgrind events, e.g. Bcm+Bim for mispredicted branches (with
--branch-sim=yes).
Self costs are the cost lines of a function's own block; inclusive costs are the calls' lines summed by callee; both
come from one pass of callgrind_calls.read_dump, so a recursive function's inclusive figure counts its nested calls
again.
"""
import collections
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from callgrind_calls import read_dump  # noqa: E402


def costs(path):
    calls, inclusive, self_cost = collections.Counter(), collections.Counter(), collections.Counter()
    read_dump(path, calls, inclusive, self_cost)
    return calls, inclusive, self_cost


def main(args):
    d = args[0]
    steps = float(args[1]) if len(args) > 1 else 20.0
    patterns = args[2].split(",") if len(args) > 2 and args[2] else ["btDbvt", "btSoftBody", "TcSoftBody"]
    events = args[3].split("+") if len(args) > 3 else ["D1mr", "D1mw"]
    per = {}
    for method in ("tcsb", "plain_equal"):
        (c0, i0, s0), (c1, i1, s1) = costs(f"{d}/{method}-short.out"), costs(f"{d}/{method}-long.out")
        per[method] = ({k: (c1[k] - c0[k]) / steps for k in set(c0) | set(c1)},
                       {k: (i1[k] - i0[k]) / steps for k in set(i0) | set(i1)},
                       {k: (s1[k] - s0[k]) / steps for k in set(s0) | set(s1)})
    names = set()
    for calls, inclusive, self_cost in per.values():
        names |= {n for (n, _) in self_cost} | {n for (n, _) in inclusive}
    names = sorted(n for n in names if n and any(p in n for p in patterns))

    def d1(table, name):
        return sum(table.get((name, e), 0) for e in events)

    print(f"{'function':60s} {'calls tc':>9s} {'calls pe':>9s} {'self Ir tc':>11s} {'self Ir pe':>11s} "
          f"{'self* tc':>9s} {'self* pe':>9s} {'incl Ir tc':>11s} {'incl Ir pe':>11s} {'incl* tc':>9s} "
          f"{'incl* pe':>9s}   (* = {'+'.join(events)})")
    rows = []
    for n in names:
        tc, pe = per["tcsb"], per["plain_equal"]
        row = (tc[0].get(n, 0), pe[0].get(n, 0), tc[2].get((n, "Ir"), 0), pe[2].get((n, "Ir"), 0), d1(tc[2], n),
               d1(pe[2], n), tc[1].get((n, "Ir"), 0), pe[1].get((n, "Ir"), 0), d1(tc[1], n), d1(pe[1], n))
        if max(abs(v) for v in row[2:4] + row[6:8]) < 100:
            continue
        rows.append((n, row))
    rows.sort(key=lambda r: -max(r[1][6], r[1][7]))
    for n, row in rows:
        short = n if len(n) <= 60 else n[:57] + "..."
        print(f"{short:60s} {row[0]:9.1f} {row[1]:9.1f} {row[2]:11.0f} {row[3]:11.0f} {row[4]:9.0f} {row[5]:9.0f} "
              f"{row[6]:11.0f} {row[7]:11.0f} {row[8]:9.0f} {row[9]:9.0f}")


if __name__ == "__main__":
    main(sys.argv[1:])
