#!/usr/bin/env python3
"""Renders the paper's Figures 4-6 in results/figures/ from kept runs in results/runs/, as render-results.sh renders
docs/results.md, and records what they were rendered from in results/figures/manifest.json.

Usage: python3 scripts/render-figures.py [--check]
  (no option)  render every figure from its newest kept input and write the manifest; needs matplotlib (Debian:
               python3-matplotlib)
  --check      only check the manifest against the tree (no matplotlib needed): every figure's input is still the
               newest kept file that holds its data, the input's, this script's and the PNG's SHA-256 are those
               recorded. Exit 0 current, 1 stale (each stale figure named on stderr), 2 a figure has no input or a
               kept file is not a JSON document (one line naming it).

The inputs, each the newest by name (file names start with the date; reverse C collation, as render-results.sh):
  fig4_operations.png, fig5_step_time.png  results/runs/*.json of the paper suite with a reproduction and the fits
      of `scaling` (op_ms_vs_nodes, step_ms_vs_nodes): cost of each operation and step time against node count
  fig6_frames.png              results/runs/frames/*.json: `tcsb frames` of the paper suite, uncalibrated
  fig6_frames_converged.png    results/runs/frames/*.json: `tcsb frames --suite converged --calibrated`
  viewer_far.png, viewer_corner.png, viewer_drape.png
                               results/runs/frames/*.json: `tcsb frames --suite viewer-SCENE --calibrated` (a scene
      with a camera): the camera's image of plain Bullet, calibrated TC-SB (its simulated nodes coloured by LOD level
      over its reconstructed surface) and the calibrated uniform grid of the same node count, at each recorded step
  shaded_SCENE.png             results/runs/frames/*.json of SCENE (a scene with a camera, or its -compliant twin):
      the last recorded step through the camera, as shaded surfaces (one light, Lambert) of full resolution, TC-SB
      (coloured by the LOD level of its nearest simulated node) and the uniform grid, and each subject's per-point
      pixel error against full resolution as a heat map. Optional, as the Pareto figures
  pareto_SCENE.png             results/runs/*.json of SCENE (each scene suite and its -compliant twin) with
      fidelity.equal_error: error against step time, log-log, of its largest net: TC-SB across budgets, the uniform
      grids, full resolution at fewer solver passes. Optional: a scene without such a kept run has no figure (and a
      figure left from one is stale)
Usage: python3 scripts/render-figures.py --animate FRAMES GIF
               draws the same three views for every frame of FRAMES (a `tcsb frames` file of a scene with a camera)
               into an animated GIF; of a scene of many bodies (`"kind": "world_frames"`), TC-SB left and discrete
               LOD right, every body's cells through the camera coloured by LOD level. Not part of the manifest (the
               input is too large to keep; results/figures/README.md has the commands of viewer_corner.gif and
               street_flyby.gif). Exit 2 and one line for a FRAMES that is not such a file, a GIF in no directory, or
               no matplotlib, before anything is drawn
Figure 6's rows: plain Bullet (every grid node), TC-SB's surface reconstructed at every grid node, TC-SB's simulated
links with those an operation is replacing (fading in or out, tethers, links about to go) in red. The figures show
exactly the numbers in their input; PNG bytes depend on the matplotlib version, so the manifest records them only to
tell a PNG that was not rendered by this script.
"""
import hashlib
import json
import os
import sys

# The repository's root; TCSB_FIGURES_ROOT points the script at a copy (scripts/render-figures-self-test.sh).
ROOT = os.environ.get("TCSB_FIGURES_ROOT") or os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNS = os.path.join("results", "runs")
FRAMES = os.path.join(RUNS, "frames")
FIGURES = os.path.join("results", "figures")
MANIFEST = os.path.join(FIGURES, "manifest.json")
SCRIPT = os.path.join("scripts", "render-figures.py")


class BadInput(Exception):
    """A file the script cannot read (a kept run cut short, a frames file that is not one): exit 2, one line."""


def read_json(path, shown):
    """The JSON document at `path` (`shown` names it in the message); BadInput when it is not one."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:  # ValueError: JSONDecodeError, UnicodeDecodeError
        raise BadInput(f"{shown}: not a readable JSON document ({e})")


def sha256(path):
    with open(os.path.join(ROOT, path), "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def newest(directory, accepts):
    """The newest .json file of `directory` (relative to the root) whose document `accepts`, or None."""
    full = os.path.join(ROOT, directory)
    if not os.path.isdir(full):
        return None
    for name in sorted((n for n in os.listdir(full) if n.endswith(".json")), reverse=True):
        doc = read_json(os.path.join(full, name), os.path.join(directory, name))
        if not isinstance(doc, dict):
            raise BadInput(f"{os.path.join(directory, name)}: not a JSON object (a kept run or frames file is one)")
        if accepts(doc):
            return os.path.join(directory, name)
    return None


def has_paper_fits(doc):
    scaling = doc.get("scaling") or {}
    return (doc.get("suite", {}).get("name") == "paper" and "reproduction" in doc
            and bool(scaling.get("op_ms_vs_nodes")) and bool(scaling.get("step_ms_vs_nodes")))


def frames_of(suite, calibrated):
    return lambda doc: (doc.get("suite", {}).get("name") == suite and bool(doc.get("calibrated")) == calibrated
                        and bool(doc.get("frames")))


def viewer_frames_of(suite):
    accepts = frames_of(suite, True)
    return lambda doc: accepts(doc) and "camera" in doc


# Each figure: its PNG, where its input is chosen from, and how it is drawn (a function of the input and the PNG).
FIGURE_INPUTS = {
    "fig4_operations.png": (RUNS, has_paper_fits),
    "fig5_step_time.png": (RUNS, has_paper_fits),
    "fig6_frames.png": (FRAMES, frames_of("paper", False)),
    "fig6_frames_converged.png": (FRAMES, frames_of("converged", True)),
    "viewer_far.png": (FRAMES, viewer_frames_of("viewer-far")),
    "viewer_corner.png": (FRAMES, viewer_frames_of("viewer-corner")),
    "viewer_drape.png": (FRAMES, viewer_frames_of("viewer-drape")),
}


SCENES = ["converged", "drape", "ball", "flag", "viewer-far", "viewer-corner", "viewer-drape"]


def curves_of(suite):
    return lambda doc: (doc.get("suite", {}).get("name") == suite
                        and bool((doc.get("fidelity") or {}).get("equal_error", {}).get("nets")))


def camera_frames_of(suite):
    return lambda doc: doc.get("suite", {}).get("name") == suite and bool(doc.get("frames")) and "camera" in doc


# The Pareto figures: one per scene suite and twin whose kept run drew the curves, none otherwise; the shaded ones
# likewise for the scenes with a camera that have frames.
OPTIONAL_INPUTS = {f"pareto_{suite}.png": (RUNS, curves_of(suite))
                   for scene in SCENES for suite in (scene, scene + "-compliant")}
OPTIONAL_INPUTS.update({f"shaded_{suite}.png": (FRAMES, camera_frames_of(suite))
                        for scene in SCENES if scene.startswith("viewer-")
                        for suite in (scene, scene + "-compliant")})


def chosen_inputs():
    """{png: input path or None}: what each figure must be rendered from today (optional ones only when they have
    an input)."""
    inputs = {png: newest(directory, accepts) for png, (directory, accepts) in FIGURE_INPUTS.items()}
    for png, (directory, accepts) in OPTIONAL_INPUTS.items():
        path = newest(directory, accepts)
        if path is not None:
            inputs[png] = path
    return inputs


def plot_fits(ax, fits, label_of, scale=1.0):
    for fit in fits:
        points = fit.get("points", [])
        if not points:
            continue
        xs = [p["nodes"] for p in points]
        ys = [p["ms"] * scale for p in points]
        line = ax.plot(xs, ys, "o", label=label_of(fit))[0]
        if fit.get("valid") and fit.get("slope_ms_per_node") is not None:
            lo, hi = min(xs), max(xs)
            a, b = fit["intercept_ms"] * scale, fit["slope_ms_per_node"] * scale
            r2 = fit.get("r2")
            ax.plot([lo, hi], [a + b * lo, a + b * hi], "-", color=line.get_color(), alpha=0.6,
                    label=f"  fit, R² = {r2:.3f}" if r2 is not None else "  fit")


def source_line(result):
    context = result["context"]
    return (f"{result['suite']['name']} suite, {context['date_utc']}, {context['cpu_model']}, "
            f"tcsb {context.get('git_commit', '?')}")


def step_label(fit):
    # plain_equal has one fit per budget, like TC-SB: without the budget its two lines would share a label.
    c = fit.get("compression")
    if c is None:
        return fit["method"]
    return f"{fit['method']} NoCompression" if c == 1.0 else f"{fit['method']} {round(100 * c)}%"


def draw_fits(plt, result, png, fits, label_of, scale, xlabel, ylabel, title):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    plot_fits(ax, fits, label_of, scale)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    fig.text(0.01, 0.01, source_line(result), fontsize=6)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)


def figure4(plt, result, png):
    draw_fits(plt, result, png, result["scaling"]["op_ms_vs_nodes"], lambda fit: fit["operation"], 1000.0,
              "Bullet nodes present (N)", "cost of one operation [µs]",
              "Figure 4: TreeCut operations against node count")


def figure5(plt, result, png):
    draw_fits(plt, result, png, result["scaling"]["step_ms_vs_nodes"], step_label, 1.0, "simulated nodes (N)",
              "step time [ms]", "Figure 5: step time against node count")


def grid_lines(points, width, height):
    """Segments along the rows and columns of a row-major grid of [x, y, z] points."""
    segments = []
    for r in range(height):
        row = points[r * width:(r + 1) * width]
        segments += [(row[c], row[c + 1]) for c in range(width - 1)]
    for c in range(width):
        segments += [(points[r * width + c], points[(r + 1) * width + c]) for r in range(height - 1)]
    return segments


def figure6(plt, doc, png):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    def draw(ax, segments, color, width):  # Bullet's y is up; matplotlib's z is: draw (x, z, y)
        view = [[(p[0], p[2], p[1]) for p in s] for s in segments]
        ax.add_collection3d(Line3DCollection(view, colors=color, linewidths=width))

    net = doc["net"]
    w, h = net["width"], net["height"]
    frames = doc["frames"]
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
                draw(ax, [(nodes[a], nodes[b]) for a, b, role in fr["tcsb_links"] if role == "steady"], "0.55", 0.3)
                draw(ax, [(nodes[a], nodes[b]) for a, b, role in fr["tcsb_links"] if role != "steady"], "red", 0.9)
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
    fig.savefig(png, dpi=110)
    plt.close(fig)


def on_image(doc, frame, points):
    """Where the frame's camera shows each [x, y, z] point: pixel columns and rows (NaN behind the near plane)."""
    import numpy as np
    camera, pose = doc["camera"], frame["camera"]
    eye = np.array(pose["position"], float)
    forward = np.array(pose["target"], float) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, camera["up"])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    width, height = camera["image"]
    focal = 0.5 * height / np.tan(np.radians(camera["fov_deg"]) / 2)  # as src/feedback/screen_projection.cpp
    d = np.array([[np.nan] * 3 if None in p else p for p in points], float) - eye
    depth = d @ forward
    depth[depth < 0.01] = np.nan
    return width / 2 + focal * (d @ right) / depth, height / 2 - focal * (d @ up) / depth


def draw_views(plt, doc, frame, axes):
    """The camera's image of plain Bullet, TC-SB and the uniform grid at one frame, on three axes."""
    from matplotlib.collections import LineCollection

    def lines(ax, points, w, h, color, width):
        x, y = on_image(doc, frame, points)
        ax.add_collection(LineCollection([[(x[a], y[a]), (x[b], y[b])] for a, b in grid_index_pairs(w, h)],
                                         colors=color, linewidths=width))

    net, grid = doc["net"], doc["uniform_grid"]
    width, height = doc["camera"]["image"]
    lines(axes[0], frame["plain"], net["width"], net["height"], "0.2", 0.3)
    lines(axes[1], frame["tcsb_surface"], net["width"], net["height"], "0.75", 0.3)
    x, y = on_image(doc, frame, frame["tcsb_nodes"])
    levels = frame["tcsb_levels"]
    dots = axes[1].scatter(x, y, c=levels, s=2, cmap="viridis", vmin=0, vmax=max(3, max(levels)))
    lines(axes[2], frame["uniform_nodes"], grid["width"], grid["height"], "0.2", 0.4)
    for ax in axes:
        ax.set_xlim(0, width)
        ax.set_ylim(height, 0)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
    return dots


def grid_index_pairs(width, height):
    """Index pairs of the segments along the rows and columns of a row-major width x height grid."""
    pairs = [(r * width + c, r * width + c + 1) for r in range(height) for c in range(width - 1)]
    return pairs + [(r * width + c, (r + 1) * width + c) for c in range(width) for r in range(height - 1)]


VIEW_TITLES = ["Bullet SoftBody, full resolution", "calibrated TC-SB (nodes by LOD level)",
               "calibrated uniform grid, same node count"]


def viewer_source(doc):
    net = doc["net"]
    return (f"{doc['suite']['name']} suite, net {net['name']} ({net['width']} x {net['height']}), "
            f"{round(100 * doc['compression'])}% of the nodes, camera image {doc['camera']['image'][0]} x "
            f"{doc['camera']['image'][1]}, tcsb {doc['context']['git_commit']}")


def figure_viewer(plt, doc, png):
    frames = doc["frames"]
    fig, axes = plt.subplots(len(frames), 3, figsize=(12, 0.6 + 2.2 * len(frames)), squeeze=False)
    for row, frame in enumerate(frames):
        dots = draw_views(plt, doc, frame, axes[row])
        axes[row][0].set_ylabel(f"step {frame['step']}\n({frame['step'] * doc['dt']:.2f} s)", fontsize=8)
    for col, title in enumerate(VIEW_TITLES):
        axes[0][col].set_title(title, fontsize=9)
    fig.colorbar(dots, ax=axes.ravel().tolist(), label="TC-SB's LOD level", shrink=0.8)
    fig.suptitle("What the camera sees", fontsize=11)
    fig.text(0.01, 0.005, viewer_source(doc), fontsize=7)
    fig.savefig(png, dpi=100)
    plt.close(fig)


def animate(frames_path, gif):
    # The input and the output's place first, then matplotlib: bad input is exit 2 before anything is drawn.
    doc = read_json(frames_path, frames_path)
    if not isinstance(doc, dict) or "camera" not in doc or not isinstance(doc.get("frames"), list) or not doc["frames"]:
        raise BadInput(f"{frames_path}: not frames of a scene with a camera (`tcsb frames --suite viewer-...`, or of "
                       f"a scene of many bodies, `--suite street`)")
    world = doc.get("kind") == "world_frames"
    if world and not all(isinstance(doc.get(key), list) and doc[key] for key in ("bodies", "methods")):
        raise BadInput(f"{frames_path}: world frames without bodies or methods (`tcsb frames` of a scene of many "
                       f"bodies writes both)")
    if not os.path.isdir(os.path.dirname(os.path.abspath(gif))):
        raise BadInput(f"{gif}: its directory does not exist")
    try:
        import matplotlib
    except ImportError:
        raise BadInput("--animate needs matplotlib, which is not installed (Debian: apt-get install "
                       "python3-matplotlib)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation, PillowWriter
    try:
        fig, draw, dpi = (world_animation if world else viewer_animation)(plt, doc)
        FuncAnimation(fig, draw, frames=len(doc["frames"])).save(gif, writer=PillowWriter(fps=10), dpi=dpi)
    except (KeyError, IndexError, TypeError, ValueError) as e:
        raise BadInput(f"{frames_path}: a frame lacks what the views need ({type(e).__name__}: {e})")
    plt.close(fig)
    print(f"render-figures: {gif} from {frames_path}", file=sys.stderr)
    return 0


def viewer_animation(plt, doc):
    """A viewer suite's frames: full resolution, TC-SB and the uniform grid side by side (figure_viewer's views)."""
    fig, axes = plt.subplots(1, 3, figsize=(10, 2.3))

    def draw(i):
        for ax in axes:
            ax.clear()
        frame = doc["frames"][i]
        draw_views(plt, doc, frame, axes)
        for ax, title in zip(axes, VIEW_TITLES):
            ax.set_title(title, fontsize=8)
        axes[0].set_ylabel(f"{frame['step'] * doc['dt']:.2f} s", fontsize=8)

    return fig, draw, 70


def world_level_labels(doc):
    """The legend's levels: 0 to the coarsest any frame holds (at least discrete LOD's 0..3), each a quarter of the
    nodes of the one before (TC-SB's level k: blocks of 2^k x 2^k grid points)."""
    coarsest = max([3] + [max(body["levels"]) for frame in doc["frames"] for scene in frame["scenes"]
                          for body in scene["bodies"]])
    return ["LOD level 0: full resolution"] + [f"{k}: 1/{4 ** k} of the nodes" for k in range(1, coarsest + 1)]


WORLD_METHOD_TITLES = {"tcsb_world": "TC-SB, one budget for the scene", "tcsb_body": "TC-SB, a budget per body",
                       "discrete_lod": "discrete LOD, switched by distance"}


def world_cells(doc, frame, scene, colours):
    """Every body's grid cells on the frame's image, all bodies together: corners, depth and colour (its level's,
    lightly shaded as shade() lights it). A cell takes the level of its first corner's block, the block holding it."""
    import numpy as np
    corners, depth, cell_colours = [], [], []
    for body, data in zip(doc["bodies"], scene["bodies"]):
        points = np.asarray(data["xyz"], float).reshape(-1, 3)
        quads, c, d, brightness = shade(doc, frame, points, body["width"], body["height"])
        rgba = colours[np.asarray(data["levels"], int)[quads[:, 0]]]
        rgba[:, :3] *= 0.6 + 0.4 * brightness[:, None]  # lightly shaded: the level's colour stays readable
        corners.append(c)
        depth.append(d)
        cell_colours.append(rgba)
    return np.concatenate(corners), np.concatenate(depth), np.concatenate(cell_colours)


def world_animation(plt, doc):
    """A scene of many bodies' world frames: TC-SB left, discrete LOD right, each banner's cells through the camera
    coloured by level, near banners hiding far ones (draw_cells' painter's order)."""
    import numpy as np
    from matplotlib import cm
    from matplotlib.patches import Patch
    width, height = doc["camera"]["image"]
    methods = [m["method"] for m in doc["methods"]]
    labels = world_level_labels(doc)
    colours = cm.turbo(np.linspace(0.9, 0.15, len(labels)))  # fine warm, coarse cool
    fig, axes = plt.subplots(1, len(methods), figsize=(9, 3.0))
    fig.subplots_adjust(left=0.01, right=0.99, top=0.84, bottom=0.1, wspace=0.03)
    fig.legend([Patch(color=c) for c in colours], labels, loc="lower center", ncol=len(colours), fontsize=7,
               frameon=False)
    budget = round(100 * doc["compression"])

    def draw(i):
        frame = doc["frames"][i]
        for ax, method, scene in zip(axes, methods, frame["scenes"]):
            ax.clear()
            corners, depth, cell_colours = world_cells(doc, frame, scene, colours)
            # Cells wholly off the image would only cost drawing time.
            x, y = corners[..., 0], corners[..., 1]
            seen = (x.max(axis=1) >= 0) & (x.min(axis=1) <= width) & (y.max(axis=1) >= 0) & (y.min(axis=1) <= height)
            draw_cells(ax, corners[seen], depth[seen], cell_colours[seen], antialiased=False)
            ax.set_facecolor("0.93")
            ax.set_xlim(0, width)
            ax.set_ylim(height, 0)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title(f"{WORLD_METHOD_TITLES.get(method, method)}: {scene['nodes']} nodes", fontsize=8)
        fig.suptitle(f"{doc['suite']['name']}, {len(doc['bodies'])} bodies, budget {budget} % of the nodes: "
                     f"{frame['step'] * doc['dt']:.2f} s", fontsize=9)

    return fig, draw, 100


def grid_quads(width, height):
    """Corner indices of the cells of a row-major width x height grid, counter-clockwise."""
    import numpy as np
    r, c = np.meshgrid(np.arange(height - 1), np.arange(width - 1), indexing="ij")
    a = (r * width + c).ravel()
    return np.stack([a, a + 1, a + 1 + width, a + width], axis=1)


def resample_grid(points, src_w, src_h, dst_w, dst_h):
    """Bilinear resampling of a src_w x src_h grid of points onto dst_w x dst_h (as src/net/grid_resample.h)."""
    import numpy as np
    p = np.asarray(points, float).reshape(src_h, src_w, 3)
    u = np.linspace(0, src_w - 1, dst_w)
    v = np.linspace(0, src_h - 1, dst_h)
    c0 = np.minimum(np.floor(u).astype(int), src_w - 2)
    r0 = np.minimum(np.floor(v).astype(int), src_h - 2)
    fu = (u - c0)[None, :, None]
    fv = (v - r0)[:, None, None]
    a = p[r0][:, c0]
    b = p[r0][:, c0 + 1]
    c = p[r0 + 1][:, c0]
    d = p[r0 + 1][:, c0 + 1]
    return ((1 - fv) * ((1 - fu) * a + fu * b) + fv * ((1 - fu) * c + fu * d)).reshape(-1, 3)


def shade(doc, frame, points, width, height):
    """Per cell of the grid: its corners on the image, its depth and its Lambert brightness (one light from behind
    the camera's right shoulder, two-sided: cloth has no outside)."""
    import numpy as np
    p = np.asarray(points, float)
    quads = grid_quads(width, height)
    x, y = on_image(doc, frame, p)
    corners = np.stack([x[quads], y[quads]], axis=2)
    pose = frame["camera"]
    eye = np.array(pose["position"], float)
    forward = np.array(pose["target"], float) - eye
    forward /= np.linalg.norm(forward)
    light = -forward + 0.5 * np.cross(forward, doc["camera"]["up"]) + 0.5 * np.array(doc["camera"]["up"], float)
    light /= np.linalg.norm(light)
    normal = np.cross(p[quads[:, 2]] - p[quads[:, 0]], p[quads[:, 3]] - p[quads[:, 1]])
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-12)
    brightness = 0.2 + 0.8 * np.abs(normal @ light)
    depth = (p[quads].mean(axis=1) - eye) @ forward
    return quads, corners, depth, brightness


def draw_cells(ax, corners, depth, colors, antialiased=True):
    """The cells in front of the camera, far ones first (the painter's order); without antialiasing no seams show
    between neighbouring cells."""
    import numpy as np
    from matplotlib.collections import PolyCollection
    keep = np.isfinite(corners).all(axis=(1, 2)) & np.isfinite(depth)
    order = np.argsort(-depth[keep])
    ax.add_collection(PolyCollection(corners[keep][order], facecolors=colors[keep][order], edgecolors="none",
                                     antialiased=antialiased))


def figure_shaded(plt, doc, png):
    import numpy as np
    from matplotlib import cm
    from matplotlib.colors import Normalize
    frame = doc["frames"][-1]
    net, grid = doc["net"], doc["uniform_grid"]
    w, h = net["width"], net["height"]
    width, height = doc["camera"]["image"]
    reference = np.asarray(frame["plain"], float)
    uniform = resample_grid(frame["uniform_nodes"], grid["width"], grid["height"], w, h)
    surfaces = [reference, np.asarray(frame["tcsb_surface"], float), uniform]
    fig, axes = plt.subplots(2, 3, figsize=(13, 6.2))
    # TC-SB's levels: each grid point takes the level of its nearest simulated node.
    nodes = np.asarray(frame["tcsb_nodes"], float)
    levels = np.asarray(frame["tcsb_levels"])
    nearest = np.argmin(((surfaces[1][:, None, :] - nodes[None, :, :]) ** 2).sum(axis=2), axis=1)
    level_norm = Normalize(0, max(3, int(levels.max())))
    rx, ry = on_image(doc, frame, reference)
    errors = []
    for k, points in enumerate(surfaces):
        quads, corners, depth, brightness = shade(doc, frame, points, w, h)
        if k == 1:
            cell_level = np.round(levels[nearest][quads].mean(axis=1))
            colors = cm.viridis(level_norm(cell_level))
        else:
            colors = np.tile(np.array([0.75, 0.75, 0.78, 1.0]), (len(quads), 1))
        colors[:, :3] *= brightness[:, None]
        draw_cells(axes[0][k], corners, depth, colors)
        if k > 0:
            x, y = on_image(doc, frame, points)
            errors.append((np.hypot(x - rx, y - ry), quads, corners, depth))
    finite = np.concatenate([e[0][np.isfinite(e[0])] for e in errors])
    err_norm = Normalize(0, max(1.0, float(np.percentile(finite, 99)) if finite.size else 1.0))
    for k, (err, quads, corners, depth) in enumerate(errors, start=1):
        draw_cells(axes[1][k], corners, depth, cm.magma(err_norm(err[quads].mean(axis=1))))
        inside = np.isfinite(rx) & (rx >= 0) & (rx < width) & (ry >= 0) & (ry < height) & np.isfinite(err)
        shown = err[inside]
        axes[1][k].set_title(f"pixel error: mean {shown.mean():.1f}, p95 {np.percentile(shown, 95):.1f} px"
                             if shown.size else "no point in view", fontsize=8)
    titles = ["full resolution (the reference)", "TC-SB, coloured by LOD level", "uniform grid, same node count"]
    # The part of the image the cloth covers (the reference's points in view, a margin around them), same aspect.
    seen = np.isfinite(rx) & np.isfinite(ry) & (rx >= 0) & (rx < width) & (ry >= 0) & (ry < height)
    x0, x1, y0, y1 = 0.0, float(width), 0.0, float(height)
    if seen.any():
        cx, cy = 0.5 * (rx[seen].min() + rx[seen].max()), 0.5 * (ry[seen].min() + ry[seen].max())
        half = 0.6 * max(rx[seen].max() - rx[seen].min(), (ry[seen].max() - ry[seen].min()) * width / height, 1.0)
        x0, x1 = max(0.0, cx - half), min(float(width), cx + half)
        y0, y1 = max(0.0, cy - half * height / width), min(float(height), cy + half * height / width)
    for k, ax in enumerate(axes.ravel()):
        ax.set_xlim(x0, x1)
        ax.set_ylim(y1, y0)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        if k < 3:
            ax.set_title(titles[k], fontsize=9)
    axes[1][0].axis("off")
    axes[1][0].text(0.02, 0.5, "Below each subject: how far each of its\ngrid points lies from the reference's on\n"
                    "the image, in pixels (the error the\nspectator sees).", fontsize=9, va="center",
                    transform=axes[1][0].transAxes)
    fig.colorbar(cm.ScalarMappable(norm=level_norm, cmap="viridis"), ax=axes[0].tolist(), label="LOD level",
                 shrink=0.8)
    fig.colorbar(cm.ScalarMappable(norm=err_norm, cmap="magma"), ax=axes[1].tolist(), label="pixels", shrink=0.8)
    model = (doc["suite"].get("material") or {}).get("model", "bullet")
    fig.suptitle(f"{doc['suite']['name']} ({model}{', calibrated' if doc.get('calibrated') else ''}) at step "
                 f"{frame['step']}, through its camera", fontsize=11)
    fig.text(0.01, 0.005, viewer_source(doc), fontsize=7)
    fig.savefig(png, dpi=90)
    plt.close(fig)


def largest_net(doc):
    """The equal_error net with the most nodes (the headline's), as render-results.sh's rows choose it."""
    nodes = {n["name"]: n.get("nodes", 0) for n in doc["suite"].get("nets", [])}
    best = None
    for net in doc["fidelity"]["equal_error"]["nets"]:
        if best is None or nodes.get(net["net"], 0) >= nodes.get(best["net"], 0):
            best = net
    return best


def figure_pareto(plt, doc, png):
    net = largest_net(doc)
    unit = "p95 pixel error (mean over steps)" if net["metric"] == "p95_px" else "RMS error, % of the extent"
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    curves = net["curves"]
    styles = [("uniform_grid", "uniform grids (full resolution finest)", "s-", "tab:gray"),
              ("full_resolution", "full resolution, fewer passes", "^-", "tab:blue"),
              ("tcsb", "TC-SB across budgets", "o-", "tab:red")]
    for key, label, style, color in styles:
        points = curves.get(key, [])
        if not points:
            continue
        ax.plot([p["time_ms"] for p in points], [p["error"] for p in points], style, color=color, label=label)
        for p in points:
            if p["method"] == "reference":
                text = "reference"
            elif p["method"] == "full_resolution":
                text = f"÷{p['solver_divisor']}"
            else:
                text = f"{round(100 * p['compression'])}%"
            ax.annotate(text, (p["time_ms"], p["error"]), fontsize=6, xytext=(3, 3), textcoords="offset points",
                        color=color)
    ax.axhline(net["floor"], color="k", lw=0.5, ls=":", label="noise floor")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("step time [ms] (median over the pass's blocks)")
    ax.set_ylabel(unit)
    model = (doc["suite"].get("material") or {}).get("model", "bullet")
    ax.set_title(f"{doc['suite']['name']} ({model}), net {net['net']}: error against step time", fontsize=10)
    ax.legend(fontsize=7)
    fig.text(0.01, 0.01, source_line(doc), fontsize=6)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


DRAW = {"fig4_operations.png": figure4, "fig5_step_time.png": figure5, "fig6_frames.png": figure6,
        "fig6_frames_converged.png": figure6, "viewer_far.png": figure_viewer, "viewer_corner.png": figure_viewer,
        "viewer_drape.png": figure_viewer, **{png: figure_pareto if png.startswith("pareto_") else figure_shaded for png in OPTIONAL_INPUTS}}


def missing_inputs(inputs):
    missing = [png for png, path in inputs.items() if path is None and png not in OPTIONAL_INPUTS]
    for png in missing:
        directory = FIGURE_INPUTS[png][0]
        print(f"render-figures: no kept file in {directory}/ holds the data of {png}", file=sys.stderr)
    return bool(missing)


def render():
    try:
        import matplotlib
    except ImportError:
        print("render-figures: matplotlib is not installed (Debian: apt-get install python3-matplotlib)",
              file=sys.stderr)
        return 2
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    inputs = chosen_inputs()
    if missing_inputs(inputs):
        return 2
    figures = {}
    for png, path in inputs.items():
        doc = read_json(os.path.join(ROOT, path), path)
        DRAW[png](plt, doc, os.path.join(ROOT, FIGURES, png))
        figures[png] = {"from": path, "from_sha256": sha256(path), "png_sha256": sha256(os.path.join(FIGURES, png))}
        print(f"render-figures: {FIGURES}/{png} from {path}", file=sys.stderr)
    # An optional figure whose input left the tree leaves with it.
    try:
        with open(os.path.join(ROOT, MANIFEST)) as f:
            previous = json.load(f).get("figures", {})
    except (OSError, ValueError):
        previous = {}
    for png in previous:
        if png not in figures and os.path.exists(os.path.join(ROOT, FIGURES, png)):
            os.remove(os.path.join(ROOT, FIGURES, png))
    manifest = {"script": SCRIPT, "script_sha256": sha256(SCRIPT), "figures": figures}
    with open(os.path.join(ROOT, MANIFEST) + ".tmp", "w") as f:
        json.dump(manifest, f, indent=2)
        f.write("\n")
    os.replace(os.path.join(ROOT, MANIFEST) + ".tmp", os.path.join(ROOT, MANIFEST))
    return 0


def stale_reasons(manifest, inputs):
    """One reason per figure the manifest does not vouch for today (empty: all current)."""
    reasons = []
    if manifest.get("script_sha256") != sha256(SCRIPT):
        reasons.append(f"{SCRIPT} changed since the figures were rendered")
    recorded = manifest.get("figures", {})
    for png, path in inputs.items():
        entry = recorded.get(png)
        png_path = os.path.join(FIGURES, png)
        if entry is None:
            reasons.append(f"{png_path} is not in {MANIFEST}")
        elif entry.get("from") != path:
            reasons.append(f"{png_path} was rendered from {entry.get('from')}; the newest input is {path}")
        elif entry.get("from_sha256") != sha256(path):
            reasons.append(f"{path} changed since {png_path} was rendered from it")
        elif not os.path.exists(os.path.join(ROOT, png_path)):
            reasons.append(f"{png_path} is missing")
        elif entry.get("png_sha256") != sha256(png_path):
            reasons.append(f"{png_path} is not the PNG this script rendered")
    for png in recorded:
        if png not in inputs:
            reasons.append(f"{os.path.join(FIGURES, png)} has no kept input any more")
    return reasons


def check():
    inputs = chosen_inputs()
    if missing_inputs(inputs):
        return 2
    try:
        with open(os.path.join(ROOT, MANIFEST)) as f:
            manifest = json.load(f)
    except (OSError, ValueError) as e:
        print(f"render-figures: {MANIFEST}: {e}", file=sys.stderr)
        return 1
    reasons = stale_reasons(manifest, inputs)
    for reason in reasons:
        print(f"render-figures: stale: {reason}; run: python3 {SCRIPT}", file=sys.stderr)
    return 1 if reasons else 0


def main(args):
    try:
        if args == ["--check"]:
            return check()
        if len(args) == 3 and args[0] == "--animate":
            return animate(args[1], args[2])
        if args:
            raise BadInput(f"unknown arguments {' '.join(args)} (usage: python3 {SCRIPT} [--check | --animate FRAMES "
                           f"GIF]; more in the script's opening comment)")
        return render()
    except BadInput as e:
        print(f"render-figures: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
