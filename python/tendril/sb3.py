"""A tendril vector env as a Stable-Baselines3 VecEnv: auto-reset, infos with
"terminal_observation", "TimeLimit.truncated" and Monitor's "episode" statistics, seeds from
VecEnv.seed (env i gets seed + i, as SB3's DummyVecEnv)."""
import time

import numpy as np
from stable_baselines3.common.vec_env.base_vec_env import VecEnv as _SB3VecEnv

from . import _tendril
from .vector import VecEnv


class SB3VecEnv(_SB3VecEnv):
    def __init__(self, venv_or_id, num_envs=None, **kwargs):
        if isinstance(venv_or_id, VecEnv):
            if num_envs is not None or kwargs:
                raise _tendril.Error("SB3VecEnv(venv) takes no further arguments")
            self.venv = venv_or_id
        else:
            if num_envs is None:
                raise _tendril.Error("SB3VecEnv(id, num_envs, ...) needs num_envs")
            self.venv = VecEnv(venv_or_id, num_envs, **kwargs)
        super().__init__(self.venv.num_envs, self.venv.single_observation_space,
                         self.venv.single_action_space)
        self._actions = None
        self._episode_start = time.time()

    def reset(self):
        seeds = [s for s in self._seeds if s is not None]
        seed = None
        if seeds:
            seed = self._seeds[0]
            if seed is None or list(self._seeds) != [seed + i for i in range(self.num_envs)]:
                raise _tendril.Error("per-env seeds must be consecutive (env i gets seed + i)")
        observations = self.venv.native.reset(seed, True)
        self._reset_seeds()
        self._reset_options()
        return observations

    def step_async(self, actions):
        self._actions = actions

    def step_wait(self):
        # Copies, made before another thread's call could refill the buffers (SB3 keeps them).
        observations, rewards, terminated, truncated, final, infos = self.venv.native.step(
            self._actions, True)
        dones = terminated | truncated
        for i in np.flatnonzero(dones):
            info = infos[i]
            info["terminal_observation"] = final[i]
            info["TimeLimit.truncated"] = bool(truncated[i] and not terminated[i])
            if "episode_return" in info:
                info["episode"] = {"r": info["episode_return"], "l": int(info["episode_length"]),
                                   "t": round(time.time() - self._episode_start, 6)}
        return observations, rewards, dones, infos

    def close(self):
        self.venv.close()

    def get_attr(self, attr_name, indices=None):
        return [getattr(self.venv, attr_name) for _ in self._get_indices(indices)]

    def set_attr(self, attr_name, value, indices=None):
        raise _tendril.Error(f"tendril's vector env has no per-env attribute {attr_name!r} to set")

    def env_method(self, method_name, *method_args, indices=None, **method_kwargs):
        if method_name == "scene":
            return [self.venv.scene(i) for i in self._get_indices(indices)]
        raise _tendril.Error(f"tendril's vector env has no per-env method {method_name!r}")

    def env_is_wrapped(self, wrapper_class, indices=None):
        return [False for _ in self._get_indices(indices)]
