"""tendril from Python: its environments as Gymnasium environments (with pictures and videos),
vector environments stepped in C++ (with a Stable-Baselines3 adapter), trained policies (and
their export to C and ONNX) and the trainer.

    import tendril
    env = tendril.make("Elastica/Tracking3D-v0", render_mode="rgb_array")
    venv = tendril.make_vec("Elastica/Tracking3D-v0", 8, num_threads=2)
    policy = tendril.load("runs/elastica_tracking3d_ppo-<stamp>")
    tendril.record_video("Elastica/Tracking3D-v0", policy, "arm.mp4")
"""
from ._tendril import Error, numerics
from ._version import __version__
from .env import (TendrilEnv, describe, gymnasium_id, make, register_with_gymnasium,
                  registry)
from .policy import Policy, load
from .training import resume, train
from .vector import VecEnv, make_vec
from .video import episode_video, record_video


def export_c_header(policy, out, name="policy", best=False):
    """The policy (a run directory or .policy file) as a dependency-free C header (docs/export.md;
    tendril.export.export_c_header)."""
    from .export import export_c_header as write

    write(policy, out, name, best)


def export_onnx(policy, out, best=False):
    """The policy as an ONNX model, checked by onnx.checker (tendril.export.export_onnx)."""
    from .export import export_onnx as write

    write(policy, out, best)


__all__ = ["Error", "Policy", "TendrilEnv", "VecEnv", "__version__", "describe", "episode_video",
           "export_c_header", "export_onnx", "gymnasium_id", "load", "make", "make_vec",
           "numerics", "record_video", "registry", "resume", "train"]

register_with_gymnasium()
