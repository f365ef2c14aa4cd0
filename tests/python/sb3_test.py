"""Stable-Baselines3, unchanged, on tendril through make_vec and the SB3 adapter: PPO and SAC
train on the Elastica case-1 arm; PPO learns SB3's identity task."""
import numpy as np
import pytest

from conftest import require_gymnasium, require_sb3

import tendril


@pytest.fixture(autouse=True)
def interop():
    require_gymnasium()
    require_sb3()
    import torch

    torch.set_num_threads(1)


def arm(n, **params):
    # Episodes of 64 steps so that the short runs see episode ends (terminal observations).
    return tendril.make_vec("Elastica/Tracking3D-v0", n, max_episode_steps=64, **params).to_sb3()


def test_sb3_checks_accept_the_environments():
    from stable_baselines3.common.env_checker import check_env

    check_env(tendril.make("Elastica/Tracking3D-v0"), warn=True)
    venv = arm(2)
    venv.seed(5)
    first = venv.reset()
    venv.seed(5)
    assert np.array_equal(first, venv.reset())
    direct = tendril.make("Elastica/Tracking3D-v0").reset(seed=6)[0]
    assert np.array_equal(first[1], direct)


def test_ppo_trains_on_the_arm_through_the_adapter():
    from stable_baselines3 import PPO

    venv = arm(4)
    model = PPO("MlpPolicy", venv, n_steps=64, batch_size=64, n_epochs=2, seed=0, device="cpu")
    model.learn(total_timesteps=1024)
    assert model.num_timesteps == 1024
    lengths = [e["l"] for e in model.ep_info_buffer]
    assert len(lengths) == 4 * (1024 // (4 * 64)) and set(lengths) == {64}
    assert all(np.isfinite(e["r"]) for e in model.ep_info_buffer)
    action, _ = model.predict(venv.reset(), deterministic=True)
    assert action.shape == (4, venv.action_space.shape[0])


def test_sac_trains_on_the_arm_through_the_adapter():
    from stable_baselines3 import SAC

    venv = arm(2)
    model = SAC("MlpPolicy", venv, learning_starts=64, batch_size=32, buffer_size=2000,
                policy_kwargs={"net_arch": [32, 32]}, seed=0, device="cpu")
    model.learn(total_timesteps=400)
    assert model.num_timesteps == 400
    assert model.replay_buffer.size() == 200
    # Truncations are flagged as timeouts, so SAC bootstraps through them.
    assert model.replay_buffer.timeouts[:200].sum() == 2 * 3
    assert {e["l"] for e in model.ep_info_buffer} == {64}


def test_ppo_learns_the_identity_task():
    from stable_baselines3 import PPO
    from stable_baselines3.common.evaluation import evaluate_policy

    env = tendril.make("Identity-v0")
    before = evaluate_policy_random(env)
    model = PPO("MlpPolicy", tendril.make_vec("Identity-v0", 4).to_sb3(), seed=0, device="cpu",
                n_steps=128)
    model.learn(total_timesteps=12000)
    mean, _ = evaluate_policy(model, env, n_eval_episodes=5, deterministic=True)
    # Episodes of 100 steps, reward 1 for repeating the state: random play scores ~100/n.
    assert mean >= 90, (mean, before)
    assert before < 60


def evaluate_policy_random(env):
    env.action_space.seed(0)
    obs, _ = env.reset(seed=0)
    total, done = 0.0, False
    while not done:
        obs, reward, terminated, truncated, _ = env.step(env.action_space.sample())
        total += reward
        done = terminated or truncated
    return total
