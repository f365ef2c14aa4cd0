"""Stable-Baselines3 PPO (the RL Baselines3 Zoo's Pendulum-v1 hyper-parameters) reaches the same
return band on tendril's Pendulum-v1 as on Gymnasium's own, with the same seed and budget
(a learning check: several minutes, label `long`)."""
import numpy as np

from conftest import require_gymnasium, require_sb3

import tendril

BUDGET = 100_000
# rl-baselines3-zoo hyperparams/ppo.yml, Pendulum-v1 (reference return −172 at 100k steps).
ZOO = dict(n_steps=1024, gae_lambda=0.95, gamma=0.9, n_epochs=10, ent_coef=0.0,
           learning_rate=1e-3, clip_range=0.2, use_sde=True, sde_sample_freq=4)


def train_and_evaluate(venv, eval_env):
    from stable_baselines3 import PPO
    from stable_baselines3.common.evaluation import evaluate_policy

    model = PPO("MlpPolicy", venv, seed=0, device="cpu", **ZOO)
    model.learn(total_timesteps=BUDGET)
    mean, _ = evaluate_policy(model, eval_env, n_eval_episodes=20, deterministic=True)
    return mean


def test_ppo_return_band_matches_gymnasium_pendulum():
    gymnasium = require_gymnasium()
    require_sb3()
    import torch
    from stable_baselines3.common.env_util import make_vec_env

    torch.set_num_threads(1)
    theirs = train_and_evaluate(make_vec_env("Pendulum-v1", n_envs=4, seed=0),
                                gymnasium.make("Pendulum-v1"))
    ours = train_and_evaluate(tendril.make_vec("Pendulum-v1", 4).to_sb3(),
                              tendril.make("Pendulum-v1"))
    print(f"SB3 PPO, {BUDGET} steps: Gymnasium Pendulum-v1 {theirs:.1f}, tendril {ours:.1f}")
    # A swing-up policy holds the pendulum up (returns above −400; random play is about −1200).
    assert theirs > -400 and ours > -400, (theirs, ours)
    assert abs(ours - theirs) < 150, (theirs, ours)
