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
