"""tendril.make: Gymnasium's env checker on every registered environment, seeded episodes equal
to the C++ environment's bit for bit, scene arrays, snapshots, and errors as tendril.Error."""
import math
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

from conftest import APP, SOURCE_DIR, make_by_id, reference_episode, require_gymnasium

import tendril

IDS = tendril.registry()
# Gymnasium's advice, not faults: Box action spaces other than [-1, 1] (its own Pendulum-v1
# gets it) and unbounded observation components (PyElastica's arm environments have them too).
ADVICE = ("We recommend you to use a symmetric and normalized Box action space",
          "For Box action spaces, we recommend using a symmetric and normalized space",
          "A Box observation space minimum value is -infinity",
          "A Box observation space maximum value is -infinity")


def test_registry_lists_the_builtin_environments():
    assert IDS == sorted(IDS)
    for env_id in ("Pendulum-v1", "CartPole-v1", "Elastica/Tracking3D-v0",
                   "Elastica/StructuredObstacles-v0"):
        assert env_id in IDS


@pytest.mark.parametrize("env_id", IDS)
def test_gymnasium_env_checker_passes(env_id):
    gymnasium = require_gymnasium()
    from gymnasium.utils.env_checker import check_env

    env = make_by_id(env_id)
    assert isinstance(env, gymnasium.Env)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env, skip_render_check=True)
    unexpected = [str(w.message) for w in caught
                  if not any(a in str(w.message) for a in ADVICE)]
    assert not unexpected, unexpected


def test_gymnasium_make_finds_tendril_ids():
    gymnasium = require_gymnasium()
    env = gymnasium.make("tendril/Elastica-Tracking3D-v0")
    obs, info = env.reset(seed=3)
    assert obs.shape == env.observation_space.shape and obs.dtype == np.float32
    direct, _ = tendril.make("Elastica/Tracking3D-v0").reset(seed=3)
    assert np.array_equal(obs, direct)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
    assert isinstance(info, dict) and "distance" in info


def seeded_actions(env, count, seed):
    env.action_space.seed(seed)
    return [env.action_space.sample() for _ in range(count)]


@pytest.mark.parametrize("env_id", IDS)
def test_seeded_episode_equals_the_cpp_environment_bit_for_bit(env_id, scratch):
    env = make_by_id(env_id)
    limit = min(env.max_episode_steps or 1000, 2000)
    obs, _ = env.reset(seed=11)
    observations, rewards, flags, used = [obs], [], [], []
    for action in seeded_actions(env, limit, seed=5):
        obs, reward, terminated, truncated, info = env.step(action)
        observations.append(obs)
        rewards.append(reward)
        flags.append((terminated, truncated))
        used.append(np.atleast_1d(np.asarray(action, dtype=np.float32)))
        if terminated or truncated:
            break
    first, steps = reference_episode(env_id, 11, np.stack(used), obs.size, scratch)
    assert len(steps) == len(used)
    assert np.array_equal(observations[0].view(np.uint32), first.view(np.uint32))
    assert np.array_equal(np.stack(observations[1:]).view(np.uint32),
                          steps["obs"].view(np.uint32))
    assert np.array_equal(np.array(rewards).view(np.uint64), steps["reward"].view(np.uint64))
    assert [(bool(a), bool(b)) for a, b in zip(steps["terminated"], steps["truncated"])] == flags


def test_the_arm_scene_comes_as_numpy_arrays():
    env = tendril.make("Elastica/Tracking3D-v0")
    env.reset(seed=0)
    before = env.scene()
    arm = [rod for rod in before["rods"] if rod["role"] == "arm"][0]
    assert arm["centreline"].ndim == 2 and arm["centreline"].shape[1] == 3
    assert arm["centreline"].shape[0] >= 2
    # The base is fixed at the origin and the rod starts straight up along z (1 m long).
    assert np.allclose(arm["centreline"][0], 0.0)
    assert math.isclose(np.linalg.norm(arm["centreline"][-1] - arm["centreline"][0]), 1.0,
                        rel_tol=1e-6)
    assert any(s["role"] == "target" for s in before["spheres"])
    for _ in range(50):
        env.step(np.ones(env.action_space.shape, dtype=np.float32))
    after = [rod for rod in env.scene()["rods"] if rod["role"] == "arm"][0]
    assert not np.array_equal(after["centreline"], arm["centreline"])
    assert env.scene()["time"] > before["time"]


def test_snapshots_repeat_the_following_steps_exactly():
    env = tendril.make("Elastica/Tracking3D-v0")
    env.reset(seed=2)
    for action in seeded_actions(env, 20, seed=1):
        env.step(action)
    assert env.supports_snapshots
    state = env.save_state()
    actions = seeded_actions(env, 30, seed=9)
    first = [env.step(a)[:2] for a in actions]
    env.load_state(state)
    again = [env.step(a)[:2] for a in actions]
    for (o1, r1), (o2, r2) in zip(first, again):
        assert np.array_equal(o1, o2) and r1 == r2
    with pytest.raises(tendril.Error):
        env.load_state(state[:-8])


def test_errors_are_tendril_errors_that_name_the_problem():
    with pytest.raises(tendril.Error, match="Elastica/NoSuchArm-v0"):
        tendril.make("Elastica/NoSuchArm-v0")
    with pytest.raises(tendril.Error, match="n_elementz"):
        tendril.make("Elastica/Tracking3D-v0", n_elementz=20)
    env = tendril.make("Elastica/Tracking3D-v0")
    size = env.action_space.shape[0]
    with pytest.raises(tendril.Error, match="reset"):
        env.step(np.zeros(size, dtype=np.float32))
    env.reset(seed=0)
    with pytest.raises(tendril.Error, match=rf"shape \({size},\).*got shape \(3,\)"):
        env.step(np.zeros(3, dtype=np.float32))
    with pytest.raises(tendril.Error, match=r"got shape \(1, %d\)" % size):
        env.step(np.zeros((1, size), dtype=np.float32))
    bad = np.zeros(size, dtype=np.float32)
    bad[4] = np.nan
    with pytest.raises(tendril.Error, match="(?i)finite|nan"):
        env.step(bad)
    cartpole = tendril.make("CartPole-v1")
    cartpole.reset(seed=0)
    with pytest.raises(tendril.Error, match="Discrete"):
        cartpole.step(np.array([0.5]))
    with pytest.raises(tendril.Error, match="outside"):
        cartpole.step(2)
    assert issubclass(tendril.Error, ValueError)


def test_the_package_works_without_gymnasium():
    code = (
        "import sys; sys.modules['gymnasium'] = None\n"
        "import numpy as np, tendril\n"
        "env = tendril.make('Pendulum-v1')\n"
        "assert not tendril.spaces.HAVE_GYMNASIUM\n"
        "obs, info = env.reset(seed=0)\n"
        "a = env.action_space.sample()\n"
        "assert env.action_space.contains(a) and obs in env.observation_space\n"
        "o, r, te, tr, i = env.step(a)\n"
        "v = tendril.make_vec('CartPole-v1', 3)\n"
        "o = v.reset(seed=1)[0]; assert o.shape == (3, 4)\n"
        "print('ok', type(env).__mro__[1].__name__)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": os.environ.get("PYTHONPATH", "")})
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["ok", "object"]


def test_conversion_errors_say_what_is_wrong():
    env = tendril.make("Pendulum-v1")
    for seed in [-1, 2**64, 1.5, "7", True]:
        with pytest.raises(tendril.Error, match=r"seed must be an integer in \[0, 2\*\*64 - 1\]"):
            env.reset(seed=seed)
    with pytest.raises(tendril.Error, match=r"seed must be an integer"):
        env._native.reset(-1)  # the extension itself, below the Python checks
    env.reset(seed=2**64 - 1)
    env.reset(seed=np.uint64(2**64 - 1))
    with pytest.raises(tendril.Error, match="an action must be numbers, got None"):
        env.step(None)
    with pytest.raises(tendril.Error, match="real numbers, got complex"):
        env.step(np.array([1 + 2j]))
    with pytest.raises(tendril.Error, match="must be numbers"):
        env.step(np.array([object()]))
    with pytest.raises(tendril.Error, match="must be numbers"):
        env.step(["a"])
    cartpole = tendril.make("CartPole-v1")
    cartpole.reset(seed=0)
    with pytest.raises(tendril.Error,
                       match=r"Discrete\(2\) action 9223372036854775808 lies outside"):
        cartpole.step(np.uint64(2**63))
    with pytest.raises(tendril.Error, match="outside"):
        cartpole.step(np.uint64(7))
    assert cartpole.step(np.uint64(1))[0].shape == (4,)


def test_saved_states_carry_a_checksum():
    env = tendril.make("Elastica/Tracking3D-v0")
    env.reset(seed=0)
    state = env.save_state()
    env.load_state(state)
    rng = np.random.default_rng(2)
    for position in rng.choice(len(state), size=40, replace=False):
        damaged = bytearray(state)
        damaged[position] ^= 1 << int(rng.integers(8))
        with pytest.raises(tendril.Error, match="checksum|not a state"):
            env.load_state(bytes(damaged))
    with pytest.raises(tendril.Error, match="not a state"):
        env.load_state(b"")


def test_an_error_quoting_bytes_that_are_not_utf8_keeps_its_message():
    # A snapshot whose first section name is invalid UTF-8, with a valid checksum: the message
    # names the section with the bytes escaped instead of arriving empty.
    import struct

    def crc32c(data):
        crc = 0xFFFFFFFF
        for byte in data:
            crc ^= byte
            for _ in range(8):
                crc = (crc >> 1) ^ (0x82F63B78 if crc & 1 else 0)
        return crc ^ 0xFFFFFFFF

    env = tendril.make("Pendulum-v1")
    env.reset(seed=0)
    state = env.save_state()
    payload = bytearray(state[12:])
    length = struct.unpack("<Q", payload[:8])[0]
    payload[8:8 + length] = b"\xff\xfe" + bytes(payload[10:8 + length])
    forged = state[:8] + struct.pack("<I", crc32c(bytes(payload))) + bytes(payload)
    with pytest.raises(tendril.Error) as raised:
        env.load_state(forged)
    assert "\\xff\\xfe" in str(raised.value), str(raised.value)


def test_describe_gives_each_environment_in_words():
    described = tendril.describe("Pendulum-v1")
    assert described["max_episode_steps"] == 200
    assert [(e["name"], e["unit"], e["count"]) for e in described["observation"]] == [
        ("cos θ (θ = 0 upright)", "1", 1), ("sin θ", "1", 1), ("angular velocity θ̇", "rad/s", 1)]
    assert [(e["unit"], e["count"]) for e in described["action"]] == [("N·m", 1)]
    assert described["reward"] and described["episode_end"]
    assert [(p["key"], p["default"], p["unit"]) for p in described["parameters"]] == [
        ("g", "10", "m/s²")]
    for env_id in IDS:
        described = tendril.describe(env_id)
        env = make_by_id(env_id)
        size = int(np.prod(env.observation_space.shape))
        assert sum(e["count"] for e in described["observation"]) == size, env_id
    with pytest.raises(tendril.Error, match="unknown environment id 'Nope-v0'"):
        tendril.describe("Nope-v0")


def test_learned_model_environments_work_from_python(scratch):
    """The dynamics layer comes with the module: a model fitted by the command line drives
    SmaLimb/LearnedReach-v0 from Python, seeded episodes repeat exactly, and a missing model is
    an error that names it."""
    if not APP:
        pytest.skip("TENDRIL_APP is not set: run these tests through ctest")
    run = scratch / "fit"
    done = subprocess.run(
        [APP, "model", "fit", os.path.join(SOURCE_DIR, "configs/dynamics/sma_stiff_rnn.yaml"),
         "--set", "training.epochs=1", "--set", "training.windows_per_epoch=256",
         "--set", "evaluation.horizons_s=[]", "--set", "model.hidden_size=8",
         "--set", "model.layers=1", "--set",
         "data.file=" + os.path.join(SOURCE_DIR, "data/sma_limb/stiff_exploration_prepared.csv"),
         "-o", str(run), "--quiet"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr

    def episode():
        env = tendril.make("SmaLimb/LearnedReach-v0", model=str(run))
        obs, _ = env.reset(seed=4)
        observations = [obs]
        for action in seeded_actions(env, 20, seed=2):
            obs, reward, terminated, truncated, _ = env.step(action)
            observations.append(obs)
            assert np.isfinite(reward)
            if terminated or truncated:
                break
        return np.stack(observations)

    first = episode()
    assert np.all(np.isfinite(first))
    assert not np.array_equal(first[0], first[-1])  # the model moved the limb
    assert np.array_equal(first.view(np.uint32), episode().view(np.uint32))
    with pytest.raises(tendril.Error, match="no-such-model"):
        tendril.make("SmaLimb/LearnedReach-v0", model=str(scratch / "no-such-model"))
