"""Run directories, their CSV files, and seeds grouped into mean and spread."""
import csv
import math
import os
import re

import numpy as np

STEPS = "time/total_timesteps"


class PlotError(ValueError):
    pass


def read_csv(path, with_text=False):
    """Columns of a numeric CSV file as float arrays (empty or non-numeric cells: NaN); with
    `with_text`, also the cells as text (string arrays), for columns of names. Lines starting
    with '#' (the commented headers of tendril's data files) are skipped. A last line without
    its newline (a file being written) and rows with the wrong number of cells are left out."""
    try:
        with open(path, newline="") as f:
            text = f.read()
    except OSError as e:
        raise PlotError(f"{path}: {e.strerror}")
    lines = text.split("\n")[:-1]  # the part after the last newline is unfinished
    complete = [line for line in lines if not line.startswith("#")]
    if not complete:
        raise PlotError(f"{path}: no complete header line")
    reader = csv.reader(complete)
    header = [h.strip() for h in next(reader)]
    rows = [row for row in reader if len(row) == len(header)]

    def number(cell):
        try:
            return float(cell)
        except ValueError:
            return math.nan

    values = np.array([[number(c) for c in row] for row in rows], dtype=float).reshape(-1, len(header))
    table = {name: values[:, i] for i, name in enumerate(header)}
    if not with_text:
        return table
    cells = np.array(rows, dtype=str).reshape(-1, len(header))
    return table, {name: np.char.strip(cells[:, i]) for i, name in enumerate(header)}


def is_run(directory):
    return any(os.path.isfile(os.path.join(directory, name))
               for name in ("config.yaml", "progress.csv", "eval.csv"))


def natural_key(text):
    """Orders names with numbers by their values: "n_steps_256" before "n_steps_1024",
    "tau_0.005" before "tau_0.01"."""
    return [(0, float(part), "") if i % 2 else (1, 0.0, part)
            for i, part in enumerate(re.split(r"(\d+(?:\.\d+)?)", text))]


def expand_runs(paths):
    """Run directories named directly, and those directly inside the other directories given
    (a sweep's output, seeds side by side), in order: the numbers in names by value."""
    runs = []
    for path in paths:
        if is_run(path):
            runs.append(path)
            continue
        if not os.path.isdir(path):
            raise PlotError(f"{path}: neither a run directory nor a directory of runs")
        inside = sorted((os.path.join(path, d) for d in os.listdir(path)
                         if not d.startswith(".") and is_run(os.path.join(path, d))),
                        key=natural_key)
        if not inside:
            raise PlotError(f"{path}: no run directories inside")
        runs.extend(inside)
    return runs


def _run_curves():
    """The extension's grouping and statistics over seeds (core/run_curves): the code the sweep
    summaries and the dashboard use, so a figure and a table of the same runs agree."""
    try:
        from tendril import _tendril
    except ImportError as e:
        raise PlotError("grouping runs by seed needs tendril's Python extension (built by default; "
                        f"`tendril plot` finds it in the build): {e}")
    return _tendril


def seed_group(name, parent=""):
    """A run's name without its seed token, a trailing time stamp and the separators left at its
    ends: "n_steps_256-seed_3" → "n_steps_256", "ppo-seed1-20261128-093000" → "ppo"; a name
    that is only a seed ("seed_42") gives `parent`, the name of the directory holding the run,
    or "seeds". Runs differing only by seed share a group."""
    return _run_curves().seed_group(name, parent)


def curve(run, metric, x_column=STEPS):
    """(x, y) of one run: a progress.csv column against `x_column`; with metric "eval" the mean
    evaluation return (and its std) against timesteps from eval.csv; with "eval:<column>" another
    eval.csv column (eval:success_rate)."""
    if metric == "eval":
        table = read_csv(os.path.join(run, "eval.csv"))
        x, y = table["timesteps"], table["mean_return"]
        spread = table.get("std_return")
    elif metric.startswith("eval:"):
        table = read_csv(os.path.join(run, "eval.csv"))
        column = metric[len("eval:"):]
        if column not in table:
            raise PlotError(f"{run}/eval.csv has no column '{column}' "
                            f"(it has: {', '.join(sorted(table))})")
        x, y, spread = table["timesteps"], table[column], None
    else:
        table = read_csv(os.path.join(run, "progress.csv"))
        for column in (metric, x_column):
            if column not in table:
                raise PlotError(f"{run}/progress.csv has no column '{column}' "
                                f"(it has: {', '.join(sorted(table))})")
        x, y, spread = table[x_column], table[metric], None
    keep = np.isfinite(x) & np.isfinite(y)
    order = np.argsort(x[keep], kind="stable")
    result = {"x": x[keep][order], "y": y[keep][order]}
    if spread is not None:
        result["std"] = spread[keep][order]
    return result


def aggregate(curves, points=200):
    """Mean and standard deviation (population), minimum and maximum of curves on `points`
    evenly spaced x values over the range every curve covers (so each point averages all seeds),
    by linear interpolation."""
    stats = _run_curves().aggregate_curves([(c["x"], c["y"]) for c in curves], points, "common")
    if stats["curves"] == 0:
        raise PlotError("no data to aggregate")
    if not stats["x"]:
        raise PlotError("the runs' x ranges do not overlap")
    result = {key: np.asarray(stats[key], dtype=float) for key in ("x", "mean", "std", "min", "max")}
    result["n"] = stats["curves"]
    return result
