"""tendril.make_vec: N environments stepped in C++ equal N single environments with seeds
seed + i, auto-reset included; zero-copy read-only views; Gymnasium's vector interface."""
import numpy as np
import pytest

from conftest import require_gymnasium

import tendril


def run_single(env_id, seed, actions):
    """One env as the vector env runs env i: reset(seed), then auto-reset without a seed."""
    env = tendril.make(env_id)
    obs, _ = env.reset(seed=seed)
    rows = [obs]
    finals, rewards, dones = [], [], []
    for action in actions:
        obs, reward, terminated, truncated, _ = env.step(action)
        finals.append(obs)
        rewards.append(reward)
        dones.append((terminated, truncated))
        if terminated or truncated:
            obs, _ = env.reset()
        rows.append(obs)
    return np.array(rows), np.array(finals), np.array(rewards, dtype=np.float32), dones


@pytest.mark.parametrize("env_id,threads", [("Pendulum-v1", 2), ("CartPole-v1", 1),
                                            ("Elastica/Tracking3D-v0", 2)])
def test_vector_env_equals_single_envs_with_consecutive_seeds(env_id, threads):
    n, steps = 3, 230
    venv = tendril.make_vec(env_id, n, num_threads=threads, copy=True)
    rng = np.random.default_rng(0)
    space = venv.single_action_space
    if hasattr(space, "n"):
        actions = rng.integers(space.n, size=(steps, n))
    else:
        actions = rng.uniform(space.low, space.high, size=(steps, n, space.shape[0]))
        actions = actions.astype(np.float32)
    obs, _ = venv.reset(seed=40)
    rows, finals, rewards, dones = [obs], [], [], []
    for t in range(steps):
        obs, reward, terminated, truncated, info = venv.step(actions[t])
        rows.append(obs)
        rewards.append(reward)
        dones.append(np.stack([terminated, truncated], axis=1))
        final = obs.copy()
        if "final_observation" in info:
            for i in np.flatnonzero(info["_final_observation"]):
                final[i] = info["final_observation"][i]
        finals.append(final)
    rows, finals, rewards = np.array(rows), np.array(finals), np.array(rewards)
    for i in range(n):
        s_rows, s_finals, s_rewards, s_dones = run_single(env_id, 40 + i, actions[:, i])
        assert np.array_equal(rows[:, i], s_rows)
        assert np.array_equal(finals[:, i], s_finals)
        assert np.array_equal(rewards[:, i], s_rewards)
        assert [tuple(d[i]) for d in dones] == s_dones
    if env_id == "Pendulum-v1":  # 200-step episodes: the auto-reset was exercised
        assert any(d[:, 1].any() for d in dones)


def test_batches_are_read_only_views_without_copies():
    venv = tendril.make_vec("Elastica/Tracking3D-v0", 8, num_threads=2)
    obs, _ = venv.reset(seed=0)
    address = obs.__array_interface__["data"][0]
    assert obs.shape == (8, venv.single_observation_space.shape[0]) and obs.dtype == np.float32
    assert not obs.flags.writeable and obs.base is not None
    actions = np.zeros((8, venv.single_action_space.shape[0]), dtype=np.float32)
    obs2, rewards, terminated, truncated, info = venv.step(actions)
    assert obs2.__array_interface__["data"][0] == address  # the same C++ buffer, refilled
    assert not rewards.flags.writeable and rewards.dtype == np.float32
    with pytest.raises(ValueError):
        obs2[0, 0] = 1.0
    copied = tendril.make_vec("Elastica/Tracking3D-v0", 2, copy=True).reset(seed=0)[0]
    assert copied.flags.writeable and copied.flags.owndata


def test_gymnasium_vector_interface():
    gymnasium = require_gymnasium()
    venv = tendril.make_vec("Pendulum-v1", 4)
    assert isinstance(venv, gymnasium.vector.VectorEnv)
    assert venv.action_space.shape == (4, 1) and venv.observation_space.shape == (4, 3)
    venv.reset(seed=0)
    for t in range(200):
        obs, reward, terminated, truncated, info = venv.step(venv.action_space.sample())
    assert truncated.all() and not terminated.any()
    assert info["_final_observation"].all()
    assert info["final_observation"][2].shape == (3,)
    assert np.allclose(info["episode_length"], 200) and info["_episode_return"].all()


def test_vector_env_errors():
    with pytest.raises(tendril.Error, match="num_envs"):
        tendril.make_vec("Pendulum-v1", 0)
    with pytest.raises(tendril.Error, match="NoSuch"):
        tendril.make_vec("NoSuch-v0", 2)
    venv = tendril.make_vec("Pendulum-v1", 2)
    venv.reset(seed=0)
    with pytest.raises(tendril.Error, match=r"shape \(2, 1\).*got shape \(3, 1\)"):
        venv.step(np.zeros((3, 1), dtype=np.float32))
    with pytest.raises(tendril.Error, match="(?i)finite|nan"):
        venv.step(np.array([[0.0], [np.nan]], dtype=np.float32))
    with pytest.raises(tendril.Error, match="reset"):  # a failed step needs a reset
        venv.step(np.zeros((2, 1), dtype=np.float32))
    venv.reset(seed=0)
    venv.step(np.zeros((2, 1), dtype=np.float32))


def test_vector_env_seeds_and_counts_are_checked():
    venv = tendril.make_vec("Pendulum-v1", 2)
    for seed in [-1, 2**64, 2**64 - 1, 1.5]:  # 2**64 - 1 would give env 1 the seed 0
        with pytest.raises(tendril.Error, match=r"seed must be an integer in \[0, 2\*\*64 - 2\]"):
            venv.reset(seed=seed)
    venv.reset(seed=2**64 - 2)
    for count in [2**31, 0, -3, 2.5, "2"]:
        with pytest.raises(tendril.Error,
                           match=r"num_envs must be an integer in \[1, 2147483647\]"):
            tendril.make_vec("Pendulum-v1", count)
    with pytest.raises(tendril.Error, match="num_threads must be an integer"):
        tendril.make_vec("Pendulum-v1", 2, num_threads=0)
    with pytest.raises(tendril.Error, match="actions must be numbers, got None"):
        venv.step(None)
    with pytest.raises(tendril.Error, match="complex"):
        venv.step(np.zeros((2, 1), dtype=np.complex64))
