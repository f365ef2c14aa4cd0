"""`tendril plot csv`: columns of CSV files as lines, points, paths or box plots, split into
series and panels by the values of a column (results pages' data files)."""
import math
import os

import matplotlib.patches
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import MaxNLocator

from .runs import PlotError, read_csv

# Colours of the series flagged by --bold, in order (the brown and magenta of the SMA thesis'
# Fig. 4.1 first).
BOLD_COLOURS = ["#8c564b", "#d62cb0", "#1f3fb4", "#2ca02c"]


def select(table, text, conditions, path):
    """Row mask of `COLUMN=VALUE` / `COLUMN!=VALUE` conditions, compared as text."""
    rows = len(next(iter(text.values()))) if text else 0
    keep = np.ones(rows, dtype=bool)
    for condition in conditions or []:
        negate = "!=" in condition
        column, _, value = condition.partition("!=" if negate else "=")
        if not _ or not column:
            raise PlotError(f"--where {condition}: expected COLUMN=VALUE or COLUMN!=VALUE")
        if column not in text:
            raise PlotError(f"{path} has no column '{column}' (it has: {', '.join(text)})")
        cells = text[column]
        same = cells == value
        if not same.any() and _is_number(value):  # 1 matches 1.0
            same = np.isclose(table[column], float(value))
        keep &= ~same if negate else same
    return keep


def _is_number(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def distinct(cells):
    """Distinct values in order: numerically when every one is a number, else as first seen."""
    values = list(dict.fromkeys(cells))
    if values and all(_is_number(v) for v in values):
        values.sort(key=float)
    return values


def _layout(count, columns):
    columns = columns or min(count, 3)
    return math.ceil(count / columns), min(columns, count)


def csv_columns(args):
    ys = args.y.split(",")
    xs = args.x.split(",")
    if len(xs) not in (1, len(ys)):
        raise PlotError(f"--x names {len(xs)} columns: name one, or one per --y column ({len(ys)})")
    xs = xs * len(ys) if len(xs) == 1 else xs
    styles = args.styles.split(",") if args.styles else ["-"] * len(ys)
    if len(styles) != len(ys):
        raise PlotError(f"--styles names {len(styles)} line styles, --y names {len(ys)}")
    errors = args.yerr.split(",") if args.yerr else [None] * len(ys)
    if len(errors) != len(ys):
        raise PlotError(f"--yerr names {len(errors)} columns, --y names {len(ys)}")
    labels = args.labels.split(",") if args.labels else None
    if labels and len(labels) != len(args.files) * len(ys):
        raise PlotError(f"--labels names {len(labels)} series, there are {len(args.files) * len(ys)}")
    bold = args.bold.split(",") if args.bold else []

    tables = []
    for path in args.files:
        table, text = read_csv(path, with_text=True)
        needed = set(xs + ys + [e for e in errors if e] + bold)
        needed |= {c for c in (args.split, args.panels) if c and c != "y"}
        for column in needed:
            if column not in table:
                raise PlotError(f"{path} has no column '{column}' (it has: {', '.join(table)})")
        tables.append((path, table, text, select(table, text, args.where, path)))

    if not any(keep.any() for _, _, _, keep in tables):
        raise PlotError("no rows left to draw (see --where)")

    # Panels: by the values of a column, by --y column ("y"), or one.
    if args.panels == "y":
        panels = [(f"y{j}", j) for j in range(len(ys))]
    elif args.panels:
        panels = [(value, None) for value in
                  distinct(np.concatenate([t[args.panels][k] for _, _, t, k in tables]))]
    else:
        panels = [(None, None)]
    if not panels:
        raise PlotError("no rows left to draw (see --where)")
    titles = args.titles.split(",") if args.titles else None
    if titles and len(titles) != len(panels):
        raise PlotError(f"--titles names {len(titles)} panels, there are {len(panels)}")
    rows, columns = _layout(len(panels), args.columns)
    figure, grid = plt.subplots(rows, columns, figsize=args.size, squeeze=False, sharex=not args.equal,
                                sharey=not args.equal, constrained_layout=True)
    for extra in grid.flat[len(panels):]:
        extra.set_visible(False)

    splits = (distinct(np.concatenate([t[args.split][k] for _, _, t, k in tables]))
              if args.split else [None])
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    shades = None
    if args.colormap and args.split:
        shades = plt.get_cmap(args.colormap)(np.linspace(0.1, 0.9, len(splits)))

    def colour_of(i):
        return shades[i % len(shades)] if shades is not None else colours[i % len(colours)]

    for p, (axes, (panel, only_y)) in enumerate(zip(grid.flat, panels)):
        axes.grid(True, color="#dddddd", linewidth=0.6)
        axes.set_axisbelow(True)
        k = 0
        box_series = []
        bold_count = 0
        for f, (path, table, text, keep) in enumerate(tables):
            in_panel = keep.copy()
            if panel is not None and only_y is None:
                in_panel &= text[args.panels] == panel
            for j, (x, y, error, style) in enumerate(zip(xs, ys, errors, styles)):
                name = labels[k] if labels else (
                    y if len(args.files) == 1 else f"{os.path.basename(path)}: {y}")
                k += 1
                if only_y is not None and j != only_y:
                    continue
                for s, value in enumerate(splits):
                    rows_of = in_panel if value is None else in_panel & (text[args.split] == value)
                    if not rows_of.any():
                        continue
                    alone = len(args.files) == 1 and (len(ys) == 1 or only_y is not None)
                    series = name if value is None else (
                        _split_name(args.split, value) if alone
                        else f"{name}, {_split_name(args.split, value)}")
                    # One colour per file, y column and split value, the same in every panel.
                    colour = colour_of(((k - 1) if only_y is None else f) * len(splits) + s)
                    if args.kind == "box":
                        box_series.append((series if value is not None or len(ys) > 1 else None,
                                           colour, text[x][rows_of], table[y][rows_of]))
                        continue
                    flags = [b for b in bold if np.nanmax(table[b][rows_of]) == 1]
                    width, alpha, label = 1.3, 0.9 if shades is not None else 1.0, series
                    if shades is not None:
                        label = None  # the colour bar names them
                    if flags:
                        colour = BOLD_COLOURS[bold_count % len(BOLD_COLOURS)]
                        bold_count += 1
                        width, alpha, label = 2.6, 1.0, f"{' and '.join(flags)}: {series}"
                    _draw(axes, args, table[x][rows_of], table[y][rows_of],
                          table[error][rows_of] if error else None, colour, style, width, alpha,
                          label)
        if args.kind == "box":
            _boxes(axes, box_series)
        _regions(axes, args)
        if panel is not None:
            if titles:
                title = titles[p]
            elif only_y is None:
                title = _split_name(args.panels, panel)
            else:  # one file's labels name its columns; several files' name the series
                title = labels[only_y] if labels and len(args.files) == 1 else ys[only_y]
            axes.set_title(title, fontsize="medium")
        if args.equal:
            axes.set_aspect("equal", adjustable="datalim")
        if args.logx:
            axes.set_xscale("log")
        if args.logy:
            axes.set_yscale("symlog" if args.logy == "symlog" else "log")
        handles, names = axes.get_legend_handles_labels()
        first = grid.flat[0].get_legend_handles_labels()[1]
        if handles and (p == 0 or names != first):
            scale = max(1.0, 6 / math.sqrt(args.marker_size)) if args.kind == "scatter" else 1
            axes.legend(frameon=False, fontsize="small", markerscale=scale)
    whole = all(np.all(np.mod(t[x][k & np.isfinite(t[x])], 1) == 0)
                for _, t, _, k in tables for x in xs)
    for axes in grid[-1, :]:
        axes.set_xlabel(args.xlabel or xs[0])
        if whole and args.kind != "box" and not args.logx:  # seeds, modules: whole ticks
            axes.xaxis.set_major_locator(MaxNLocator(integer=True))
    for axes in grid[:, 0]:
        axes.set_ylabel(args.ylabel or (ys[0] if len(ys) == 1 else ""))
    if shades is not None:
        mapper = plt.cm.ScalarMappable(cmap=plt.get_cmap(args.colormap))
        numeric = [float(v) for v in splits] if all(_is_number(v) for v in splits) else None
        if numeric:
            mapper.set_clim(min(numeric), max(numeric))
        colourbar = figure.colorbar(mapper, ax=list(grid.flat[:len(panels)]), shrink=0.9)
        colourbar.set_label(args.split)
    if args.title:
        figure.suptitle(args.title, fontsize="medium")
    from .figures import save
    save(figure, args.out, args.dpi)


def _split_name(column, value):
    return f"{column} {value}" if _is_number(value) else value


def _draw(axes, args, x, y, error, colour, style, width, alpha, label):
    keep = np.isfinite(x) & np.isfinite(y)
    if not keep.any():
        return
    x, y = x[keep], y[keep]
    if args.kind == "scatter":
        axes.scatter(x, y, s=args.marker_size, color=colour, alpha=alpha, lw=0, label=label)
        return
    if args.kind == "path" or args.order == "rows":  # the rows' order: a trajectory
        axes.plot(x, y, color=colour, ls=style, lw=width, alpha=alpha, label=label)
        return
    order = np.argsort(x, kind="stable")
    if error is not None:
        axes.errorbar(x[order], y[order], yerr=np.nan_to_num(error[keep][order]), lw=width,
                      marker="o", markersize=3, capsize=3, label=label, color=colour, ls=style)
        return
    axes.plot(x[order], y[order], color=colour, ls=style, lw=width, alpha=alpha, label=label,
              marker="o" if args.kind == "linepoints" else None, markersize=3)


def _regions(axes, args):
    """--rect: shaded rectangles (obstacles, regions); --mark: marked points (targets)."""
    for (x0, x1, y0, y1), label in args.rect:
        axes.add_patch(matplotlib.patches.Rectangle((min(x0, x1), min(y0, y1)), abs(x1 - x0),
                                                    abs(y1 - y0), facecolor="#6c7a89", alpha=0.35,
                                                    edgecolor="#6c7a89", label=label))
    for (x, y), label in args.mark:
        axes.plot([x], [y], marker="*", markersize=12, color="#d62728", linestyle="none",
                  label=label)


def _boxes(axes, series):
    """Box plots of each series' y values at each distinct x value (categories), the series of
    one category side by side: box from the first to the third quartile, the median, whiskers to
    the extremes within 1.5 interquartile ranges, the rest as outliers (matplotlib's default)."""
    categories = distinct(np.concatenate([cells for _, _, cells, _ in series])) if series else []
    width = 0.8 / max(len(series), 1)
    for s, (name, colour, cells, values) in enumerate(series):
        data, positions = [], []
        for c, category in enumerate(categories):
            chosen = values[(cells == category) & np.isfinite(values)]
            if len(chosen):
                data.append(chosen)
                positions.append(c + (s - (len(series) - 1) / 2) * width)
        if not data:
            continue
        axes.boxplot(data, positions=positions, widths=width * 0.85, patch_artist=True,
                     boxprops={"facecolor": colour, "alpha": 0.55, "edgecolor": colour},
                     medianprops={"color": "#b22222", "lw": 1.5},
                     whiskerprops={"color": colour}, capprops={"color": colour},
                     flierprops={"markeredgecolor": colour, "markersize": 3})
        if name:
            axes.fill_between([], [], color=colour, alpha=0.55, label=name)  # the legend swatch
    axes.set_xticks(range(len(categories)), categories)
    axes.set_xlim(-0.6, len(categories) - 0.4)
