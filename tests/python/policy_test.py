"""tendril.load and tendril.train: a policy trained by tendril acts from Python exactly as the C++
rl::Policy acts (deterministic and seeded stochastic actions, observation normalization
included); errors name the file."""
import os

import numpy as np
import pytest

from conftest import SOURCE_DIR, reference, require_gymnasium, require_sb3

import tendril

PENDULUM = os.path.join(SOURCE_DIR, "configs", "ppo", "pendulum.yaml")
CARTPOLE = os.path.join(SOURCE_DIR, "configs", "ppo", "cartpole.yaml")


@pytest.fixture(scope="module")
def pendulum_run(tmp_path_factory):
    # A short run with observation normalization, so the policy file carries statistics.
    run = tmp_path_factory.mktemp("runs") / "pendulum"
    returned = tendril.train(PENDULUM, out=run, quiet=True, n_timesteps=8192, seed=3,
                             env__normalize_observation=True, eval__freq=4096,
                             eval__episodes=1, checkpoint_freq=0)
    assert os.path.samefile(returned, run)
    return run


def recorded_observations(env_id, count, seed):
    env = tendril.make(env_id)
    obs, _ = env.reset(seed=seed)
    rows = [obs]
    env.action_space.seed(seed)
    for _ in range(count - 1):
        obs, _, terminated, truncated, _ = env.step(env.action_space.sample())
        rows.append(obs)
        if terminated or truncated:
            obs, _ = env.reset()
    return np.array(rows, dtype=np.float32)


def cpp_actions(policy_file, observations, deterministic, seed, scratch):
    obs_file, out_file = scratch / "obs.f32", scratch / "actions.f32"
    observations.tofile(obs_file)
    reference("act", policy_file, obs_file, int(deterministic), seed, out_file)
    return np.fromfile(out_file, dtype="<f4")


def test_run_files_and_policy_metadata(pendulum_run):
    assert (pendulum_run / "model.policy").exists()
    assert (pendulum_run / "config.yaml").read_text().count("normalize_observation: true") == 1
    policy = tendril.load(pendulum_run)
    assert policy.kind == "actor_critic"
    assert policy.observation_space.shape == (3,) and policy.action_space.shape == (1,)


@pytest.mark.parametrize("deterministic", [True, False])
def test_actions_equal_the_cpp_policy(pendulum_run, deterministic, scratch):
    observations = recorded_observations("Pendulum-v1", 300, seed=4)
    policy = tendril.load(pendulum_run, seed=17)
    rows = np.array([policy.act(o, deterministic) for o in observations])
    expected = cpp_actions(pendulum_run / "model.policy", observations, deterministic, 17, scratch)
    assert np.array_equal(rows.ravel().view(np.uint32), expected.view(np.uint32))
    if deterministic:
        # A batch goes through a matrix-matrix product (BLAS), whose sums round differently
        # from one observation's matrix-vector product, in C++ as here: equal to float
        # precision, not bit for bit.
        batch = tendril.load(pendulum_run).act(observations, True)
        assert batch.shape == (300, 1)
        assert np.allclose(batch.ravel(), expected, rtol=1e-5, atol=1e-6)
        # The statistics matter: without them the network's outputs would differ.
        assert np.abs(expected).max() > 0


def test_discrete_policy_actions_equal_the_cpp_policy(tmp_path):
    run = tendril.train(CARTPOLE, out=tmp_path / "cartpole", quiet=True, n_timesteps=2048,
                        eval__freq=2048, eval__episodes=1, checkpoint_freq=0)
    policy = tendril.load(run)
    observations = recorded_observations("CartPole-v1", 200, seed=1)
    actions = policy.act(observations, True)
    assert actions.dtype == np.int64 and actions.shape == (200,)
    expected = cpp_actions(os.path.join(run, "model.policy"), observations, True, 0, tmp_path)
    assert np.array_equal(actions, expected.astype(np.int64))
    single = policy.act(observations[0], True)
    assert single.shape == () and single == actions[0]


def test_sb3_evaluate_policy_runs_a_tendril_policy(pendulum_run):
    require_gymnasium()
    require_sb3()
    from stable_baselines3.common.evaluation import evaluate_policy

    policy = tendril.load(pendulum_run)
    env = tendril.make("Pendulum-v1")
    mean, std = evaluate_policy(policy, env, n_eval_episodes=2, deterministic=True)
    assert -2000 < mean < 0 and np.isfinite(std)


def test_policy_errors_name_the_file(pendulum_run, tmp_path):
    with pytest.raises(tendril.Error, match="best_model.policy"):
        tendril.load(pendulum_run, best=True)
    damaged = tmp_path / "damaged.policy"
    data = bytearray((pendulum_run / "model.policy").read_bytes())
    data[len(data) // 2] ^= 0xFF
    damaged.write_bytes(bytes(data))
    with pytest.raises(tendril.Error, match="damaged.policy"):
        tendril.load(damaged)
    policy = tendril.load(pendulum_run)
    with pytest.raises(tendril.Error, match=r"\(3,\)"):
        policy.act(np.zeros(4, dtype=np.float32))
    with pytest.raises(tendril.Error, match="(?i)finite|nan"):
        policy.act(np.array([0.0, np.nan, 0.0], dtype=np.float32))
    with pytest.raises(tendril.Error, match="algo.no_such_key"):
        tendril.train(PENDULUM, out=tmp_path / "never", overrides={"algo.no_such_key": 1})
    assert not (tmp_path / "never").exists()


def test_every_damaged_copy_of_a_policy_file_is_refused(pendulum_run, tmp_path):
    # A bit flipped in each of 200 places spread over the file (header, weights, statistics,
    # checksum line): never loaded as a policy.
    data = (pendulum_run / "model.policy").read_bytes()
    damaged = tmp_path / "flipped.policy"
    rng = np.random.default_rng(4)
    for position in sorted(rng.choice(len(data), size=200, replace=False)):
        flipped = bytearray(data)
        flipped[position] ^= 1 << int(rng.integers(8))
        damaged.write_bytes(bytes(flipped))
        with pytest.raises(tendril.Error, match="flipped.policy"):
            tendril.load(damaged)
    for size in [0, 7, len(data) // 3, len(data) - 1]:
        damaged.write_bytes(data[:size])
        with pytest.raises(tendril.Error, match="flipped.policy"):
            tendril.load(damaged)


# Ctrl-C during tendril.train: the training ends its iteration, writes a checkpoint and the call
# raises KeyboardInterrupt saying how to continue; tendril.resume continues it.
INTERRUPTED = """
import signal, sys, tendril
signal.signal(signal.SIGINT, signal.default_int_handler)
try:
    tendril.train(sys.argv[1], out=sys.argv[2], quiet=True, n_timesteps=3000000,
                  checkpoint_freq=2048, eval__freq=0)
except KeyboardInterrupt as stop:
    print("KeyboardInterrupt:", stop)
    sys.exit(3)
print("finished without an interrupt")
"""


def test_ctrl_c_stops_training_at_a_checkpoint(tmp_path):
    import signal
    import subprocess
    import sys
    import time

    run = tmp_path / "interrupted"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    child = subprocess.Popen([sys.executable, "-c", INTERRUPTED, PENDULUM, str(run)], env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 60
    while not (run / "progress.csv").exists() and time.time() < deadline:
        time.sleep(0.1)
    time.sleep(1.0)  # into training
    sent = time.time()
    child.send_signal(signal.SIGINT)
    try:
        out, err = child.communicate(timeout=20)
    except subprocess.TimeoutExpired:
        child.kill()
        child.communicate()
        pytest.fail("tendril.train went on for 20 s after Ctrl-C")
    assert child.returncode == 3, out + err
    assert time.time() - sent < 20
    assert "tendril.resume(" in out and str(run) in out, out
    assert list((run / "checkpoints").glob("*.ckpt")), "no checkpoint written"
    # The run continues from there.
    steps = int(out.split("training stopped at ")[1].split()[0])
    resumed = tendril.resume(run, stop_at=steps + 2048, quiet=True)
    assert os.path.samefile(resumed, run)


def test_progress_goes_to_sys_stderr_and_the_callback_sees_every_iteration(tmp_path, capsys):
    reports = []
    tendril.train(PENDULUM, out=tmp_path / "watched", n_timesteps=4096, seed=2,
                  algo__n_steps=256, checkpoint_freq=0, callback=reports.append)
    err = capsys.readouterr().err  # Python's sys.stderr, which a notebook shows
    assert "steps 4096/4096 (100.0%)" in err and "ETA" in err, err
    # Four envs of 256 steps: 1024 steps per iteration, four reports, in order.
    assert [r["timesteps"] for r in reports] == [1024, 2048, 3072, 4096]
    assert reports[-1]["episodes"] > 0 and np.isfinite(reports[-1]["ep_rew_mean"])
    assert "train/approx_kl" in reports[-1]["train"]


def test_a_raising_callback_stops_the_run_at_a_checkpoint_and_propagates(tmp_path):
    run = tmp_path / "stopped"

    def stop_after_first(report):
        raise RuntimeError(f"enough at {report['timesteps']}")

    # Long enough (about 2 s) that the stop lands before the end.
    with pytest.raises(RuntimeError, match="enough at 1024"):
        tendril.train(PENDULUM, out=run, quiet=True, n_timesteps=200_000, seed=2,
                      algo__n_steps=256, checkpoint_freq=0, callback=stop_after_first)
    assert not (run / "model.policy").exists()
    assert list((run / "checkpoints").glob("*.ckpt")), "no checkpoint written"
    tendril.resume(run, quiet=True)
    assert (run / "model.policy").exists()
