#!/usr/bin/env python3
"""Gathers the data behind docs/results/ur5.md's figures from run directories into CSV files
beside the page (Python's standard library only).

  /usr/bin/python3 docs/results/ur5/collect.py curves OUT.csv RUN_DIR...
      One row per progress.csv row of each run: run, seed, timesteps, success_rate (last 100
      episodes), episode_return_mean, episode_length_mean, time_elapsed_s.
  /usr/bin/python3 docs/results/ur5/collect.py trajectories OUT.csv LABEL=ROLLOUT.csv...
      One row per step of `tendril rollout` files of UR5/Reach-v0: label, episode, step,
      flange_x/y/z and target_x/y/z (m, lab frame; observations 12-17 after the step), distance,
      orientation_error, is_success, collision. Each episode starts with its reset position
      (step 0).
  /usr/bin/python3 docs/results/ur5/collect.py summary RUN_DIR...
      Per run: the success rate of the last 100 training episodes at the first log row past
      250k and 500k steps and at the end, the final mean episode length and return, the steps
      and the training's wall time (s).
"""
import csv
import os
import sys



def seed_of(run_dir):
    with open(os.path.join(run_dir, "config.yaml")) as config:
        for line in config:
            if line.startswith("seed:"):
                return int(line.split(":", 1)[1])
    raise SystemExit(f"{run_dir}: no seed in config.yaml")


def curves(out_path, run_dirs):
    with open(out_path, "x", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["run", "seed", "timesteps", "success_rate", "episode_return_mean",
                         "episode_length_mean", "time_elapsed_s"])
        for run_dir in run_dirs:
            seed = seed_of(run_dir)
            with open(os.path.join(run_dir, "progress.csv"), newline="") as progress:
                for row in csv.DictReader(progress):
                    writer.writerow([os.path.basename(os.path.normpath(run_dir)), seed,
                                     row["time/total_timesteps"],
                                     row.get("rollout/success_rate", ""),
                                     row.get("rollout/ep_rew_mean", ""),
                                     row.get("rollout/ep_len_mean", ""),
                                     row["time/time_elapsed"]])


def trajectories(out_path, labelled_files):
    with open(out_path, "x", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["label", "episode", "step", "flange_x", "flange_y", "flange_z",
                         "target_x", "target_y", "target_z", "distance", "orientation_error",
                         "is_success", "collision"])
        for item in labelled_files:
            label, path = item.split("=", 1)
            with open(path, newline="") as rollout:
                for row in csv.DictReader(rollout):
                    if row["step"] == "0":
                        start = [row[f"observation_{i}"] for i in range(12, 18)]
                        writer.writerow([label, row["episode"], 0, *start, "", "", 0, 0])
                    after = [row[f"next_observation_{i}"] for i in range(12, 18)]
                    writer.writerow([label, row["episode"], int(row["step"]) + 1, *after,
                                     row["distance"], row["orientation_error"],
                                     row["is_success"], row["collision"]])


def summary(run_dirs):
    print("run,seed,success_250k,success_500k,success_final,length_final,return_final,steps,"
          "wall_s")
    for run_dir in run_dirs:
        with open(os.path.join(run_dir, "progress.csv"), newline="") as progress:
            rows = list(csv.DictReader(progress))
        def success_after(steps):
            for row in rows:
                if float(row["time/total_timesteps"]) >= steps:
                    return row.get("rollout/success_rate", "")
            return ""
        last = rows[-1]
        print(",".join(str(value) for value in [
            os.path.basename(os.path.normpath(run_dir)), seed_of(run_dir), success_after(250000),
            success_after(500000), last.get("rollout/success_rate", ""),
            round(float(last["rollout/ep_len_mean"]), 1),
            round(float(last["rollout/ep_rew_mean"]), 1), last["time/total_timesteps"],
            round(float(last["time/time_elapsed"]))]))


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "summary":
        summary(sys.argv[2:])
    elif len(sys.argv) >= 4 and sys.argv[1] in ("curves", "trajectories"):
        (curves if sys.argv[1] == "curves" else trajectories)(sys.argv[2], sys.argv[3:])
    else:
        raise SystemExit(__doc__)
