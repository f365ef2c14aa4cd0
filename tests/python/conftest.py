"""Shared set-up of the Python package's tests: the package itself (PYTHONPATH=<build>/python),
the C++ reference program, and Gymnasium / Stable-Baselines3 from the interpreter or from the
vendored upstream sources (TENDRIL_VENDOR)."""
import importlib
import os
import subprocess
import sys

import numpy as np
import pytest

VENDOR = os.environ.get("TENDRIL_VENDOR", "")
REQUIRE_INTEROP = os.environ.get("TENDRIL_REQUIRE_INTEROP") == "1"
INSTALL_HINT = ("install gymnasium==0.29.1 and stable-baselines3==2.3.2 (pip), or point "
                "TENDRIL_VENDOR at a folder holding their sources")


def _import_vendored(module, folder):
    try:
        return importlib.import_module(module)
    except ImportError:
        path = os.path.join(VENDOR, folder)
        if VENDOR and os.path.isdir(path):
            sys.path.insert(0, path)
            return importlib.import_module(module)
        raise


# Before tendril is imported, so that it sees Gymnasium and uses its spaces.
try:
    gymnasium = _import_vendored("gymnasium", "gymnasium-0.29.1")
except ImportError as error:
    if REQUIRE_INTEROP:
        raise
    gymnasium = None
    GYMNASIUM_MISSING = f"Gymnasium is not importable ({error}): {INSTALL_HINT}"

try:
    sb3 = _import_vendored("stable_baselines3", "stable-baselines3-2.3.2")
except ImportError as error:
    if REQUIRE_INTEROP:
        raise
    sb3 = None
    SB3_MISSING = f"Stable-Baselines3 is not importable ({error}): {INSTALL_HINT}"


def require_gymnasium():
    if gymnasium is None:
        pytest.skip(GYMNASIUM_MISSING)
    return gymnasium


def require_sb3():
    if sb3 is None:
        pytest.skip(SB3_MISSING)
    return sb3


REFERENCE = os.environ.get("TENDRIL_REFERENCE", "")

# What a registered environment cannot default (tests/support/required_env_params.hpp): the SMA
# limb robot always names its calibration; "none" is its nominal table on raw readings.
REQUIRED_PARAMS = {"SmaLimb/Robot-v0": {"calibration": "none"},
                   "TendonArm/LearnedReach-v0": {"model": "constant_curvature"}}


def make_by_id(env_id, **kwargs):
    """tendril.make(env_id) with the parameters the environment cannot default."""
    import tendril
    return tendril.make(env_id, **REQUIRED_PARAMS.get(env_id, {}), **kwargs)
APP = os.environ.get("TENDRIL_APP", "")
SOURCE_DIR = os.environ.get("TENDRIL_SOURCE_DIR",
                            os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture
def scratch(tmp_path):
    return tmp_path


def reference(*args):
    """Runs the C++ reference program; fails the test with its message on an error."""
    if not REFERENCE:
        pytest.fail("TENDRIL_REFERENCE is not set: run these tests through ctest")
    done = subprocess.run([REFERENCE, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def reference_episode(env_id, seed, actions, obs_size, scratch):
    """The C++ env's reset observation and per-step (observation, reward, terminated, truncated)
    for `actions`, exactly."""
    actions_file, out_file = scratch / "actions.f32", scratch / "episode.bin"
    np.ascontiguousarray(actions, dtype=np.float32).tofile(actions_file)
    reference("episode", env_id, seed, actions_file, out_file)
    data = out_file.read_bytes()
    row = np.dtype([("obs", "<f4", (obs_size,)), ("reward", "<f8"), ("terminated", "u1"),
                    ("truncated", "u1")])
    first = np.frombuffer(data[:4 * obs_size], dtype="<f4")
    steps = np.frombuffer(data[4 * obs_size:], dtype=row)
    return first, steps
