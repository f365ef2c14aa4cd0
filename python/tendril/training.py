"""tendril's trainer in-process (what `tendril train` runs)."""
import json
import os

from . import _tendril


def _yaml_scalar(value):
    # JSON is YAML: numbers, booleans, quoted strings and flow sequences read back exactly.
    return json.dumps(value, allow_nan=False)


def train(config, *, out=None, stop_at=None, quiet=False, overrides=None, **keys):
    """Runs the experiment file `config` in C++ (the GIL is released; the progress line goes to
    standard error unless quiet) and returns the run directory.

    Overrides are `--set key.path=value` of the command line: a dict {"algo.n_steps": 256} in
    `overrides` and/or keyword arguments with "__" for "." (algo__n_steps=256, seed=1).

    Ctrl-C stops the run as `tendril train` does: at the end of the current iteration, with a
    checkpoint, and then raises KeyboardInterrupt saying how to continue (resume(run))."""
    assignments = [f"{key}={_yaml_scalar(value)}" for key, value in (overrides or {}).items()]
    assignments += [f"{key.replace('__', '.')}={_yaml_scalar(value)}"
                    for key, value in keys.items()]
    result = _tendril.train(os.fspath(config), assignments,
                            None if out is None else os.fspath(out), stop_at, quiet)
    return result["run_directory"]


def resume(run, *, stop_at=None, quiet=False):
    """Continues a stopped run from its newest checkpoint (`tendril resume run`), to its
    end or to `stop_at` steps; returns the run directory."""
    return _tendril.resume(os.fspath(run), stop_at, quiet)["run_directory"]
