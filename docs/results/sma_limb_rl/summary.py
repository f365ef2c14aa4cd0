#!/usr/bin/env python3
"""The tables of docs/results/sma_limb_rl.md as CSV (Python's standard library only).

  /usr/bin/python3 docs/results/sma_limb_rl/summary.py runs RUN_DIR...
  /usr/bin/python3 docs/results/sma_limb_rl/summary.py track TRACK_LOG...

`runs`: one row per SAC run: its seed; the success rate and mean return of its last evaluation
(eval.csv: 100 episodes at the final goal tolerance); the mean return of the last 100 training
episodes (progress.csv's rollout/ep_rew_mean); the steps done; the training's wall time
(time/time_elapsed, s). Then one row per group of runs whose names differ only by `_seedN`:
mean, sample standard deviation, min and max of the final success rates.

`track`: one row per path of the standard output of `tendril track` saved as TRACK_LOG: the
log's name, the path, control steps, whether every waypoint was reached, the RMSE (deg; empty
when the path's first point was never reached).
`tables`: Tables 5.4 and 5.5 of the page as Markdown rows, read from tracking.csv (the `track`
output): per controller and kind of action, each seed's RMSE ("*": the path was not finished,
"n.r.": its first point never reached), the thesis' number in brackets, and per seed the mean of
the averaged columns when that seed finished all of them ("—" otherwise).
With training_runs.csv (the `runs` output) as a second argument, Table 5.1's rows first.
  /usr/bin/python3 docs/results/sma_limb_rl/summary.py tables docs/results/sma_limb_rl/tracking.csv \
    docs/results/sma_limb_rl/training_runs.csv
"""
import csv
import os
import re
import statistics
import sys


def read_rows(path):
    with open(path, newline="") as file:
        rows = list(csv.DictReader(file))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    return rows


def seed_of(run_dir):
    with open(os.path.join(run_dir, "config.yaml")) as config:
        for line in config:
            if line.startswith("seed:"):
                return int(line.split(":", 1)[1])
    raise SystemExit(f"{run_dir}: no seed in config.yaml")


def summarize_runs(run_dirs):
    print("run,seed,success_final,eval_return_final,eval_return_std,train_return_final,steps,"
          "wall_s")
    groups = {}
    for run_dir in run_dirs:
        evaluation = read_rows(os.path.join(run_dir, "eval.csv"))[-1]
        progress = read_rows(os.path.join(run_dir, "progress.csv"))
        returns = [row["rollout/ep_rew_mean"] for row in progress if row["rollout/ep_rew_mean"]]
        name = os.path.basename(os.path.normpath(run_dir))
        print(",".join(str(value) for value in [
            name, seed_of(run_dir), evaluation["success_rate"],
            round(float(evaluation["mean_return"]), 1), round(float(evaluation["std_return"]), 1),
            round(float(returns[-1]), 1), evaluation["timesteps"],
            round(float(progress[-1]["time/time_elapsed"]))]))
        group = re.sub(r"_seed\d+$", "", name)
        groups.setdefault(group, []).append(float(evaluation["success_rate"]))
    print()
    print("group,runs,success_mean,success_std,success_min,success_max")
    for group, values in groups.items():
        spread = statistics.stdev(values) if len(values) > 1 else float("nan")
        print(f"{group},{len(values)},{statistics.mean(values):.3f},{spread:.3f},"
              f"{min(values):.2f},{max(values):.2f}")


def summarize_tracking(logs):
    print("log,pattern,steps,finished,rmse_deg")
    for log in logs:
        name = os.path.splitext(os.path.basename(log))[0]
        with open(log) as file:
            for line in file:
                fields = line.split()
                # "<pattern> <steps> yes|no <rmse>" or "... no the path's first point was never reached"
                if len(fields) >= 3 and fields[1].isdigit() and fields[2] in ("yes", "no"):
                    rmse = fields[3] if len(fields) == 4 else ""
                    print(f"{name},{fields[0]},{fields[1]},{fields[2]},{rmse}")


# The thesis' robot numbers (Tables 5.4 and 5.5), None where it has none.
THESIS_5_4 = {"lk_encoder": (4.73, 3.22, 3.62, 3.86), "lk_full": (4.75, 3.00, 4.00, 3.92),
              "no_head": (4.73, 4.75, 4.10, 4.53), "mlp_head": None,
              "pid": (5.06, 3.48, 3.91, 4.15)}
THESIS_5_5 = {"lk_encoder": (4.62, 3.83, 5.92, 8.75), "lk_full": None,
              "no_head": (5.18, 5.20, 5.22, 9.20), "mlp_head": None,
              "pid": (5.53, 4.72, 7.45, 9.28)}
CONTROLLERS = (("lk_encoder", "LK (Encoder)"), ("lk_full", "LK (Full)"),
               ("no_head", "MLP No Head"), ("mlp_head", "MLP Head"), ("pid", "PID"))


def cell(entry):
    """One path's RMSE as the page writes it; None (and the text) when not finished."""
    if entry is None:
        return None, "—"
    finished, rmse = entry
    if not rmse:
        return None, "n.r."
    return (float(rmse) if finished == "yes" else None), f"{float(rmse):.2f}" + (
        "" if finished == "yes" else "*")


THESIS_5_1 = {"lk_encoder": ("LK Head (Encoder)", "1.00", "−1507.87"),
              "lk_full": ("LK (Full)", "0.90", "−1794.63"),
              "mlp_head": ("MLP Head", "0.00", "−7046.79"),
              "no_head": ("MLP No Head", "0.76", "−2009.50")}


def spread(values, digits):
    """mean ± sample standard deviation as the page writes it (U+2212 for minus)."""
    text = f"{statistics.mean(values):.{digits}f}"
    if len(values) > 1:
        text += f" ± {statistics.stdev(values):.{digits}f}"
    return text.replace("-", "−")


def table_5_1_rows(training_csv):
    """Table 5.1's rows from training_runs.csv (its table51_<head>_seed<N> runs)."""
    with open(training_csv, newline="") as file:
        runs = [row for row in csv.DictReader(file) if row.get("seed")]
    print("Table 5.1")
    for key, (label, success, ret) in THESIS_5_1.items():
        mine = sorted((row for row in runs if re.fullmatch(rf"table51_{key}_seed\d+", row["run"])),
                      key=lambda row: int(row["seed"]))
        if not mine:
            continue
        rates = [float(row["success_final"]) for row in mine]
        seeds = ", ".join(f"{rate:.2f}" for rate in rates)
        print(f"| {label} | {success} | {spread(rates, 2)} ({seeds}; {len(mine)} seeds) | {ret} | "
              f"{spread([float(row['eval_return_final']) for row in mine], 0)} | "
              f"{spread([float(row['train_return_final']) for row in mine], 0)} | "
              + ", ".join(f"{float(row['wall_s']) / 60:.1f}" for row in mine) + " |")
    print()


def table_rows(tracking_csv):
    rows = read_rows(tracking_csv)
    results = {(row["log"], row["pattern"]): (row["finished"], row["rmse_deg"]) for row in rows}
    logs = sorted({row["log"] for row in rows})
    tables = (
        ("5.4", THESIS_5_4, [("", "spiral"), ("", "square"), ("", "sml")], [0, 1, 2],
         ("", "circle")),
        ("5.5", THESIS_5_5, [("_push", "circle"), ("_soft", "circle"), ("_load10", "circle"),
                             ("_load50", "circle")], [0, 1, 2], None))
    for number, thesis, columns, averaged, extra in tables:
        print(f"Table {number}")
        for key, label in CONTROLLERS:
            for actions in (("",) if key == "pid" else ("mean", "sampled")):
                prefix = key if key == "pid" else None
                seeds = [""] if key == "pid" else sorted(
                    {re.match(rf"{key}_seed(\d+)_{actions}$", log).group(1)
                     for log in logs if re.match(rf"{key}_seed(\d+)_{actions}$", log)})
                if not seeds:
                    continue
                names = [prefix if prefix else f"{key}_seed{seed}_{actions}" for seed in seeds]
                texts, values = [], []
                for suffix, pattern in columns:
                    parts = [cell(results.get((name + suffix, pattern))) for name in names]
                    values.append([value for value, _ in parts])
                    texts.append(" / ".join(text for _, text in parts))
                reference = thesis[key]
                out = []
                for c, text in enumerate(texts):
                    out.append(f"{text} ({'—' if reference is None else f'{reference[c]:.2f}'})")
                means = []
                for s in range(len(names)):
                    picked = [values[c][s] for c in averaged]
                    means.append("—" if None in picked else f"{sum(picked) / len(picked):.2f}")
                average = " / ".join(means)
                if number == "5.4":
                    out.append(f"{average} ({'—' if reference is None else f'{reference[3]:.2f}'})")
                    out.append(" / ".join(cell(results.get((name, extra[1])))[1] for name in names))
                else:
                    out.append(average)
                print(f"| {label} | {actions or '—'} | " + " | ".join(out) + " |")
        print()


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("runs", "track", "tables"):
        raise SystemExit(__doc__)
    {"runs": summarize_runs, "track": summarize_tracking,
     "tables": lambda args: (table_5_1_rows(args[1]) if len(args) > 1 else None,
                             table_rows(args[0]))}[sys.argv[1]](sys.argv[2:])
