#!/usr/bin/env python3
"""Instructions and cache misses per call of the four TreeCut operations, from callgrind output files.

Usage: callgrind_calls.py [--only NAME] CALLGRIND_OUT...   (several dumps are summed)
Reads the raw callgrind format: each `cfn=` names a callee, the following `calls=N ...` line and cost line give
N calls and their inclusive cost. Prints calls and instructions (Ir) per call for begin/end refine/coarse, and with
--cache-sim=yes also last-level data misses per call (DLmr + DLmw: cache lines fetched from beyond the simulated
last-level cache). --only keeps the operation whose name contains NAME (e.g. begin_refine): a benchmark's dump
also holds the untimed operations that undo each timed one, whose lines are still warm.
"""
import collections
import re
import sys


def read_dump(path, calls, inclusive, self_cost=None):
    """Adds one dump's call counts and inclusive costs (name ids are per file); returns its event names. With
    `self_cost`, also adds each function's self cost there: the cost lines of its own block, not its calls' lines."""
    names = {}
    events = ["Ir"]
    fn = None
    callee = None
    pending = None
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("events:"):
                events = line.split()[1:]
                continue
            m = re.match(r"^(c?fn)=\((\d+)\)(?: (.*))?$", line)
            if m:
                if m.group(3):
                    names[m.group(2)] = m.group(3)
                if m.group(1) == "cfn":
                    callee = names.get(m.group(2), m.group(2))
                else:
                    fn = names.get(m.group(2), m.group(2))
                continue
            m = re.match(r"^calls=(\d+)", line)
            if m:
                pending = int(m.group(1))
                continue
            if pending is not None:
                parts = line.split()
                if len(parts) >= 2:
                    calls[callee] += pending
                    for event, value in zip(events, parts[1:]):
                        inclusive[(callee, event)] += int(value)
                pending = None
                continue
            if self_cost is not None and line and (line[0].isdigit() or line[0] in "+-*"):
                for event, value in zip(events, line.split()[1:]):
                    self_cost[(fn, event)] += int(value)
    return events


def main(args):
    only = None
    if len(args) >= 2 and args[0] == "--only":
        only, args = args[1], args[2:]
    paths = args
    calls = collections.Counter()
    inclusive = collections.Counter()
    events = []
    for path in paths:
        events = read_dump(path, calls, inclusive)
    for name in sorted(calls):
        if re.search(r"TcSoftBody::(begin_refine|begin_coarse|end_refine|end_coarse)\(", name) and (
            only is None or only in name
        ):
            n = calls[name]
            line = f"{name.split('(')[0]:40s} calls={n:7d} Ir/call={inclusive[(name, 'Ir')] / n:8.0f}"
            if "DLmr" in events:
                misses = inclusive[(name, "DLmr")] + inclusive[(name, "DLmw")]
                line += f" LL-misses/call={misses / n:6.1f}"
            print(line)


if __name__ == "__main__":
    main(sys.argv[1:])
