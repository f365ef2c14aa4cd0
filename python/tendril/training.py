"""tendril's trainer in-process (what `tendril train` runs)."""
import json
import os

from . import _tendril


def _yaml_scalar(value):
    # JSON is YAML: numbers, booleans, quoted strings and flow sequences read back exactly.
    return json.dumps(value, allow_nan=False)


def train(config, *, out=None, stop_at=None, quiet=False, callback=None, overrides=None,
          **keys):
    """Runs the experiment file `config` in C++ (the GIL is released) and returns the run
    directory. The progress line (steps, steps/s, mean return, ETA) goes to Python's
    sys.stderr, so notebooks show it, unless quiet; `callback`, when given, is called after
    every iteration with a dict (timesteps, iterations, episodes, ep_rew_mean, ep_len_mean,
    success_rate when reported, train: the update's scalars under SB3's names). A callback that
    raises stops the run as Ctrl-C does, then its exception propagates.

    Overrides are `--set key.path=value` of the command line: a dict {"algo.n_steps": 256} in
    `overrides` and/or keyword arguments with "__" for "." (algo__n_steps=256, seed=1).

    Ctrl-C stops the run as `tendril train` does: at the end of the current iteration, with a
    checkpoint, and then raises KeyboardInterrupt saying how to continue (resume(run))."""
    assignments = [f"{key}={_yaml_scalar(value)}" for key, value in (overrides or {}).items()]
    assignments += [f"{key.replace('__', '.')}={_yaml_scalar(value)}"
                    for key, value in keys.items()]
    result = _tendril.train(os.fspath(config), assignments,
                            None if out is None else os.fspath(out), stop_at, quiet, callback)
    return result["run_directory"]


def resume(run, *, stop_at=None, quiet=False, callback=None):
    """Continues a stopped run from its newest checkpoint (`tendril resume run`), to its
    end or to `stop_at` steps; returns the run directory. Progress and `callback` as train's."""
    return _tendril.resume(os.fspath(run), stop_at, quiet, callback)["run_directory"]
