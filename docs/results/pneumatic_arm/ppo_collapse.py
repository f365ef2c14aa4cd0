"""PPO's collapse in PneumaticArm/LearnedReach-v0: one CSV row per run of the sweeps
configs/pneumatic_arm/sweeps/ppo_collapse_*.yaml, from each run's progress.csv, eval.csv and
config.yaml (Python's standard library only).

The success rate is progress.csv's rollout/success_rate (the share of the last 100 training
episodes that reached the goal), logged once per rollout (4 × 150 = 600 steps). A run
"collapses" at the first logged step s after it has reached ≥ 0.9 where the rate is ≤ 0.1 and
never again exceeds 0.5 in the rest of the logged window, which must extend ≥ 50 k steps past s
(a fall in the last 50 k steps is not called a collapse).

Each row: the variant (the sweep's output directory without "ppo_collapse_"), the seed, the steps
trained, the first step with success ≥ 0.9, the collapse step (empty: none), the final success
rate, the lowest success rate after the first ≥ 0.9, how often the rate fell to ≤ 0.1 after the
first ≥ 0.9 (a fall that recovered counts too), the shortest mean episode (rollout/ep_len_mean)
while it was ≤ 0.1 after the first ≥ 0.9 (driving into the plate ends episodes in ≈ 10 steps,
losing the goal lets them run 150), the first step from which every rollout to the end has
success ≤ 0.1 and a mean episode of ≤ 20 steps (the run ends driving into the plate, whether or
not it had reached the goal; empty: no), the policy's σ (train/std) at the end, the best
deterministic evaluation return (eval.csv) and the step it was measured at, and the training's
wall time (time/time_elapsed, s).

  /usr/bin/python3 docs/results/pneumatic_arm/ppo_collapse.py \
      --out docs/results/pneumatic_arm/ppo_collapse.csv runs/sweeps/ppo_collapse_*/*seed_*/
  /usr/bin/python3 docs/results/pneumatic_arm/ppo_collapse.py \
      --table docs/results/pneumatic_arm/ppo_collapse.csv      (the page's table rows)
"""
import argparse
import csv
import os
import re

REACHED = 0.9
COLLAPSED = 0.1
RECOVERED = 0.5
MIN_WINDOW = 50_000
PLATE_LENGTH = 20


def progress(run):
    """(steps, success rate, σ, wall seconds, mean episode length) per logged rollout."""
    with open(os.path.join(run, "progress.csv"), newline="") as file:
        return [(int(row["time/total_timesteps"]), float(row["rollout/success_rate"]),
                 float(row["train/std"]), float(row["time/time_elapsed"]),
                 float(row["rollout/ep_len_mean"]))
                for row in csv.DictReader(file)]


def collapse_step(rows, first):
    """The first step after `first` at which the run collapsed (see the module's docstring)."""
    end = rows[-1][0]
    for index, (step, success, *_) in enumerate(rows):
        if step <= first or success > COLLAPSED or end - step < MIN_WINDOW:
            continue
        if all(later[1] <= RECOVERED for later in rows[index + 1:]):
            return step
    return None


def plate_step(rows):
    """The first step from which every logged rollout has success ≤ 0.1 and a mean episode of
    ≤ 20 steps (every episode driving into the plate) to the run's end, ≥ 50 k steps before it."""
    end, start = rows[-1][0], None
    for step, success, _, _, length in rows:
        if success <= COLLAPSED and length <= PLATE_LENGTH:
            start = step if start is None else start
        else:
            start = None
    return start if start is not None and end - start >= MIN_WINDOW else None


def dips(rows, first):
    """How often the rate fell from above 0.1 to ≤ 0.1 after `first` (collapses and recoveries)."""
    count, above = 0, True
    for step, success, *_ in rows:
        if step <= first:
            continue
        if above and success <= COLLAPSED:
            count += 1
        above = success > COLLAPSED
    return count


def best_evaluation(run):
    """(best mean_return, its step) of eval.csv."""
    with open(os.path.join(run, "eval.csv"), newline="") as file:
        rows = [(float(row["mean_return"]), int(row["timesteps"])) for row in csv.DictReader(file)]
    return max(rows)


def seed(run):
    """The run's seed from its resolved config.yaml (a top-level `seed:` line)."""
    with open(os.path.join(run, "config.yaml"), encoding="utf-8") as file:
        return int(re.search(r"^seed: *(\d+)", file.read(), re.M).group(1))


LABELS = {"base": "the page's setting", "vf_lr": "critic's rate = actor's",
          "unsquashed": "unsquashed mean", "target_kl": "target KL 0.02",
          "ent_coef": "entropy bonus 0.01"}


def table_rows(path):
    """The page's table, one row per variant (in LABELS' order), each seed's value in seed order."""
    with open(path, newline="") as file:
        runs = list(csv.DictReader(file))
    lines = []
    for variant, label in LABELS.items():
        group = sorted((run for run in runs if run["variant"] == variant),
                       key=lambda run: int(run["seed"]))
        if not group:
            continue

        def each(key, form=str):
            return ", ".join(form(run[key]) if run[key] else "–" for run in group)

        reached = sum(1 for run in group if run["first_success_step"])
        collapses = ", ".join(f"seed {run['seed']} at {int(run['collapse_step']) / 1e6:.2f} M"
                              for run in group if run["collapse_step"]) or "none"
        dips = sum(int(run["dips"]) for run in group if run["dips"])
        lengths = [float(run["dip_ep_len_min"]) for run in group if run["dip_ep_len_min"]]
        if lengths:
            dips = f"{dips} (shortest mean episode {min(lengths):.0f}–{max(lengths):.0f} steps)"
        plate = ", ".join(f"seed {run['seed']} from {int(run['plate_step']) / 1e6:.2f} M"
                          for run in group if run["plate_step"]) or "none"
        lines.append(f"| {label} | {reached} of {len(group)} | "
                     f"{each('first_success_step', lambda v: f'{int(v) / 1e3:.0f}')} | "
                     f"{collapses} | {dips} | {plate} | {each('final_success')} | "
                     f"{each('final_std')} | "
                     f"{each('best_eval_return', lambda v: v.replace('-', chr(0x2212)))} | "
                     f"{each('wall_s')} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out")
    parser.add_argument("--table", help="print the page's table rows from this CSV")
    parser.add_argument("runs", nargs="*", help="run directories under runs/sweeps/ppo_collapse_*")
    args = parser.parse_args()
    if args.table:
        print("\n".join(table_rows(args.table)))
        return
    if not args.out or not args.runs:
        parser.error("--out CSV and run directories, or --table CSV")
    table = []
    for run in args.runs:
        run = os.path.normpath(run)
        variant = os.path.basename(os.path.dirname(run)).removeprefix("ppo_collapse_")
        rows = progress(run)
        first = next((step for step, success, *_ in rows if success >= REACHED), None)
        collapse = collapse_step(rows, first) if first is not None else None
        lowest = min((success for step, success, *_ in rows if first is not None and step > first),
                     default=None)
        failing = [length for step, success, _, _, length in rows
                   if first is not None and step > first and success <= COLLAPSED]
        best_return, best_step = best_evaluation(run)
        table.append([variant, seed(run), rows[-1][0], "" if first is None else first,
                      "" if collapse is None else collapse, f"{rows[-1][1]:.2f}",
                      "" if lowest is None else f"{lowest:.2f}",
                      "" if first is None else dips(rows, first),
                      f"{min(failing):.0f}" if failing else "",
                      "" if plate_step(rows) is None else plate_step(rows),
                      f"{rows[-1][2]:.3f}",
                      f"{best_return:.0f}", best_step, f"{rows[-1][3]:.0f}"])
    with open(args.out, "w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(["variant", "seed", "steps", "first_success_step", "collapse_step",
                         "final_success", "min_success_after_first", "dips", "dip_ep_len_min",
                         "plate_step", "final_std", "best_eval_return", "best_eval_step",
                         "wall_s"])
        for row in table:
            writer.writerow(row)
            print(",".join(str(value) for value in row))


if __name__ == "__main__":
    main()
