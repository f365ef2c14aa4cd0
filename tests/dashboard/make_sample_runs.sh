#!/usr/bin/env bash
# Trains three short PPO runs of the Elastica case-1 arm side by side (a sweep over seeds),
# records an episode of the first, and adds an episode with every kind of Scene primitive:
# the runs the browser and plotting tests open.
#   make_sample_runs.sh <tendril> <sample_episodes> <source dir> <output dir>
set -euo pipefail
tendril=$1 sample_episodes=$2 source=$3 out=$4
rm -rf "$out"
mkdir -p "$out/sweep"
for seed in 0 1 2; do
  "$tendril" train "$source/configs/elastica/tracking3d_ppo_quick.yaml" --quiet \
    --set seed=$seed --set n_timesteps=24576 --set eval.freq=8192 --set eval.episodes=2 \
    --set checkpoint_freq=0 --set env.params.max_episode_steps=200 \
    -o "$out/sweep/ppo_seed$seed"
done
"$tendril" run "$out/sweep/ppo_seed0" --episodes 1 --record "$out/sweep/ppo_seed0/episodes"
"$sample_episodes" "$out/sweep/ppo_seed0/episodes"

# Logs written elsewhere (Stable-Baselines3's own progress.csv) whose returns span a narrow range
# of large values: the y-axis labels must still differ (−1.12k, −1.13k, …).
mkdir -p "$out/external/sb3_pendulum"
awk 'BEGIN {
  print "time/total_timesteps,rollout/ep_rew_mean,rollout/ep_len_mean,train/loss,time/fps";
  for (i = 1; i <= 60; i++) {
    printf "%d,%.3f,200,%.5f,%d\n", 2048 * i, -1190 + 70 * (1 - exp(-i / 15)) + 4 * sin(i),
           0.8 * exp(-i / 20) + 0.01 * cos(i), 1500 + (i % 7)
  }
}' > "$out/external/sb3_pendulum/progress.csv"

# A finished model fit (tendril model fit's files: progress.csv by epoch, evaluation.csv).
fit="$out/fits/sma_stiff_lstm"
mkdir -p "$fit"
cp "$source/configs/dynamics/sma_stiff_lstm.yaml" "$fit/config.yaml"
epochs=$(awk '/^ *epochs:/ {print $2; exit}' "$fit/config.yaml")
awk -v epochs="$epochs" 'BEGIN {
  print "train/loss,train/val_loss,train/learning_rate,time/epochs,time/windows,time/fps,time/time_elapsed";
  for (e = 1; e <= epochs; e++) {
    printf "%.6f,%.6f,0.001,%d,%d,%.1f,%.2f\n", 0.02 + 0.5 * exp(-e / 3), 0.03 + 0.45 * exp(-e / 3.5),
           e, 16384 * e, 2100 + e, 7.8 * e
  }
}' > "$fit/progress.csv"
cat > "$fit/evaluation.csv" <<'CSV'
metric,horizon_s,group,unit,rmse,points,rollouts
one_step,0,angle,deg,0.412,2761,0
one_step,0,angular velocity,deg/s,3.05,2761,0
rollout,60,angle,deg,4.87,2761,12
rollout,60,angular velocity,deg/s,9.6,2761,12
CSV

# A sweep summary beside the seeds (what `tendril sweep` writes into <output>/summary/): the
# runs' table from `tendril report` and their curves from `tendril plot`.
mkdir -p "$out/sweep/summary"
"$tendril" plot curves "$out/sweep" --out "$out/sweep/summary/training.png" --size 6.4,3.6 --dpi 80
{
  "$tendril" report "$out/sweep"
  echo
  echo "![Mean training return of the three seeds ± std](training.png)"
} > "$out/sweep/summary/summary.md"
