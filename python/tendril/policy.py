"""Policies trained by tendril (model.policy files, rl::Policy), acting from Python."""
import os

import numpy as np

from . import _tendril
from .spaces import from_native


class Policy:
    """A trained policy: network and the observation normalization it was trained behind, so it
    acts on the environment's raw observations. Computes in C++ what `tendril run` computes."""

    def __init__(self, path, best=False, seed=0):
        self._native = _tendril.Policy(os.fspath(path), best, int(seed))
        self.observation_space = from_native(self._native.observation_space)
        self.action_space = from_native(self._native.action_space)

    @property
    def kind(self):
        return self._native.kind

    @property
    def file(self):
        return self._native.file

    def act(self, observation, deterministic=True):
        """The action for one observation (obs size,) or a batch (B, obs size)."""
        return self._native.act(observation, bool(deterministic))

    def predict(self, observation, state=None, episode_start=None, deterministic=False):
        """Stable-Baselines3's signature: returns (actions, None); stochastic actions draw from
        the policy's own random stream (seeded at load)."""
        return self.act(np.asarray(observation, dtype=np.float32), deterministic), None

    def __repr__(self):
        return f"<tendril Policy {self.kind} {self.file}>"


def load(run_or_file, best=False, seed=0):
    """The policy of a run directory (model.policy, or best_model.policy with best=True) or of a
    policy file."""
    return Policy(run_or_file, best=best, seed=seed)
