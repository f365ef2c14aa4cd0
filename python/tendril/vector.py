"""N tendril environments stepped together in C++ (threads, GIL released), with Gymnasium's
vector-env interface (gymnasium.vector.VectorEnv when Gymnasium is installed)."""
import numpy as np

from . import _tendril
from .env import params_json
from .spaces import HAVE_GYMNASIUM, from_native

if HAVE_GYMNASIUM:
    import gymnasium.vector

    _Base = gymnasium.vector.VectorEnv
else:
    _Base = object


class VecEnv(_Base):
    """`num_envs` copies of a registered environment; finished episodes reset automatically
    (the observation returned for such an env is its next episode's first; the final one is in
    info["final_observation"], Gymnasium 0.29's convention).

    With copy=False (the default) observations and rewards are read-only NumPy views of the C++
    buffers, valid until the next reset or step: copy them to keep them. copy=True returns
    copies, as Gymnasium's SyncVectorEnv does.

    Calls from several threads into one VecEnv run one at a time; a view is refilled by the next
    call from any thread, so threads sharing one VecEnv want copy=True (the copies are made before
    another call can start)."""

    def __init__(self, env_id, num_envs, *, num_threads=1, copy=False, **params):
        self._native = _tendril.VecEnv(env_id, num_envs, params_json(env_id, params), num_threads)
        num_envs = self._native.num_envs
        self.env_id = env_id
        self.copy = copy
        single_observation = from_native(self._native.observation_space)
        single_action = from_native(self._native.action_space)
        if HAVE_GYMNASIUM:
            super().__init__(int(num_envs), single_observation, single_action)
        else:
            self.num_envs = int(num_envs)
            self.single_observation_space = single_observation
            self.single_action_space = single_action
            self.observation_space = None
            self.action_space = None
            self.closed = False

    @property
    def native(self):
        """The extension's VecEnv: reset(seed) → observations; step(actions) → (observations,
        rewards, terminated, truncated, final_observations, infos as a list of dicts)."""
        return self._native

    def reset(self, *, seed=None, options=None):
        """Resets env i with seed + i (each continues its own stream when seed is None)."""
        if options:
            raise _tendril.Error(f"tendril vector env {self.env_id}: reset takes no options")
        if isinstance(seed, (list, tuple)):
            if list(seed) != [seed[0] + i for i in range(self.num_envs)]:
                raise _tendril.Error("per-env seeds must be consecutive (env i gets seed + i)")
            seed = seed[0]
        return self._native.reset(seed, self.copy), {}

    def step(self, actions):
        observations, rewards, terminated, truncated, final, infos = self._native.step(
            actions, self.copy)
        return observations, rewards, terminated, truncated, self._gymnasium_info(
            infos, terminated | truncated, final)

    def _gymnasium_info(self, infos, done, final):
        # Gymnasium's vector info: each key an array over envs with a boolean mask "_key".
        out = {}
        for i, info in enumerate(infos):
            for key, value in info.items():
                if key not in out:
                    out[key] = np.zeros(self.num_envs)
                    out["_" + key] = np.zeros(self.num_envs, dtype=bool)
                out[key][i] = value
                out["_" + key][i] = True
        if done.any():
            final_observation = np.full(self.num_envs, None, dtype=object)
            final_info = np.full(self.num_envs, None, dtype=object)
            for i in np.flatnonzero(done):
                final_observation[i] = final[i].copy()
                final_info[i] = infos[i]
            out["final_observation"] = final_observation
            out["_final_observation"] = done.copy()
            out["final_info"] = final_info
            out["_final_info"] = done.copy()
        return out

    def scene(self, index=0):
        """Env `index`'s scene as NumPy arrays (TendrilEnv.scene)."""
        return self._native.scene(index)

    def to_sb3(self):
        """This vector env as a Stable-Baselines3 VecEnv (tendril.sb3.SB3VecEnv)."""
        from .sb3 import SB3VecEnv

        return SB3VecEnv(self)

    def close(self, **kwargs):
        self.closed = True

    def __repr__(self):
        return f"<tendril VecEnv {self.env_id} x{self.num_envs}>"


def make_vec(env_id, num_envs, *, num_threads=1, copy=False, **params):
    """`num_envs` copies of a registered environment stepped in C++ on `num_threads` threads."""
    return VecEnv(env_id, num_envs, num_threads=num_threads, copy=copy, **params)
