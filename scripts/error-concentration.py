#!/usr/bin/env python3
"""How local is a body's error? Reads a `tcsb frames` file and, per recorded step, reports TC-SB's RMS distance from
plain Bullet over the grid points (in % of the net's extent, as the fidelity pass measures it), the share of the
squared error that the worst WORST % of the grid points hold, and the RMS that would remain if those points were
exact.

The last figure bounds what detail can buy where the error is: a body that spent its extra nodes exactly on the
worst points of every step, and made them exact without moving any other point, would err that much. Where the
share is small the error is spread over the cloth, and no placement of detail can take it down by much.

Usage: python3 scripts/error-concentration.py FRAMES.json [--worst PCT]
       python3 scripts/error-concentration.py --self-test
Bad input: exit 2 and one line naming the file and the field.
"""
import argparse
import json
import math
import sys


class InputError(Exception):
    pass


def concentration(reference, subject, extent, worst_pct):
    """(rms %, share of the squared error in the worst points, rms % left if they were exact) of one step."""
    squared = [sum((a - b) ** 2 for a, b in zip(p, q)) for p, q in zip(reference, subject)]
    total = sum(squared)
    count = len(squared)
    rms = 100.0 * math.sqrt(total / count) / extent
    worst = sorted(squared, reverse=True)[: int(round(worst_pct / 100.0 * count))]
    share = sum(worst) / total if total > 0 else 0.0
    return rms, share, rms * math.sqrt(1.0 - share)


def field(doc, path, name):
    try:
        for key in name.split("."):
            doc = doc[int(key)] if isinstance(doc, list) else doc[key]
        return doc
    except (KeyError, IndexError, TypeError, ValueError):
        raise InputError(f"{path}: missing or malformed field '{name}'")


def points(doc, path, name):
    """The list of [x, y, z] points at field `name`: each exactly three finite numbers (a point of two coordinates
    would be measured on two silently)."""
    value = field(doc, path, name)
    if not isinstance(value, list) or not value:
        raise InputError(f"{path}: field '{name}' must be a non-empty list of [x, y, z] points")
    for k, point in enumerate(value):
        if (not isinstance(point, list) or len(point) != 3
                or not all(isinstance(c, (int, float)) and not isinstance(c, bool) and math.isfinite(c) for c in point)):
            shown = json.dumps(point)
            shown = shown if len(shown) <= 40 else shown[:37] + "..."
            raise InputError(f"{path}: field '{name}.{k}' must be a point [x, y, z] of three finite numbers, "
                             f"got {shown}")
    return value


def report(path, worst_pct):
    try:
        with open(path) as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: cannot read a JSON document ({e})")
    if field(doc, path, "kind") != "frames":
        raise InputError(f"{path}: field 'kind' is not \"frames\" (give the output of `tcsb frames`)")
    extent = field(doc, path, "net.extent")
    if not isinstance(extent, (int, float)) or isinstance(extent, bool) or not math.isfinite(extent) or extent <= 0:
        raise InputError(f"{path}: field 'net.extent' must be a positive number")
    frames = field(doc, path, "frames")
    if not isinstance(frames, list) or not frames:
        raise InputError(f"{path}: field 'frames' must be a non-empty list")
    print(f"{path}: net {field(doc, path, 'net.name')}, compression {field(doc, path, 'compression')}, "
          f"calibrated {field(doc, path, 'calibrated')}; the worst {worst_pct:g} % of the grid points")
    print(f"  {'step':>5}  {'RMS %':>7}  {'share':>6}  {'RMS % if exact':>14}")
    rows = []
    for i, frame in enumerate(frames):
        reference = points(doc, path, f"frames.{i}.plain")
        subject = points(doc, path, f"frames.{i}.tcsb_surface")
        step = field(doc, path, f"frames.{i}.step")
        if not isinstance(step, int) or isinstance(step, bool):
            raise InputError(f"{path}: field 'frames.{i}.step' must be a whole number")
        if len(reference) != len(subject):
            raise InputError(f"{path}: field 'frames.{i}.tcsb_surface' does not match 'frames.{i}.plain' in length")
        rows.append(concentration(reference, subject, extent, worst_pct))
        print(f"  {step:>5}  {rows[-1][0]:7.3f}  {rows[-1][1]:6.2f}  {rows[-1][2]:14.3f}")
    mean = [sum(r[k] for r in rows) / len(rows) for k in range(3)]
    print(f"  {'mean':>5}  {mean[0]:7.3f}  {mean[1]:6.2f}  {mean[2]:14.3f}")


def self_test():
    line = [[float(i), 0.0, 0.0] for i in range(100)]
    moved = [[p[0], 0.0, 1.0 if i < 5 else 0.0] for i, p in enumerate(line)]
    rms, share, left = concentration(line, moved, 10.0, 7.0)
    assert abs(rms - 100.0 * math.sqrt(0.05) / 10.0) < 1e-12 and share == 1.0 and left == 0.0, (rms, share, left)
    spread = [[p[0], 0.0, 1.0] for p in line]
    rms, share, left = concentration(line, spread, 10.0, 7.0)
    assert rms == 10.0 and abs(share - 0.07) < 1e-12 and abs(left - 10.0 * math.sqrt(0.93)) < 1e-12
    rms, share, left = concentration(line, line, 10.0, 7.0)
    assert (rms, share, left) == (0.0, 0.0, 0.0)
    print("error-concentration self-test: ok")


class OneLineParser(argparse.ArgumentParser):
    """Bad arguments: exit 2 and one line, as bad input (argparse prints its usage on a second line)."""

    def error(self, message):
        print(f"error-concentration: {message} (usage: python3 scripts/error-concentration.py FRAMES.json "
              f"[--worst PCT] | --self-test)", file=sys.stderr)
        sys.exit(2)


def main():
    parser = OneLineParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("frames", nargs="?", help="a `tcsb frames` file")
    parser.add_argument("--worst", type=float, default=7.0, help="percentage of the grid points (default 7)")
    parser.add_argument("--self-test", action="store_true", help="check the arithmetic on synthetic frames")
    args = parser.parse_args()
    if args.self_test:
        self_test()
        return 0
    if not args.frames or not 0 < args.worst < 100:
        print("error-concentration: give a frames file, and --worst between 0 and 100", file=sys.stderr)
        return 2
    try:
        report(args.frames, args.worst)
    except InputError as e:
        print(f"error-concentration: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
