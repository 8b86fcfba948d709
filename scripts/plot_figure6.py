#!/usr/bin/env python3
"""Figure 6 of the paper, redrawn from a `tcsb frames` file: plain Bullet and TC-SB side by side at a few steps.

Usage: plot_figure6.py FRAMES.json OUTDIR [NAME]
  NAME (default fig6_frames.png)
                   one column per recorded step; rows: plain Bullet (every grid node), TC-SB's surface
                   reconstructed at every grid node, TC-SB's simulated links with those an operation is replacing
                   (fading in or out, tethers, links about to go) in red
A second figure from another suite is another NAME, e.g. fig6_frames_converged.png from
`tcsb frames --suite converged --calibrated` (docs/methodology.md, "Figure 6 in the converged regime").
Reads only what `tcsb frames` wrote, so the figure shows exactly those positions. Needs matplotlib.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402


def grid_lines(points, width, height):
    """Segments along the rows and columns of a row-major grid of [x, y, z] points."""
    segments = []
    for r in range(height):
        row = points[r * width:(r + 1) * width]
        segments += [(row[c], row[c + 1]) for c in range(width - 1)]
    for c in range(width):
        segments += [(points[r * width + c], points[(r + 1) * width + c]) for r in range(height - 1)]
    return segments


def to_view(segments):
    """Bullet's y is up; matplotlib's z is: draw (x, z, y)."""
    return [[(p[0], p[2], p[1]) for p in s] for s in segments]


def draw(ax, segments, color, width):
    ax.add_collection3d(Line3DCollection(to_view(segments), colors=color, linewidths=width))


def main(frames_path, outdir, name="fig6_frames.png"):
    with open(frames_path) as f:
        doc = json.load(f)
    os.makedirs(outdir, exist_ok=True)
    net = doc["net"]
    w, h = net["width"], net["height"]
    frames = doc["frames"]
    if not frames:
        sys.exit(f"{frames_path}: no frames (status {doc['status']})")
    every = [p for fr in frames for key in ("plain", "tcsb_surface") for p in fr[key] if None not in p]
    lo = [min(p[k] for p in every) for k in range(3)]
    hi = [max(p[k] for p in every) for k in range(3)]

    rows = ["Bullet SoftBody", "TC-SB surface", "TC-SB links (red: being replaced)"]
    fig = plt.figure(figsize=(3.2 * len(frames), 3.0 * len(rows)))
    for col, fr in enumerate(frames):
        for row in range(len(rows)):
            ax = fig.add_subplot(len(rows), len(frames), row * len(frames) + col + 1, projection="3d")
            if row == 0:
                draw(ax, grid_lines(fr["plain"], w, h), "0.25", 0.3)
                ax.set_title(f"step {fr['step']} ({fr['step'] * doc['dt']:.2f} s)", fontsize=9)
            elif row == 1:
                draw(ax, grid_lines(fr["tcsb_surface"], w, h), "0.25", 0.3)
            else:
                nodes = fr["tcsb_nodes"]
                steady = [(nodes[a], nodes[b]) for a, b, role in fr["tcsb_links"] if role == "steady"]
                moving = [(nodes[a], nodes[b]) for a, b, role in fr["tcsb_links"] if role != "steady"]
                draw(ax, steady, "0.55", 0.3)
                draw(ax, moving, "red", 0.9)
                ax.text2D(0.02, 0.02, f"N = {len(nodes)}, I = {fr['interpolations']}", transform=ax.transAxes,
                          fontsize=7)
            ax.set_xlim(lo[0], hi[0])
            ax.set_ylim(lo[2], hi[2])
            ax.set_zlim(lo[1], hi[1])
            ax.view_init(elev=20, azim=-60)
            ax.set_axis_off()
            if col == 0:
                ax.text2D(-0.05, 0.5, rows[row], transform=ax.transAxes, rotation=90, va="center", fontsize=9)
    tcsb = "calibrated TC-SB" if doc.get("calibrated") else "TC-SB"
    solver = doc["suite"]["solver"]["piterations"]
    source = (f"{doc['suite']['name']} suite ({solver} solver iterations), net {net['name']} ({w} x {h}), {tcsb} at "
              f"{round(100 * doc['compression'])}% of the nodes, tcsb {doc['context']['git_commit']}")
    fig.suptitle("Figure 6: Bullet SoftBody and TC-SB at the same steps", fontsize=11)
    fig.text(0.01, 0.005, source, fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, name), dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])
