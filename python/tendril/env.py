"""One tendril environment as a gymnasium.Env (a plain object with the same methods when
Gymnasium is not installed)."""
import json
import operator

from . import _tendril
from .spaces import HAVE_GYMNASIUM, from_native

if HAVE_GYMNASIUM:
    import gymnasium

    _Base = gymnasium.Env
else:
    _Base = object


def params_json(env_id, params):
    """The environment's parameters as JSON text, which tendril's YAML reader takes as is."""
    try:
        return json.dumps(params, allow_nan=False)
    except (TypeError, ValueError) as error:
        raise _tendril.Error(f"tendril env {env_id}: parameters must be numbers, strings, lists "
                             f"and dicts of them ({error})") from None


def _is_integer(value):
    try:
        operator.index(value)
        return True
    except TypeError:
        return False


class TendrilEnv(_Base):
    """A registered tendril environment, stepped in C++.

    Observations are float32 arrays; actions are float32 arrays of the Box's shape or integer
    indices for Discrete spaces. `info` holds the environment's named scalars (distance,
    is_success, ...). The registered time limit is part of the environment (`truncated`).

    render_mode (Gymnasium's): "rgb_array" — render() returns the scene drawn by tendril's
    software rasterizer as a height x width x 3 uint8 array (render_size, default 640 x 480; no
    GPU or display needed); "human" — every reset and step shows that picture in a matplotlib
    window. Environments that describe no scene (the classic-control tasks) refuse both."""

    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 30}

    def __init__(self, env_id, render_mode=None, render_size=(640, 480), **params):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise _tendril.Error(f"tendril env {env_id}: render_mode must be one of "
                                 f"{self.metadata['render_modes']} or None, not {render_mode!r}")
        width, height = (int(v) for v in render_size)
        self._native = _tendril.Env(env_id, params_json(env_id, params))
        self.env_id = env_id
        self.params = dict(params)
        self.render_mode = render_mode
        self.render_size = (width, height)
        self.metadata = dict(TendrilEnv.metadata)
        self.observation_space = from_native(self._native.observation_space)
        self.action_space = from_native(self._native.action_space)
        self.max_episode_steps = _tendril.max_episode_steps(env_id)
        self._viewer = None

    def reset(self, *, seed=None, options=None):
        """Starts an episode, seeded when `seed` is given; returns (observation, info)."""
        if options:
            raise _tendril.Error(f"tendril env {self.env_id}: reset takes no options, got "
                                 f"{sorted(options)}")
        if seed is not None and (isinstance(seed, bool) or not _is_integer(seed)
                                 or not 0 <= int(seed) < 2**64):
            raise _tendril.Error(f"tendril env {self.env_id}: the seed must be an integer in "
                                 f"[0, 2**64 - 1], got {seed!r}")
        if HAVE_GYMNASIUM:
            super().reset(seed=None if seed is None else int(seed))  # seeds self.np_random
        observation = self._native.reset(None if seed is None else int(seed))
        if self.render_mode is not None and not self._native.has_scene:
            raise _tendril.Error(f"tendril env {self.env_id} describes no scene to draw, so it "
                                 f"cannot render (render_mode={self.render_mode!r})")
        if self.render_mode == "human":
            self._show()
        return observation, {}

    def step(self, action):
        """Returns (observation, reward, terminated, truncated, info)."""
        result = self._native.step(action)
        if self.render_mode is not None:
            seconds = self._native.step_seconds
            if seconds:  # the picture rate of real time, as RecordVideo reads it
                self.metadata["render_fps"] = max(1, min(240, round(1.0 / seconds)))
            if self.render_mode == "human":
                self._show()
        return result

    def scene(self):
        """What a viewer draws now, as NumPy arrays (lab frame, metres): rods' centrelines
        (nodes × 3) and radii, spheres (targets), cylinders (obstacles), ...; None when the
        environment draws nothing."""
        return self._native.scene()

    @property
    def supports_snapshots(self):
        return self._native.supports_snapshots

    def save_state(self):
        """The environment's exact state as bytes; load_state(bytes) returns to it."""
        return self._native.save_state()

    def load_state(self, state):
        self._native.load_state(state)

    def render(self):
        """rgb_array: the scene now (height x width x 3 uint8); human: None (the window shows
        every step); no render_mode: None."""
        if self.render_mode == "rgb_array":
            return self.picture()
        return None

    def picture(self, width=None, height=None):
        """The scene now as a height x width x 3 uint8 array, whatever the render_mode; None for
        an environment without a scene. One view per episode, framed at its first picture."""
        width = self.render_size[0] if width is None else int(width)
        height = self.render_size[1] if height is None else int(height)
        return self._native.render(width, height)

    def _show(self):
        from .viewer import Viewer  # matplotlib loads only for human rendering

        if self._viewer is None:
            self._viewer = Viewer(self.env_id)
        self._viewer.show(self.picture(), 1.0 / self.metadata["render_fps"])

    def close(self):
        if self._viewer is not None:
            self._viewer.close()
            self._viewer = None
        self._native.close()

    def __repr__(self):
        return f"<TendrilEnv {self.env_id}>"


def make(env_id, render_mode=None, **params):
    """A tendril environment by registered id (see registry()), with its parameters and
    optionally Gymnasium's render_mode ("rgb_array" or "human")."""
    return TendrilEnv(env_id, render_mode=render_mode, **params)


def registry():
    """Every registered environment id, sorted."""
    return list(_tendril.registered_ids())


def describe(env_id):
    """`env_id` in words, as `tendril list envs --describe` prints it: a dict with summary,
    max_episode_steps, observation and action (lists of {name, unit, count}, in vector order),
    reward, episode_end and parameters (lists of {key, default, unit, meaning, optional}; default
    is the value the environment read, as YAML text, or None for a key read only when given)."""
    return _tendril.describe(env_id)


def gymnasium_id(env_id):
    """The id under which gymnasium.make finds `env_id`: 'tendril/' + id with '/' as '-'
    ('Elastica/Tracking3D-v0' → 'tendril/Elastica-Tracking3D-v0')."""
    return "tendril/" + env_id.replace("/", "-")


def _gymnasium_entry(tendril_id, render_mode=None, **params):
    return TendrilEnv(tendril_id, render_mode=render_mode, **params)


def register_with_gymnasium():
    """Registers every tendril environment with Gymnasium (gymnasium.make(gymnasium_id(id)))."""
    if not HAVE_GYMNASIUM:
        return
    for env_id in registry():
        name = gymnasium_id(env_id)
        if name not in gymnasium.registry:
            # The time limit is the environment's own (truncated), so Gymnasium adds none.
            gymnasium.register(name, entry_point=_gymnasium_entry, kwargs={"tendril_id": env_id})
