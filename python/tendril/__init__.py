"""tendril from Python: its environments as Gymnasium environments, vector environments stepped
in C++ (with a Stable-Baselines3 adapter), trained policies and the trainer.

    import tendril
    env = tendril.make("Elastica/Tracking3D-v0")
    venv = tendril.make_vec("Elastica/Tracking3D-v0", 8, num_threads=2)
    policy = tendril.load("runs/elastica_tracking3d_ppo-<stamp>")
"""
from ._tendril import Error, numerics
from .env import TendrilEnv, gymnasium_id, make, register_with_gymnasium, registry
from .policy import Policy, load
from .training import resume, train
from .vector import VecEnv, make_vec

__all__ = ["Error", "Policy", "TendrilEnv", "VecEnv", "gymnasium_id", "load", "make",
           "make_vec", "numerics", "registry", "resume", "train"]

register_with_gymnasium()
