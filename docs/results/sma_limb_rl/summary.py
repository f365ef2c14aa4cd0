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


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("runs", "track"):
        raise SystemExit(__doc__)
    (summarize_runs if sys.argv[1] == "runs" else summarize_tracking)(sys.argv[2:])
