#!/usr/bin/env python3
"""The numbers the results pages quote, read back from the committed files they come from.

Each check regenerates a table row or a sentence's numbers from a file beside a page
(docs/results/...) and requires the page to carry that text verbatim, so a page left stale after
its file changed (or a number typed by hand) fails. Every results page opens with its "Headline
numbers" table (3-8 rows: what is measured, the paper's number, tendril's, a verdict, where it is
read from); each row must name a file that exists or a section of the page, and the rows that
name a committed file have their tendril number regenerated from it. Python's standard library
only.
  python3 tests/docs/results_numbers_test.py SOURCE_DIR
"""
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import unicodedata

ROOT = sys.argv[1] if len(sys.argv) > 1 else "."
RESULTS = os.path.join(ROOT, "docs", "results")


def page(name):
    with open(os.path.join(RESULTS, name), encoding="utf-8") as file:
        return file.read()


def rows(path):
    """A CSV beside the pages, its `#` comment lines skipped."""
    with open(os.path.join(RESULTS, path), newline="") as file:
        return list(csv.DictReader(line for line in file if not line.startswith("#")))


def minus(text):
    """Negative numbers as the pages write them (U+2212)."""
    return text.replace("-", "\u2212")


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


def safety_filter_margin_feature():
    """The Dubins co-training with and without the margin input: the means over the seeds of
    margin_feature.csv, as the page's table rows give them."""
    table = rows("safety_filter/margin_feature.csv")

    def mean(variant, column):
        return statistics.mean(float(row[column]) for row in table if row["variant"] == variant)

    def both(formats):
        return " | ".join(formats(variant) for variant in ("plain", "margin"))

    def pair(returns, safety):
        return lambda v: minus(f"{mean(v, returns):.2f} / {mean(v, safety):.3f}")

    expected = [
        "| filtered return / safety at ε₂ = 0 | "
        + both(pair("filtered_return_eps0", "filtered_safety_rate_eps0")) + " |",
        "| filtered return / safety at Algorithm 3's ε₂ | "
        + both(pair("filtered_return", "filtered_safety_rate")) + " |",
        "| task agent alone: return / safety | "
        + both(pair("task_return", "task_safety_rate")) + " |",
        "| V > 0 on the slice: ring / disc / outside the walls | "
        + both(lambda v: " / ".join(f"{mean(v, c):.2f}" for c in (
            "v_positive_ring", "v_positive_disc", "v_positive_outside"))) + " |",
    ]
    return "safety_filter.md", "safety_filter/margin_feature.csv", expected


def signed(value):
    """A return as the pages write it: sign, thousands separator, U+2212."""
    return minus(f"{value:+,.0f}")


def elastica_buffer_studies():
    """The scaled replay-buffer studies of case 1 (Fig. 3): per buffer the seeds' final training
    means, the configuration's final evaluation (mean ± population std) and each seed's, read
    from the committed sweep summaries."""
    expected = []
    for study in ("tracking3d_ddpg_buffer_size_reduced", "tracking3d_td3_buffer_size_reduced"):
        folder = f"elastica/studies/{study}"
        runs = rows(f"{folder}/runs.csv")
        for configuration in rows(f"{folder}/configurations.csv"):
            buffer = int(configuration["algo.buffer_size"])
            seeds = sorted((run for run in runs
                            if run["configuration"] == configuration["configuration"]),
                           key=lambda run: run["run"])
            paper = {20000: "100k", 100000: "500k", 400000: "2M"}[buffer]
            train = " / ".join(signed(float(run["final_train_mean"])) for run in seeds)
            final = " / ".join(signed(float(run["final_eval_mean"])) for run in seeds)
            mean = signed(float(configuration["final_eval_mean"]))
            std = f"{float(configuration['final_eval_std']):,.0f}"
            expected.append(
                f"| {buffer // 1000}k ({paper}) | {train} | {mean} ± {std} | {final} |")
    return "elastica.md", "elastica/studies/*/", expected


def elastica_penalty_phi10():
    """Case 3's φ = 10 arm from the contact policy and at 10M steps: each variant's row of
    penalty_phi10.csv as the page gives it (seeds joined by " / ")."""
    table = rows("elastica/studies/penalty_phi10.csv")
    labels = {"contact_policy_under_penalty": "the contact policy, unchanged",
              "from_contact": "warm-started from it, 2M steps",
              "from_scratch_10m": "from scratch, 10M steps"}
    expected = []
    for variant, label in labels.items():
        runs = [row for row in table if row["variant"] == variant]

        def joined(column, form):
            return " / ".join(form(float(row[column])) for row in runs)

        def elements(value):
            return f"{value:.2g}" if value < 1 else f"{value:.1f}"

        expected.append(
            f"| {label} | {' / '.join(row['seed'] for row in runs)} | "
            + minus(f"{joined('penalty_return', lambda v: f'{v:,.0f}')} | "
                    f"{joined('distance_m', lambda v: f'{v:.3f}')} | "
                    f"{joined('intersecting_elements', elements)} |"))
    return "elastica.md", "elastica/studies/penalty_phi10.csv", expected


def ur5_bonus_ladder():
    """The success-bonus study: per rung and bonus, the mean over the seed's five seeds and each
    seed's final training success, from bonus_ladder.csv's run rows."""
    table = rows("ur5/bonus_ladder.csv")
    rungs = {"base": "base", "exp_distance": "+ exp distance",
             "action_penalty": "+ action penalty 0.05"}
    expected = []
    for rung, label in rungs.items():
        for bonus, shown in (("0", "0"), ("10", "+10")):
            prefix = f"runs/sweeps/ur5_ppo_{rung}_bonus/success_bonus_{bonus}-seed_"
            by_seed = {int(row["seed"]): float(row["success_final"]) for row in table
                       if row["run"].startswith(prefix)}
            values = [by_seed[seed] for seed in (42, 55, 100, 200, 300)]
            each = " / ".join(f"{value:.2f}" for value in values)
            expected.append(f"| {'base' if rung == 'base' else label} | {shown} | "
                            f"**{statistics.mean(values):.2f}** | {each} |")
    return "ur5.md", "ur5/bonus_ladder.csv", expected


def sma_limb_rl_budget_capacity():
    """The LK Encoder at 1M steps and the 2 × 512 No Head runs, from budget_capacity_runs.csv."""
    runs = {row["run"]: row for row in rows("sma_limb_rl/budget_capacity_runs.csv")}
    labels = (("lk_encoder_1m_seed0", "LK Encoder, the thesis' budget (seed 0)",
               "**{:.2f}** (thesis 1.00)"),
              ("no_head_2x512_seed0", "MLP No Head, 2 × 512 (seed 0)", "{:.2f}"),
              ("no_head_2x512_seed1", "MLP No Head, 2 × 512 (seed 1)", "{:.2f}"))
    expected = []
    for run, label, success in labels:
        row = runs[run]
        expected.append(minus(
            f"| {label} | {int(row['steps']):,} | {success.format(float(row['success_final']))} | "
            f"{float(row['eval_return_final']):.1f} | {row['wall_s']} s |"))
    return "sma_limb_rl.md", "sma_limb_rl/budget_capacity_runs.csv", expected


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


def learned_dynamics_twin_damping():
    """The twin's damping: its free response and steps per damping rate (damping_summary.csv),
    and persistence on the 10 min exploration data sets (persistence_10min.csv) and the committed
    test split (persistence_stiff_test.csv)."""
    def number(text, digits, scale=1.0):
        value = float(text)
        return "—" if math.isnan(value) else f"{scale * value:.{digits}f}"

    directory = os.path.join("learned_dynamics", "twin_damping")
    summary = rows(os.path.join(directory, "damping_summary.csv"))
    expected = []
    zeta = {}
    for row in summary:
        rate = row["damping_rate_per_s"]
        zeta[rate] = number(row["zeta_rayleigh"], 2)
        expected.append(
            f"| {rate} | {number(row['release_frequency_hz'], 2)} | "
            f"{number(row['release_zeta'], 2)} / {number(row['release_zeta_full'], 2)} | "
            f"{zeta[rate]} | {number(row['release_undershoot'], 1, 100)} % | "
            f"{number(row['release_settle_2pct_s'], 2)} s | "
            f"{number(row['step_sampled_largest_domega_deg_s'], 1)} | "
            f"{number(row['staircase_persistence_change_deg_s'], 1)} / "
            f"{number(row['staircase_persistence_steady_deg_s'], 1)} |")
    default = next(row["damping_rate_per_s"] for row in summary
                   if float(row["damping_rate_per_s"]) == 15)
    data = rows(os.path.join(directory, "persistence_stiff_test.csv"))
    data += rows(os.path.join(directory, "persistence_10min.csv"))
    for row in data:
        continuous = row["data_set"].startswith("continuous_")
        rate = row["data_set"].removeprefix("rate_").removeprefix("continuous_")
        label = {"stiff_exploration": "15, committed test split (30 min)",
                 "default": "15 (the twin's own)"}.get(rate, rate)
        if continuous:
            label = ("15" if rate == "default" else rate) + ", continuous phase"
        key = default if rate in ("stiff_exploration", "default") else rate
        expected.append(
            f"| {label} | {zeta[key]} | {row['persistence_rmse_omega']} | "
            f"{row['persistence_rmse_omega_input_change']} | "
            f"{row['persistence_rmse_omega_steady_input']} | "
            f"{number(row['largest_1pct_share'], 0, 100)} % | "
            f"{row['persistence_rmse_omega_without_largest_1pct']} | "
            f"{row['raw_jumps_over_30deg']} | {number(row['share_rate_beyond_80'], 1, 100)} % |")
    return "learned_dynamics.md", directory + "/*.csv", expected


def pneumatic_open_loop_spread():
    """The open-loop trials' range of final distances (Fig. 7 counterpart)."""
    distances = [float(row["goal_distance_mm"])
                 for row in rows("pneumatic_arm/learned/open_loop_S0.csv")]
    return ("pneumatic_arm.md", "pneumatic_arm/learned/open_loop_S0.csv",
            [f"({min(distances):.1f}–{max(distances):.1f} mm over the {len(distances)} trials"])


def pneumatic_initial_offset():
    """The closed-loop trials on the twin of the policies trained from one rest and from varied
    starts (initial_offset_mm), one row per policy: its best evaluation in the model (eval_*.csv,
    the one save_best kept) and its episodes on the twin (closed_loop_*.csv)."""
    expected = []
    for start, prefix in (("one rest", "rest"), ("rest + up to 40 mm", "offset40")):
        for seed in (0, 1, 2):
            trials = rows(f"pneumatic_arm/initial_offset/closed_loop_{prefix}_seed{seed}.csv")
            success = [float(row["is_success"]) for row in trials]
            collision = [float(row["collision"]) for row in trials]
            neither = [1.0 - s - c for s, c in zip(success, collision)]
            shares = " / ".join(f"{100 * statistics.mean(v):.0f}" for v in
                                (success, collision, neither))
            distance = mean_sd([float(row["goal_distance_mm"]) for row in trials], 1)
            length = statistics.mean(float(row["length"]) for row in trials)
            evaluations = rows(f"pneumatic_arm/initial_offset/eval_{prefix}_seed{seed}.csv")
            best = max(evaluations, key=lambda row: float(row["mean_return"]))
            in_model = (f"{int(best['timesteps']) // 1000} k: "
                        f"{100 * float(best['success_rate']):.0f} % of {best['episodes']}")
            expected.append(f"| {start} | {seed} | {in_model} | {shares} % ({len(trials)} trials) "
                            f"| {distance} | {length:.1f} |")
    return "pneumatic_arm.md", "pneumatic_arm/initial_offset/*.csv", expected


def beam_variants():
    """Seed 003's variants (early termination; case 1 from case 2): per experiment, --set keys and
    steps, the mean over seeds and each seed's value, from variants.csv."""
    groups = {}
    for row in rows("beam/variants.csv"):
        groups.setdefault((row["config"], row["overrides"], row["steps"]), []).append(row)
    expected = []
    for (_, _, steps), runs in groups.items():
        def spread(key, digits):
            values = [float(run[key]) for run in runs]
            each = ", ".join(f"{value:.{digits}f}" for value in values)
            return f"{statistics.mean(values):.{digits}f} ({each})"
        velocity = statistics.mean(float(run["velocity_error_m_s"]) for run in runs)
        walls = ", ".join(run["wall_s"] for run in runs)
        expected.append(minus(f"| {int(steps) // 1000}k | {spread('mean_distance_m', 3)} | "
                              f"{velocity:.3g} | {spread('reward_per_step', 2)} | {walls} |"))
    return "beam.md", "beam/variants.csv", expected


def pneumatic_ppo_collapse():
    """The PPO collapse experiment: every variant's row as ppo_collapse.py builds it from
    ppo_collapse.csv."""
    script = os.path.join(RESULTS, "pneumatic_arm", "ppo_collapse.py")
    done = subprocess.run([sys.executable, script, "--table",
                           os.path.join(RESULTS, "pneumatic_arm", "ppo_collapse.csv")],
                          capture_output=True, text=True, check=True)
    expected = [line for line in done.stdout.splitlines() if line.startswith("| ")]
    assert len(expected) >= 2, done.stdout
    return "pneumatic_arm.md", "pneumatic_arm/ppo_collapse.csv", expected


# --- The headline tables -------------------------------------------------------------------------

HEADLINE_HEADING = "## Headline numbers"


def slug(heading):
    """The anchor mkdocs' toc extension gives a heading (its default slugify)."""
    text = unicodedata.normalize("NFKD", heading.replace("`", ""))
    text = re.sub(r"[^\w\s-]", "", text.encode("ascii", "ignore").decode("ascii")).strip().lower()
    return re.sub(r"[-\s]+", "-", text)


def cells(line):
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


def headline_table(name):
    """The page's headline rows by their first cell, and the problems with the table's shape."""
    lines = page(name).split("\n")
    problems = []
    opening = lines.index(HEADLINE_HEADING) if HEADLINE_HEADING in lines else 0
    between = [line for line in lines[1:opening] if line.strip()]
    if (not lines[0].startswith("# ") or not between
            or not between[0].startswith("> Build mode") or any(
                not line.startswith(">") for line in between)):
        return {}, [f"does not open with its title, the build-mode line and '{HEADLINE_HEADING}'"]
    start = opening + 2
    table = []
    for line in lines[start:]:
        if not line.startswith("|"):
            break
        table.append(cells(line))
    header, rows_ = (table[0], table[2:]) if len(table) > 2 else ([], [])
    if (len(header) != 5 or header[0] or not header[1].startswith("paper")
            or not header[2].startswith("tendril") or header[3:] != ["verdict", "read from"]):
        problems.append(f"headline header is {header}, "
                        "not | | paper … | tendril … | verdict | read from |")
    if not 3 <= len(rows_) <= 8:
        problems.append(f"headline table has {len(rows_)} rows, not 3-8")
    anchors = {slug(line.lstrip("#").strip()) for line in lines if re.match(r"#{2,6} ", line)}
    for row in rows_:
        if len(row) != 5 or not all(row[1:]):
            problems.append(f"headline row {row[0]!r} has an empty or missing cell")
            continue
        files = re.findall(r"`([^`]+)`", row[4])
        links = re.findall(r"\]\(#([^)]+)\)", row[4])
        if not files and not links:
            problems.append(f"headline row {row[0]!r} names neither a file nor a section")
        for file in files:
            if not (os.path.exists(os.path.join(RESULTS, file))
                    or os.path.exists(os.path.join(ROOT, file))):
                problems.append(f"headline row {row[0]!r} reads from {file}, which does not exist")
        for link in links:
            if link not in anchors:
                problems.append(f"headline row {row[0]!r} links #{link}, no heading of the page")
    return {row[0]: row for row in rows_}, problems


def mean_sd(values, digits, population=True):
    spread = statistics.pstdev(values) if population else statistics.stdev(values)
    return minus(f"{statistics.mean(values):.{digits}f} ± {spread:.{digits}f}")


def headline_safety_filter():
    name = "safety_filter.md"
    co_trained = [row for row in rows("safety_filter/table_6_1.csv")
                  if row["method"] == "co_trained"]
    epsilons = [float(row["epsilon"]) for row in rows("safety_filter/epsilon_search.csv")]
    ppo = [float(row["filtered_safety_rate"]) for row in rows("safety_filter/table_6_2.csv")
           if row["method"] == "dubins_ppo"]
    grid = rows("safety_filter/double_integrator_map.csv")
    learned = [row for row in grid if float(row["value"]) > 0]
    outside = sum(row["analytic_safe"] == "0" for row in learned)
    diamond = rows("safety_filter/limb_diamond.csv")

    def violations(epsilon):
        trials = [row for row in diamond if float(row["epsilon"]) == epsilon]
        hits = sum(not math.isnan(float(row["time_to_violation_s"])) for row in trials)
        return f"{hits} of {len(trials)} at ε₂ = {epsilon}"

    return [
        (name, "Dubins car, filtered policy: safety rate", "safety_filter/table_6_1.csv",
         mean_sd([float(row["filtered_safety_rate"]) for row in co_trained], 3)),
        (name, "Dubins car, filtered policy: return", "safety_filter/table_6_1.csv",
         mean_sd([float(row["filtered_return"]) for row in co_trained], 2)),
        (name, "Dubins car: steps the filter takes over", "safety_filter/table_6_1.csv",
         mean_sd([float(row["intervention_rate"]) for row in co_trained], 2)),
        (name, "Dubins car: Algorithm 3's ε₂", "safety_filter/epsilon_search.csv",
         minus(f"{min(epsilons):.2f} to {max(epsilons):.2f} over the {len(epsilons)} seeds")),
        (name, "Dubins car, filter on PPO not co-trained: safety rate",
         "safety_filter/table_6_2.csv", mean_sd(ppo, 3)),
        (name, "double integrator: learned safe set at ε₂ = 0 outside the analytic set",
         "safety_filter/double_integrator_map.csv", f"{outside} of {len(learned)} grid points"),
        (name, "limb diamond: trials leaving the 30° circle", "safety_filter/limb_diamond.csv",
         f"{violations(90)}, {violations(270)}"),
    ]


def headline_pneumatic_adaptation():
    name = "pneumatic_adaptation.md"
    expected = []
    for method, label in (("gprca", "GPRCA"), ("boac", "BOAC")):
        source = f"pneumatic_adaptation/{method}/summary.csv"
        runs = rows(source)
        reached = [row for row in runs if row["goal_flag"] == "1"]
        accuracy = [float(row["final_distance_mm"]) for row in reached]
        online = [float(row["robot_s"]) for row in reached]
        expected += [
            (name, f"{label}: final accuracy where the goal was reached", source,
             f"{mean_sd(accuracy, 2)} mm ({len(reached)} runs)"),
            (name, f"{label}: online time where the goal was reached", source,
             f"{mean_sd(online, 1)} s"),
            (name, f"{label}: how often the goal is reached", source,
             f"{len(reached)} of {len(runs)} runs")]
        if method == "gprca":
            expected.append((name, "GPRCA: the learner's work in one 10 Hz step, largest", source,
                             f"{max(float(row['max_update_ms']) for row in runs):.1f} ms"))
        else:
            oracle = [float(row["oracle_robot_s"]) for row in reached]
            expected.append((name, "BOAC: online time where the goal was reached", source,
                             f"plus {min(oracle):.1f}–{max(oracle):.1f} s of oracle trials"))
    return expected


def headline_pneumatic_arm():
    name = "pneumatic_arm.md"
    open_loop = rows("pneumatic_arm/learned/open_loop_S0.csv")
    closed_loop = rows("pneumatic_arm/learned/closed_loop_S0.csv")
    plans = [float(row["final_distance_mm"])
             for row in rows("pneumatic_arm/calibration/e0.10_d10_c40/open_loop_reach.csv")
             if row["scenario"] == "S0"]
    errors = {(row["metric"], row["group"]): float(row["rmse"])
              for row in rows("pneumatic_arm/learned/model_error_s0.csv")}
    gap = rows("pneumatic_arm/model_gap/replay_gap.csv")
    module3 = {}
    for row in gap:
        if row["module"] == "3":
            module3.setdefault(row["scenario"], []).append(float(row["mad_from_reference_mm"]))
    order = sorted(module3, key=lambda scenario: -statistics.mean(module3[scenario]))

    def share(values):
        return f"{100 * statistics.mean(values):.0f} %"

    return [
        (name, "the PPO policy open loop, intact arm: success within 5 mm",
         "pneumatic_arm/learned/open_loop_S0.csv",
         f"{share([float(row['is_success']) for row in open_loop])} ({len(open_loop)} trials)"),
        (name, "the PPO policy open loop, intact arm: final distance",
         "pneumatic_arm/learned/open_loop_S0.csv",
         f"{mean_sd([float(row['goal_distance_mm']) for row in open_loop], 1)} mm"),
        (name, "the PPO policy closed loop, intact arm: success within 15 mm / collisions",
         "pneumatic_arm/learned/closed_loop_S0.csv",
         f"{share([float(row['is_success']) for row in closed_loop])} / "
         f"{share([float(row['collision']) for row in closed_loop])} ({len(closed_loop)} trials)"),
        (name, "perfect-model plans open loop, intact arm: within 5 mm / within 15–25 mm",
         "pneumatic_arm/calibration/e0.10_d10_c40/open_loop_reach.csv",
         f"{share([d <= 5 for d in plans])} / {share([15 <= d <= 25 for d in plans])} "
         f"({len(plans)} trials, {mean_sd(plans, 2)} mm)"),
        (name, "the LSTM's 60 s rollout error, module 3, intact arm",
         "pneumatic_arm/learned/model_error_s0.csv",
         f"{math.sqrt(sum(errors[('rollout', axis + '3')] ** 2 for axis in 'xyz')):.1f} mm RMS"),
        (name, "model-vs-arm gap across damage scenarios, module 3",
         "pneumatic_arm/model_gap/replay_gap.csv",
         " > ".join(order) + " (" +
         ", ".join(f"{statistics.mean(module3[s]):.2f}" for s in order) + " mm)"),
    ]


def headline_learned_dynamics():
    source = "learned_dynamics/table4_1_seq2seq_baselines.csv"
    errors = {(row["metric"], row["horizon_s"], row["group"]): float(row["rmse"])
              for row in rows(source)}
    name = "learned_dynamics.md"
    return [
        (name, "Seq2Seq, stiff limb: one-step angle RMSE", source,
         f"{errors[('one_step', '0', 'angle')]:.2f}°"),
        (name, "Seq2Seq, stiff limb: one-step velocity RMSE", source,
         f"{errors[('one_step', '0', 'velocity')]:.2f} °/s (predicting no change: "
         f"{errors[('persistence_one_step', '0', 'velocity')]:.2f})"),
        (name, "Seq2Seq, stiff limb: 60 s rollout angle RMSE", source,
         f"{errors[('rollout', '60', 'angle')]:.2f}°"),
    ]


def headline_sma_limb():
    name = "sma_limb.md"
    expected = []

    def span(values, text):
        low, high = text(min(values)), text(max(values))
        return low if low == high else f"{low}–{high}"

    def percent(pwm):
        return f"{100 * pwm / 255:.1f}"  # the duty of the 8-bit PWM

    for limb in ("stiff", "soft"):
        source = f"sma_limb/fig4_1_calibration_curves_{limb}.csv"
        curves = rows(source)
        lower = [int(row["pwm"]) for row in curves if row["lower"] == "1"]
        upper = [int(row["pwm"]) for row in curves if row["upper"] == "1"]
        label = ("stiff limb: lower / upper input bound (PWM duty)" if limb == "stiff"
                 else "soft limb: lower / upper input bound")
        expected.append((name, label, source,
                         f"{span(lower, percent)} % / {span(upper, percent)} % "
                         f"(PWM {span(lower, str)} / {span(upper, str)})"))
        source = f"sma_limb/fig4_2_coverage_{limb}.csv"
        coverage = rows(source)
        evenness = {kind: {row["seed"]: float(row["evenness"]) for row in coverage
                           if row["source"] == kind} for kind in ("explore", "babble")}
        ahead = sum(evenness["explore"][seed] > evenness["babble"][seed]
                    for seed in evenness["explore"])
        expected.append((
            name, f"{limb} limb, first 10 min: evenness of exploration / babbling", source,
            f"{mean_sd(list(evenness['explore'].values()), 3, population=False)} / "
            f"{mean_sd(list(evenness['babble'].values()), 3, population=False)} "
            f"(more even on {ahead} of {len(evenness['explore'])} seeds)"))
    with open(os.path.join(ROOT, "data", "sma_limb", "stiff_exploration.csv")) as file:
        readings = sum(1 for line in file if not line.startswith("#")) - 1
    expected.append((name, "stiff exploration data set", "data/sma_limb/stiff_exploration.csv",
                     f"{readings:,} readings"))
    return expected


def headline_sma_limb_rl():
    name = "sma_limb_rl.md"
    runs = rows("sma_limb_rl/training_runs.csv")
    tracking = {(row["log"], row["pattern"]): row for row in rows("sma_limb_rl/tracking.csv")}

    def success(head):
        rates = [float(row["success_final"]) for row in runs
                 if re.fullmatch(rf"table51_{head}_seed\d+", row["run"])]
        return f"{mean_sd(rates, 2, population=False)} ({len(rates)} seeds"

    def average(log, paths):
        """Mean RMSE over the paths, None unless every one was finished."""
        picked = [tracking[(log + suffix, pattern)] for suffix, pattern in paths]
        if any(row["finished"] != "yes" for row in picked):
            return None
        return sum(float(row["rmse_deg"]) for row in picked) / len(picked)

    shapes = [("", "spiral"), ("", "square"), ("", "sml")]
    tests = [("_push", "circle"), ("_soft", "circle"), ("_load10", "circle")]
    policies = {seed: [average(f"lk_encoder_seed{seed}_{actions}", shapes)
                       for actions in ("mean", "sampled")] for seed in "012"}
    tracked = [value for values in policies.values() for value in values]
    robust = {seed: [v for v in (average(f"lk_encoder_seed{seed}_{actions}", tests)
                                 for actions in ("mean", "sampled")) if v is not None]
              for seed in "012"}
    late = robust["1"] + robust["2"]
    budget = {row["run"]: row for row in rows("sma_limb_rl/budget_capacity_runs.csv")}
    return [
        (name, "LK Encoder head: success at 1° in the learned model",
         "sma_limb_rl/training_runs.csv", success("lk_encoder")),
        (name, "LK Encoder head at the thesis' budget (1M steps): success at 1°",
         "sma_limb_rl/budget_capacity_runs.csv",
         f"{float(budget['lk_encoder_1m_seed0']['success_final']):.2f} (seed 0)"),
        (name, "MLP No Head: success at 1°", "sma_limb_rl/training_runs.csv", success("no_head")),
        (name, "LK Encoder policy tracking spiral, square and SML: mean RMSE",
         "sma_limb_rl/tracking.csv", f"{min(tracked):.2f}–{max(tracked):.2f}° (3 seeds"),
        (name, "PID tracking spiral, square and SML: mean RMSE", "sma_limb_rl/tracking.csv",
         f"{average('pid', shapes):.2f}°"),
        (name, "robustness on the circle (push, soft limb, 10 g): LK Encoder against PID",
         "sma_limb_rl/tracking.csv",
         f"{min(late):.2f}–{max(late):.2f}° (seeds 1 and 2) and "
         + ", ".join(f"{value:.2f}" for value in robust["0"])
         + f"° (seed 0) against {average('pid', tests):.2f}°"),
    ]


def headline_beam():
    """Case 1 started from case 2's model, at the seed's 300k steps, from variants.csv."""
    distances = [float(row["mean_distance_m"]) for row in rows("beam/variants.csv")
                 if row["config"] == "trajectory_case1_from_case2_sac.yaml"
                 and row["steps"] == "300000"]
    return [("beam.md", "task 2, case 1: mean tip distance", "beam/variants.csv",
             f"{statistics.mean(distances):.3f} m from case 2's model ({len(distances)} seeds")]


def headline_implicit_rods():
    name, source = "implicit_rods.md", "implicit_rods/accuracy.csv"
    table = [row for row in rows(source) if row["integrator"] != "verlet"]
    within = sum(row["within_tolerance"] == "1" for row in table)
    schemes = {"backward_euler": "backward Euler", "bdf2": "BDF2"}

    def deviation(row):
        value = f"{float(row['max_deviation']):.3g}"
        return f"{value}°" if row["unit"] == "deg" else f"{value} {row['unit']}"

    def fastest(robot):
        row = max((row for row in table if row["robot"] == robot),
                  key=lambda row: float(row["speed_vs_reference"]))
        return (f"{float(row['speed_vs_reference']):.2f}× at {deviation(row)} "
                f"({schemes[row['integrator']]}, {row['step_ms']} ms)")

    bdf2_1ms = next(row for row in table if row["robot"] == "pneumatic"
                    and row["integrator"] == "bdf2" and float(row["step_ms"]) == 1)
    # Position Verlet at half the reference's step: the reference's own discretisation error.
    halves = [row for row in rows(source) if row["integrator"] == "verlet"
              and float(row["max_deviation"]) > 0]
    floor = "; ".join(f"{row['robot']} {deviation(row)}" for row in halves)
    return [
        (name, "implicit configurations within the sensor noise", source,
         f"{within} of {len(table)}"),
        (name, "pneumatic arm, BDF2 at 1 ms", source,
         f"{float(bdf2_1ms['max_deviation']):.2f} mm, "
         f"{float(bdf2_1ms['speed_vs_reference']):.2f}× the explicit speed"),
        (name, "pneumatic arm, fastest implicit step", source, fastest("pneumatic")),
        (name, "Elastica case 3 with contact, fastest implicit step", source, fastest("case3")),
        (name, "SMA limb, fastest implicit step", source, fastest("sma")),
        (name, "SMA limb with continuous phase re-entry, fastest implicit step", source,
         fastest("sma_continuous")),
        (name, "the reference's own error: position Verlet at half its step", source, floor),
    ]


HEADLINE_CHECKS = (headline_safety_filter, headline_pneumatic_adaptation, headline_pneumatic_arm,
                   headline_learned_dynamics, headline_sma_limb, headline_sma_limb_rl,
                   headline_implicit_rods, headline_beam)


def check_headlines():
    """The shape of every page's headline table, then its rows read from committed files."""
    failures = 0
    tables = {}
    for name in sorted(os.listdir(RESULTS)):
        if name.endswith(".md"):
            tables[name], problems = headline_table(name)
            for problem in problems:
                print(f"docs/results/{name}: {problem}")
            failures += len(problems)
    checked = 0
    for check in HEADLINE_CHECKS:
        for name, label, source, expected in check():
            row = tables.get(name, {}).get(label)
            checked += 1
            if row is None:
                print(f"docs/results/{name}: no headline row {label!r}")
            elif f"`{source}`" not in row[4]:
                print(f"docs/results/{name}: headline row {label!r} does not cite `{source}`")
            elif expected not in row[2]:
                print(f"docs/results/{name}: headline row {label!r} stale against {source}; "
                      f"expected its tendril cell to hold\n  {expected}\n  it is\n  {row[2]}")
            else:
                continue
            failures += 1
    return failures, len(tables), checked


CHECKS = (sma_limb_rl_tables, safety_filter_limb, safety_filter_baselines,
          safety_filter_margin_feature, learned_dynamics_baselines, learned_dynamics_twin_damping,
          pneumatic_open_loop_spread, beam_variants, pneumatic_initial_offset,
          pneumatic_ppo_collapse, elastica_buffer_studies, elastica_penalty_phi10, ur5_bonus_ladder,
          sma_limb_rl_budget_capacity)


def main():
    failures = 0
    for check in CHECKS:
        name, source, expected = check()
        text = page(name)
        missing = [line for line in expected if line not in text]
        for line in missing:
            print(f"docs/results/{name}: stale against {source}; expected the text\n  {line}")
        failures += len(missing)
    headline_failures, pages, rows_checked = check_headlines()
    failures += headline_failures
    if failures:
        sys.exit(f"{failures} quoted numbers or headline rows differ from their files")
    print(f"{len(CHECKS)} checks and the headline tables of {pages} pages ({rows_checked} rows "
          "read back from their files): every quoted number matches its file")


if __name__ == "__main__":
    main()
