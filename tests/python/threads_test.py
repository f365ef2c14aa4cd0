"""One Policy, VecEnv or Env used from several Python threads at once: the calls run one at a time
(each object holds a lock, taken with the GIL released), so nothing crashes or deadlocks and the
answers are those of the calls made one after the other. Each case runs in a fresh interpreter
with a time limit, so that a deadlock fails the test instead of hanging it."""
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import SOURCE_DIR

import tendril

PENDULUM = os.path.join(SOURCE_DIR, "configs", "ppo", "pendulum.yaml")


def run_python(code, *args, timeout=120):
    """Runs `code` in a new interpreter with this one's path; returns its standard output."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    try:
        done = subprocess.run([sys.executable, "-c", code, *map(str, args)], env=env,
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        pytest.fail(f"no answer after {timeout} s (a deadlock?)")
    assert done.returncode == 0, f"exit {done.returncode}: {done.stderr[-2000:]}"
    return done.stdout


@pytest.fixture(scope="module")
def policy_run(tmp_path_factory):
    run = tmp_path_factory.mktemp("runs") / "pendulum"
    tendril.train(PENDULUM, out=run, quiet=True, n_timesteps=2048, seed=1, checkpoint_freq=0)
    return run


# Batches of 20,000 and 1 observations from two threads: each call resized the buffers the other
# was computing on (SIGSEGV in 3 of 3 runs). Every answer must equal the one-thread answer.
POLICY = """
import sys, threading, numpy as np, tendril
p = tendril.load(sys.argv[1])
rng = np.random.default_rng(0)
big = rng.normal(size=(20000, 3)).astype(np.float32)
small = rng.normal(size=(1, 3)).astype(np.float32)
want_big, want_small = p.act(big), p.act(small)
bad = []
def work(x, want, n):
    for _ in range(n):
        if not np.array_equal(p.act(x), want):
            bad.append(1)
threads = [threading.Thread(target=work, args=(big, want_big, 150)),
           threading.Thread(target=work, args=(small, want_small, 6000))]
[t.start() for t in threads]; [t.join() for t in threads]
print("finished", len(bad))
"""


def test_one_policy_acts_from_two_threads(policy_run):
    assert run_python(POLICY, policy_run).split() == ["finished", "0"]


# step in one thread and reset (or step) in another, on a vector env with a thread pool of its
# own: deadlocked in ThreadPool::run, or crashed converting infos the other step rewrote.
VEC = """
import sys, threading, numpy as np, tendril
v = tendril.make_vec('Pendulum-v1', 8, num_threads=2, copy=True)
v.reset(seed=0)
a = np.zeros((8, 1), np.float32)
shapes = set()
def stepper():
    for _ in range(3000):
        obs, rewards, terminated, truncated, info = v.step(a)
        shapes.add((obs.shape, rewards.shape))
def resetter():
    for i in range(3000):
        shapes.add((v.reset(seed=i)[0].shape,))
second = stepper if sys.argv[1] == 'step' else resetter
threads = [threading.Thread(target=stepper), threading.Thread(target=second)]
[t.start() for t in threads]; [t.join() for t in threads]
print("finished", sorted(map(str, shapes)))
"""


@pytest.mark.parametrize("second", ["reset", "step"])
def test_one_vector_env_from_two_threads(second):
    out = run_python(VEC, second, timeout=60)
    assert out.startswith("finished")
    assert "((8, 3), (8,))" in out


# Two threads stepping one Pendulum each through one object, in turn: the sequence of states
# each sees is some interleaving of whole steps, so the total number of steps taken is exact.
ENV = """
import threading, numpy as np, tendril
e = tendril.make('Pendulum-v1', max_episode_steps=100000)
e.reset(seed=0)
state = e.save_state()
def work():
    for _ in range(2000):
        e.step(np.array([0.5], np.float32))
        e.scene()
threads = [threading.Thread(target=work) for _ in range(3)]
[t.start() for t in threads]; [t.join() for t in threads]
after = e.step(np.array([0.5], np.float32))[0]
e.load_state(state)
for _ in range(6000):
    e.step(np.array([0.5], np.float32))
print("finished", bool(np.array_equal(e.step(np.array([0.5], np.float32))[0], after)))
"""


def test_one_env_from_three_threads():
    assert run_python(ENV).split() == ["finished", "True"]
