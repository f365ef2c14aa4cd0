#!/usr/bin/python3
# Writes docs/results/beam/<name>_training.csv and <name>_eval.csv from a run directory.
import csv, sys, os
run, name, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
with open(os.path.join(run, 'progress.csv')) as f, open(os.path.join(out, name + '_training.csv'), 'w', newline='') as g:
    w = csv.writer(g)
    w.writerow(['timesteps', 'episode_return_mean_last100', 'episode_length_mean', 'reward_per_step_mean', 'wall_seconds'])
    for row in csv.DictReader(f):
        ret = float(row['rollout/ep_rew_mean']); length = float(row['rollout/ep_len_mean'])
        w.writerow([row['time/total_timesteps'], '%.4f' % ret, '%.1f' % length, '%.5f' % (ret / length if length else 0.0), '%.1f' % float(row['time/time_elapsed'])])
with open(os.path.join(run, 'eval.csv')) as f, open(os.path.join(out, name + '_eval.csv'), 'w', newline='') as g:
    w = csv.writer(g)
    w.writerow(['timesteps', 'eval_return_mean', 'eval_return_std', 'eval_length_mean', 'reward_per_step_mean'])
    for row in csv.DictReader(f):
        w.writerow([row['timesteps'], '%.4f' % float(row['mean_return']), '%.4f' % float(row['std_return']), row['mean_length'], '%.5f' % (float(row['mean_return']) / float(row['mean_length']))])
