"""Seed 003's beam: one CSV row per trained run of the variants of docs/results/beam.md ("Early
termination and a pretrained case 1"), from each run's progress.csv and the printed output of its
evaluation (Python's standard library only).

Each row: the experiment file, the keys its training changed with --set (none: "-"), the seed, the
training steps of the evaluated policy, the per-step means over the evaluation of distance (m),
velocity_error (m/s) and reward, and the training's time/time_elapsed (s) at those steps.

  build/apps/tendril run RUN --steps N --seed 1000 [--set ...] > EVAL.txt
  /usr/bin/python3 docs/results/beam/variants.py --out docs/results/beam/variants.csv \
      CONFIG:OVERRIDES:SEED:STEPS:RUN:EVAL.txt ...

With --append the rows are added to an existing file (runs of a later variant).
"""
import argparse
import csv
import re


def per_step_means(path):
    """The 'per step (mean over N steps)' block of `tendril run`'s output: name -> value."""
    with open(path, encoding="utf-8") as output:
        text = output.read()
    block = text.split("per step (mean over", 1)[1].split("\n", 1)[1]
    return {name: float(value) for name, value in re.findall(r"^ +(\w+) +(\S+)$", block, re.M)}


def wall_seconds(run, steps):
    """time/time_elapsed of the last progress row at or before `steps`; a resumed run's clock
    starts again at 0, so each earlier segment's last value is added."""
    offset, last, elapsed = 0.0, 0.0, None
    with open(f"{run}/progress.csv", newline="") as progress:
        for row in csv.DictReader(progress):
            now = float(row["time/time_elapsed"])
            if now < last:
                offset += last
            last = now
            if int(row["time/total_timesteps"]) <= steps:
                elapsed = offset + now
    return elapsed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--append", action="store_true", help="add the rows to an existing --out")
    parser.add_argument("runs", nargs="+", help="CONFIG:OVERRIDES:SEED:STEPS:RUN:EVAL.txt")
    args = parser.parse_args()
    with open(args.out, "a" if args.append else "w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        if not args.append:
            writer.writerow(["config", "overrides", "seed", "steps", "mean_distance_m",
                             "velocity_error_m_s", "reward_per_step", "wall_s"])
        for item in args.runs:
            config, overrides, seed, steps, run, evaluation = item.split(":")
            means = per_step_means(evaluation)
            writer.writerow([config, overrides, seed, steps, f"{means['distance']:.4f}",
                             f"{means['velocity_error']:.3f}", f"{means['reward']:.3f}",
                             f"{wall_seconds(run, int(steps)):.0f}"])
            print(",".join([config, overrides, seed, steps, f"{means['distance']:.3f}"]))


if __name__ == "__main__":
    main()
