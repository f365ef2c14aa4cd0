"""`tendril plot map`: a value over a plane as a heat map, with contour lines of it or of other
columns, and paths and circles drawn over it (the learned safety value of `tendril safety map`,
seed 001 Figs. 6.4 and 6.6)."""
import matplotlib.pyplot as plt
import numpy as np

from .runs import PlotError, read_csv


def grid(table, x, y, z, path):
    """The columns of a CSV grid (every (x, y) pair once, any row order) as 2-D arrays."""
    for column in (x, y, z):
        if column not in table:
            raise PlotError(f"{path} has no column '{column}' (it has: {', '.join(table)})")
    xs, ys = np.unique(table[x]), np.unique(table[y])
    if len(xs) < 2 or len(ys) < 2 or len(xs) * len(ys) != len(table[x]):
        raise PlotError(f"{path}: columns {x} and {y} do not form a full grid "
                        f"({len(xs)} × {len(ys)} values, {len(table[x])} rows)")
    values = np.full((len(ys), len(xs)), np.nan)
    values[np.searchsorted(ys, table[y]), np.searchsorted(xs, table[x])] = table[z]
    return xs, ys, values


def contour_spec(text):
    """COLUMN:LEVEL[,LEVEL...][:LABEL] → (column, levels, label)."""
    parts = text.split(":")
    if len(parts) not in (2, 3) or not parts[0]:
        raise PlotError(f"--contour {text}: expected COLUMN:LEVEL[,LEVEL...][:LABEL]")
    try:
        levels = sorted(float(v) for v in parts[1].split(","))
    except ValueError:
        raise PlotError(f"--contour {text}: the levels must be numbers")
    return parts[0], levels, parts[2] if len(parts) == 3 else None


def path_spec(text):
    """FILE:XCOLUMN,YCOLUMN[:LABEL] → (file, x, y, label)."""
    parts = text.rsplit(":", 2)
    if len(parts) < 2 or len(parts[1].split(",")) != 2:
        raise PlotError(f"--path {text}: expected FILE:XCOLUMN,YCOLUMN[:LABEL]")
    if len(parts) == 3 and "," not in parts[1]:  # FILE:X,Y without a label, FILE holding ':'
        parts = [parts[0] + ":" + parts[1], parts[2]]
    x, y = parts[1].split(",")
    return parts[0], x, y, parts[2] if len(parts) == 3 else None


LINE_STYLES = ["-", "--", ":", "-."]
CONTOUR_COLOURS = ["black", "tab:blue", "tab:red", "tab:green"]
PATH_COLOURS = ["tab:orange", "magenta", "cyan", "white"]


def value_map(args):
    table = read_csv(args.file)
    xs, ys, values = grid(table, args.x, args.y, args.z, args.file)
    fig, ax = plt.subplots(figsize=args.size)
    mesh = ax.pcolormesh(xs, ys, values, shading="nearest", cmap=args.colormap,
                         vmin=args.vmin, vmax=args.vmax)
    fig.colorbar(mesh, ax=ax, label=args.zlabel or args.z)
    handles = []
    for k, text in enumerate(args.contour or []):
        column, levels, label = contour_spec(text)
        _, _, field = grid(table, args.x, args.y, column, args.file)
        colour = CONTOUR_COLOURS[k % len(CONTOUR_COLOURS)]
        style = LINE_STYLES[k % len(LINE_STYLES)]
        lines = ax.contour(xs, ys, field, levels=levels, colors=colour, linestyles=style,
                           linewidths=1.6)
        if len(levels) > 1 or args.level_labels:
            ax.clabel(lines, fmt="%g", fontsize=8)
        handles.append(plt.Line2D([], [], color=colour, linestyle=style,
                                  label=label or f"{column} = {', '.join(f'{v:g}' for v in levels)}"))
    for k, text in enumerate(args.path or []):
        file, x, y, label = path_spec(text)
        path = read_csv(file)
        for column in (x, y):
            if column not in path:
                raise PlotError(f"{file} has no column '{column}' (it has: {', '.join(path)})")
        (line,) = ax.plot(path[x], path[y], linewidth=1.4, label=label,
                          color=PATH_COLOURS[k % len(PATH_COLOURS)])
        if label:
            handles.append(line)
    for text in args.circle or []:
        (cx, cy, radius), label = text
        circle = plt.Circle((cx, cy), radius, fill=False, color="tab:green", linewidth=1.8)
        ax.add_patch(circle)
        if label:
            handles.append(plt.Line2D([], [], color="tab:green", label=label))
    ax.set_xlabel(args.xlabel or args.x)
    ax.set_ylabel(args.ylabel or args.y)
    ax.set_xlim(xs[0], xs[-1])
    ax.set_ylim(ys[0], ys[-1])
    if args.equal:
        ax.set_aspect("equal")
    if args.title:
        ax.set_title(args.title)
    if handles:
        ax.legend(handles=handles, loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)
    plt.close(fig)
