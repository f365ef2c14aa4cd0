"""The figures of `tendril plot`: learning curves and episode snapshots (CSV columns: tables.py)."""
import os

import matplotlib
import matplotlib.patches
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .episode import read_episode  # noqa: E402
from .runs import PlotError, aggregate, curve, expand_runs, seed_group  # noqa: E402

METRIC_LABELS = {
    "rollout/ep_rew_mean": "mean training episode return (last 100)",
    "eval": "evaluation mean return",
}
X_LABELS = {"time/total_timesteps": "environment steps", "time/time_elapsed": "wall time (s)"}


def new_figure(size):
    figure, axes = plt.subplots(figsize=size, constrained_layout=True)
    axes.grid(True, color="#dddddd", linewidth=0.6)
    axes.set_axisbelow(True)
    return figure, axes


def short_number(value, _position=None):
    magnitude = abs(value)
    if magnitude >= 1e6:
        return f"{value / 1e6:g}M"
    if magnitude >= 1e3:
        return f"{value / 1e3:g}k"
    return f"{value:g}"


def finish(figure, axes, args, xlabel, ylabel):
    if not getattr(args, "logx", False):
        axes.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(short_number))
    axes.set_xlabel(args.xlabel or xlabel)
    axes.set_ylabel(args.ylabel or ylabel)
    if args.title:
        axes.set_title(args.title)
    if getattr(args, "logx", False):
        axes.set_xscale("log")
    if getattr(args, "logy", False):
        axes.set_yscale("symlog" if args.logy == "symlog" else "log")
    if axes.get_legend_handles_labels()[0]:
        axes.legend(frameon=False, fontsize="small")
    save(figure, args.out, args.dpi)


def save(figure, out, dpi):
    extension = os.path.splitext(out)[1].lower()
    if extension not in (".png", ".svg", ".pdf"):
        raise PlotError(f"{out}: the figure's file must end in .png, .svg or .pdf")
    directory = os.path.dirname(out)
    if directory:
        os.makedirs(directory, exist_ok=True)
    figure.savefig(out, dpi=dpi)
    plt.close(figure)
    print(out)


def curves(args):
    runs = expand_runs(args.runs)
    labels = args.labels.split(",") if args.labels else None
    figure, axes = new_figure(args.size)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    groups = {}
    for run in runs:
        path = os.path.normpath(run)
        parent = os.path.basename(os.path.dirname(os.path.abspath(path)))
        key = seed_group(os.path.basename(path), parent) if args.group == "seeds" else run
        groups.setdefault(key, []).append(run)
    if labels and len(labels) != len(groups):
        raise PlotError(f"--labels names {len(labels)} curves, there are {len(groups)}: "
                        + ", ".join(os.path.basename(os.path.normpath(k)) for k in groups))
    for i, (key, members) in enumerate(groups.items()):
        colour = colours[i % len(colours)]
        data = [curve(run, args.metric, args.x) for run in members]
        name = labels[i] if labels else os.path.basename(os.path.normpath(key))
        if len(members) == 1:
            one = data[0]
            axes.plot(one["x"], one["y"], color=colour, lw=1.6, label=name)
            if "std" in one and args.spread != "none":
                axes.fill_between(one["x"], one["y"] - one["std"], one["y"] + one["std"],
                                  color=colour, alpha=0.2, lw=0)
            continue
        stats = aggregate(data)
        band = {"std": " ± std", "minmax": ", min–max"}.get(args.spread, "")
        axes.plot(stats["x"], stats["mean"], color=colour, lw=1.8,
                  label=f"{name}: mean{band} of {stats['n']} seeds")
        if args.spread == "std":
            axes.fill_between(stats["x"], stats["mean"] - stats["std"], stats["mean"] + stats["std"],
                              color=colour, alpha=0.2, lw=0)
        elif args.spread == "minmax":
            axes.fill_between(stats["x"], stats["min"], stats["max"], color=colour, alpha=0.2, lw=0)
        if args.seeds:
            for one in data:
                axes.plot(one["x"], one["y"], color=colour, lw=0.6, alpha=0.5)
    ylabel = METRIC_LABELS.get(args.metric, args.metric)
    if args.metric == "eval" and len(runs) == len(groups) and args.spread != "none":
        ylabel += " ± std"
    finish(figure, axes, args, X_LABELS.get(args.x, args.x), ylabel)


# Display axes for each lab axis that may point up: cyclic (right-handed) orders of x, y, z.
_ORDERS = {"z": (0, 1, 2), "y": (2, 0, 1), "x": (1, 2, 0)}


def up_axis(ep, requested):
    """The lab axis drawn upwards: as requested, or with "auto" the one along which the first
    rod runs from base to tip at the start (PyElastica's arms grow along y), else z."""
    if requested != "auto":
        return requested
    for frame in ep.frames[:1]:
        for rod in frame["rods"]:
            span = rod["points"][-1] - rod["points"][0]
            return "xyz"[int(np.argmax(np.abs(span)))]
    return "z"


def episode(args):
    ep = read_episode(args.episode, partial=True)
    if not ep.frames:
        raise PlotError(f"{args.episode}: no frames ({ep.problem})")
    if ep.problem:
        print(f"warning: {args.episode}: {ep.problem}; drawing the {len(ep.frames)} whole frames")
    figure = plt.figure(figsize=args.size, constrained_layout=True)
    grid = figure.add_gridspec(2, 2, width_ratios=[1.25, 1], height_ratios=[1, 1])
    space = figure.add_subplot(grid[:, 0], projection="3d")
    top = figure.add_subplot(grid[0, 1])
    timeline = figure.add_subplot(grid[1, 1])

    order = list(_ORDERS[up_axis(ep, args.up)])
    flat = order[:2]  # seen from above: the two horizontal axes

    def in_space(points):
        return np.atleast_2d(points)[:, order].T

    def from_above(points):
        return np.atleast_2d(points)[:, flat].T

    count = min(args.snapshots, len(ep.frames))
    picks = np.unique(np.linspace(0, len(ep.frames) - 1, count).round().astype(int))
    shades = plt.get_cmap(args.colormap)(np.linspace(0.35, 1.0, len(picks)))
    times = ep.times()

    # Obstacles and reference paths as at the last snapshot; targets' paths over the episode.
    last = ep.frames[picks[-1]]
    for c in last["cylinders"]:
        ends = np.array([c["start"], c["end"]])
        space.plot(*in_space(ends), color="#6c7a89", lw=3.0, alpha=0.6, solid_capstyle="round")
        top.plot(*from_above(ends), color="#6c7a89", lw=3.0, alpha=0.6, solid_capstyle="round")
    for b in last["boxes"]:
        corners = _box_corners(b)
        for i, j in _BOX_EDGES:
            space.plot(*in_space(corners[[i, j]]), color="#6c7a89", lw=0.8)
            top.plot(*from_above(corners[[i, j]]), color="#6c7a89", lw=0.8)
    for path in last["paths"]:
        space.plot(*in_space(path["points"]), color="#1f77b4", lw=1, ls="--")
        top.plot(*from_above(path["points"]), color="#1f77b4", lw=1, ls="--")
    for s, sphere in enumerate(ep.frames[0]["spheres"]):
        centres = np.array([f["spheres"][s]["centre"] for f in ep.frames if len(f["spheres"]) > s])
        space.plot(*in_space(centres), color="#d62728", lw=0.9, alpha=0.7,
                   label=f"{sphere['role']} path")
        top.plot(*from_above(centres), color="#d62728", lw=0.9, alpha=0.7)
    for k, (index, shade) in enumerate(zip(picks, shades)):
        frame = ep.frames[index]
        label = f"t = {frame['time']:.2f} s"
        for rod in frame["rods"]:
            space.plot(*in_space(rod["points"]), color=shade, lw=2.2, label=label)
            top.plot(*from_above(rod["points"]), color=shade, lw=2.0)
            label = None
        for lattice in frame["lattices"]:
            for a, b in lattice["springs"]:
                space.plot(*in_space(lattice["nodes"][[a, b]]), color=shade, lw=0.6)
        for sphere in frame["spheres"]:
            space.scatter(*in_space(sphere["centre"]), color="#d62728", s=14,
                          alpha=float(0.3 + 0.7 * k / max(len(picks) - 1, 1)))
    _equal_axes(space, ep, order)
    names = "xyz"
    space.set_xlabel(f"{names[order[0]]} (m)")
    space.set_ylabel(f"{names[order[1]]} (m)")
    space.set_zlabel(f"{names[order[2]]} (m)")
    space.legend(frameon=False, fontsize="x-small", loc="upper left")
    top.set_aspect("equal", adjustable="datalim")
    top.set_xlabel(f"{names[flat[0]]} (m)")
    top.set_ylabel(f"{names[flat[1]]} (m)")
    top.set_title(f"seen from above ({names[order[2]]} up)", fontsize="small")
    top.grid(True, color="#dddddd", linewidth=0.6)

    rewards = ep.rewards()
    timeline.plot(times[1:], rewards[1:], color="#1f77b4", lw=1.0)
    timeline.set_xlabel("time (s)")
    timeline.set_ylabel("reward per step", color="#1f77b4")
    timeline.grid(True, color="#dddddd", linewidth=0.6)
    distance = ep.info("distance")
    if np.isfinite(distance).any():
        twin = timeline.twinx()
        twin.plot(times, distance, color="#2ca02c", lw=1.0)
        twin.set_ylabel("distance to target (m)", color="#2ca02c")
    for index, shade in zip(picks, shades):
        timeline.axvline(times[index], color=shade, lw=0.8, alpha=0.8)
    total = ep.summary["episode_return"] if ep.summary else rewards.sum()
    title = args.title or (f"{ep.metadata.get('env', os.path.basename(args.episode))}: "
                           f"return {total:,.1f} over {len(ep.frames) - 1} steps")
    figure.suptitle(title, fontsize="medium")
    save(figure, args.out, args.dpi)


_BOX_EDGES = [(0, 1), (1, 3), (3, 2), (2, 0), (4, 5), (5, 7), (7, 6), (6, 4), (0, 4), (1, 5), (2, 6), (3, 7)]


def _box_corners(box):
    w, x, y, z = box["orientation"]
    rotation = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    return box["centre"] + (signs * box["half_extents"]) @ rotation.T


def _equal_axes(axes, ep, order):
    points = []
    for frame in ep.frames:
        for rod in frame["rods"]:
            points.append(rod["points"])
        for sphere in frame["spheres"]:
            points.append(sphere["centre"][None, :])
        for lattice in frame["lattices"]:
            points.append(lattice["nodes"])
    if not points:
        return
    cloud = np.concatenate(points)[:, order]
    centre = (cloud.max(axis=0) + cloud.min(axis=0)) / 2
    half = max((cloud.max(axis=0) - cloud.min(axis=0)).max() / 2, 1e-3)
    for setter, c in zip((axes.set_xlim, axes.set_ylim, axes.set_zlim), centre):
        setter(c - half, c + half)
    axes.set_box_aspect((1, 1, 1))
