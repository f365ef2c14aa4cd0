#!/usr/bin/env python3
"""The numbers the results pages quote, read back from the committed files they come from.

Each check regenerates a table row or a sentence's numbers from a file beside a page
(docs/results/...) and requires the page to carry that text verbatim, so a page left stale after
its file changed (or a number typed by hand) fails. Python's standard library only.
  python3 tests/docs/results_numbers_test.py SOURCE_DIR
"""
import csv
import math
import os
import statistics
import subprocess
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else "."
RESULTS = os.path.join(ROOT, "docs", "results")


def page(name):
    with open(os.path.join(RESULTS, name), encoding="utf-8") as file:
        return file.read()


def rows(path):
    with open(os.path.join(RESULTS, path), newline="") as file:
        return list(csv.DictReader(file))


def sma_limb_rl_tables():
    """Tables 5.1, 5.4 and 5.5: every row as summary.py builds it from training_runs.csv and
    tracking.csv."""
    script = os.path.join(RESULTS, "sma_limb_rl", "summary.py")
    done = subprocess.run([sys.executable, script, "tables",
                           os.path.join(RESULTS, "sma_limb_rl", "tracking.csv"),
                           os.path.join(RESULTS, "sma_limb_rl", "training_runs.csv")],
                          capture_output=True, text=True, check=True)
    expected = [line for line in done.stdout.splitlines() if line.startswith("| ")]
    assert len(expected) >= 22, done.stdout
    return ("sma_limb_rl.md", "sma_limb_rl/training_runs.csv and tracking.csv", expected)


def safety_filter_limb():
    """The limb's diamond table (Figs. 6.6-6.7) from limb_diamond.csv."""
    table = rows("safety_filter/limb_diamond.csv")
    expected = []
    epsilons = []
    for row in table:
        if row["epsilon"] not in epsilons:
            epsilons.append(row["epsilon"])
    for epsilon in epsilons:
        trials = [row for row in table if row["epsilon"] == epsilon]
        times = [float(row["time_to_violation_s"]) for row in trials]
        hits = [t for t in times if not math.isnan(t)]
        per_trial = ", ".join("—" if math.isnan(t) else f"{t:.2f}" for t in times)
        name = "unfiltered" if float(epsilon) == -1000 else epsilon
        mean = f"{statistics.mean(hits):.2f}" if hits else "—"
        interventions = statistics.mean(float(row["intervention_rate"]) for row in trials)
        expected.append(f"| {name} | {len(hits)}/{len(times)} | "
                        f"{per_trial if hits else '—'} | {mean} | {interventions:.2f} |")
    return "safety_filter.md", "safety_filter/limb_diamond.csv", expected


def safety_filter_baselines():
    """Table 6.1's reward penalty and Lagrangian safety rates, means over the seeds."""
    table = rows("safety_filter/table_6_1.csv")
    means = [statistics.mean(float(row["unfiltered_safety_rate"]) for row in table
                             if row["method"] == method)
             for method in ("dubins_reward_penalty", "dubins_lagrangian")]
    return ("safety_filter.md", "safety_filter/table_6_1.csv",
            [f"(safety rates {means[0]:.3f} and {means[1]:.3f}, the means over the 10 seeds"])


def learned_dynamics_baselines():
    """Tables 4.1-4.2: the predict-no-change row and the velocity split by throttle change."""
    expected = []
    for name, horizon in (("table4_1_seq2seq_baselines.csv", "1800"),
                          ("table4_2_stiff_seq2seq_on_soft_baselines.csv", "600")):
        errors = {(row["metric"], row["horizon_s"], row["group"]): float(row["rmse"])
                  for row in rows(os.path.join("learned_dynamics", name))}
        cells = [errors[("persistence_rollout", "60", "velocity")],
                 errors[("persistence_rollout", "60", "angle")],
                 errors[("persistence_rollout", horizon, "velocity")],
                 errors[("persistence_rollout", horizon, "angle")],
                 errors[("persistence_one_step", "0", "velocity")],
                 errors[("persistence_one_step", "0", "angle")]]
        expected.append("| predict no change (same points) | " +
                        " | ".join(f"{value:.2f}" for value in cells) + " |")
        if horizon == "1800":
            for label, prefix in (("Seq2Seq", ""), ("predict no change", "persistence_")):
                split = [errors[(f"{prefix}one_step_input_change", "0", "velocity")],
                         errors[(f"{prefix}one_step_steady_input", "0", "velocity")],
                         errors[(f"{prefix}one_step", "0", "velocity")]]
                expected.append(f"| {label} | " + " | ".join(f"{v:.2f}" for v in split) + " |")
    return "learned_dynamics.md", "learned_dynamics/table4_*_baselines.csv", expected


def pneumatic_open_loop_spread():
    """The open-loop trials' range of final distances (Fig. 7 counterpart)."""
    distances = [float(row["goal_distance_mm"])
                 for row in rows("pneumatic_arm/learned/open_loop_S0.csv")]
    return ("pneumatic_arm.md", "pneumatic_arm/learned/open_loop_S0.csv",
            [f"({min(distances):.1f}–{max(distances):.1f} mm over the {len(distances)} trials"])


CHECKS = (sma_limb_rl_tables, safety_filter_limb, safety_filter_baselines,
          learned_dynamics_baselines, pneumatic_open_loop_spread)


def main():
    failures = 0
    for check in CHECKS:
        name, source, expected = check()
        text = page(name)
        missing = [line for line in expected if line not in text]
        for line in missing:
            print(f"docs/results/{name}: stale against {source}; expected the text\n  {line}")
        failures += len(missing)
    if failures:
        sys.exit(f"{failures} quoted numbers differ from their files")
    print(f"{len(CHECKS)} checks: every quoted number matches its file")


if __name__ == "__main__":
    main()
