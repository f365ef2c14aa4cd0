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
    is_success, ...). The registered time limit is part of the environment (`truncated`)."""

    metadata = {"render_modes": []}
    render_mode = None

    def __init__(self, env_id, **params):
        self._native = _tendril.Env(env_id, params_json(env_id, params))
        self.env_id = env_id
        self.params = dict(params)
        self.observation_space = from_native(self._native.observation_space)
        self.action_space = from_native(self._native.action_space)
        self.max_episode_steps = _tendril.max_episode_steps(env_id)

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
        return self._native.reset(None if seed is None else int(seed)), {}

    def step(self, action):
        """Returns (observation, reward, terminated, truncated, info)."""
        return self._native.step(action)

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
        return None

    def close(self):
        self._native.close()

    def __repr__(self):
        return f"<TendrilEnv {self.env_id}>"


def make(env_id, **params):
    """A tendril environment by registered id (see registry()), with its parameters."""
    return TendrilEnv(env_id, **params)


def registry():
    """Every registered environment id, sorted."""
    return list(_tendril.registered_ids())


def gymnasium_id(env_id):
    """The id under which gymnasium.make finds `env_id`: 'tendril/' + id with '/' as '-'
    ('Elastica/Tracking3D-v0' → 'tendril/Elastica-Tracking3D-v0')."""
    return "tendril/" + env_id.replace("/", "-")


def _gymnasium_entry(tendril_id, **params):
    return TendrilEnv(tendril_id, **params)


def register_with_gymnasium():
    """Registers every tendril environment with Gymnasium (gymnasium.make(gymnasium_id(id)))."""
    if not HAVE_GYMNASIUM:
        return
    for env_id in registry():
        name = gymnasium_id(env_id)
        if name not in gymnasium.registry:
            # The time limit is the environment's own (truncated), so Gymnasium adds none.
            gymnasium.register(name, entry_point=_gymnasium_entry, kwargs={"tendril_id": env_id})
