#!/usr/bin/env python3
"""The tables of docs/results/ur5.md from run directories (Python's standard library only).

  /usr/bin/python3 docs/results/ur5/summary.py RUN_DIR...

One row per run: the success rate of the last 100 training episodes (progress.csv's
rollout/success_rate) at the first log row past 250k and 500k steps and at the end, the mean
length and return of those episodes at the end, the steps done, and the training's wall time
(time/time_elapsed, s). Then one row per configuration (a sweep's directory, and the run's name
without its seed token where the sweep varies more than the seed): the mean and the range of the
final success rates over its runs.
"""
import csv
import os
import re
import sys


def seed_of(run_dir):
    with open(os.path.join(run_dir, "config.yaml")) as config:
        for line in config:
            if line.startswith("seed:"):
                return int(line.split(":", 1)[1])
    raise SystemExit(f"{run_dir}: no seed in config.yaml")


def rows_of(run_dir):
    with open(os.path.join(run_dir, "progress.csv"), newline="") as progress:
        rows = list(csv.DictReader(progress))
    if not rows:
        raise SystemExit(f"{run_dir}: progress.csv has no rows")
    return rows


def success_after(rows, steps):
    for row in rows:
        if float(row["time/total_timesteps"]) >= steps:
            return row.get("rollout/success_rate", "")
    return ""


def group_of(run_dir):
    """The sweep directory, with the run's name but its seed token when it has more
    (runs/sweeps/ur5_ppo_base_bonus/success_bonus_0-seed_42 → …/success_bonus_0)."""
    rest = re.sub(r"(^|[-_])seed_?\d+", "", os.path.basename(run_dir), count=1).strip("-_")
    return os.path.join(os.path.dirname(run_dir), rest) if rest else os.path.dirname(run_dir)


def main(run_dirs):
    print("run,seed,success_250k,success_500k,success_final,length_final,return_final,steps,"
          "wall_s")
    finals = {}
    for run_dir in run_dirs:
        rows = rows_of(run_dir)
        last = rows[-1]
        name = os.path.normpath(run_dir)
        print(",".join(str(value) for value in [
            name, seed_of(run_dir), success_after(rows, 250000), success_after(rows, 500000),
            last.get("rollout/success_rate", ""), round(float(last["rollout/ep_len_mean"]), 1),
            round(float(last["rollout/ep_rew_mean"]), 1), last["time/total_timesteps"],
            round(float(last["time/time_elapsed"]))]))
        finals.setdefault(group_of(name), []).append(float(last["rollout/success_rate"]))
    print()
    print("directory,runs,success_final_mean,success_final_min,success_final_max")
    for directory, values in finals.items():
        print(f"{directory},{len(values)},{sum(values) / len(values):.3f},{min(values):.2f},"
              f"{max(values):.2f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    main(sys.argv[1:])
