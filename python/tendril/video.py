"""Videos of environments: a policy's episodes as they are played now (record_video), or an
episode recorded earlier by `tendril run RUN --record DIR` (episode_video). Frames come from tendril's
software rasterizer; Debian's ffmpeg encodes them (.mp4, .webm or .gif)."""
import os

import numpy as np

from . import _tendril


def _acting(policy, deterministic):
    """A function observation -> action from a tendril Policy, a run directory or policy file,
    anything with SB3's predict(), or a plain callable."""
    if isinstance(policy, (str, os.PathLike)):
        from .policy import load

        policy = load(policy)
    if hasattr(policy, "act"):
        return lambda observation: policy.act(observation, deterministic)
    if hasattr(policy, "predict"):
        return lambda observation: policy.predict(observation, deterministic=deterministic)[0]
    if callable(policy):
        return policy
    raise _tendril.Error(f"record_video: cannot act with {policy!r} (a tendril Policy, a run "
                         f"directory, an SB3 model or a function of the observation)")


def record_video(env, policy, path, *, episodes=1, seed=0, deterministic=True, size=(640, 480),
                 max_fps=30, every=1, max_steps=None):
    """Plays `episodes` episodes of `env` (an environment id or a TendrilEnv) with `policy` and
    writes them, one after the other, as the video `path`; returns the episodes' returns.

    Every `every`-th step is a frame, shown at the environment's own rate up to `max_fps`
    frames per second: real time for environments that step at most that often, slow motion
    for faster ones (an Elastica arm steps every 1.4 ms). Reset seeds are seed, seed + 1, ...;
    `max_steps` cuts episodes short (the environment's own time limit applies anyway)."""
    from .env import TendrilEnv, make

    owned = not isinstance(env, TendrilEnv)
    if owned:
        env = make(env)
    act = _acting(policy, deterministic)
    width, height = (int(v) for v in size)
    returns = []
    writer = None
    try:
        for episode in range(int(episodes)):
            observation, _ = env.reset(seed=int(seed) + episode)
            frames = [env.picture(width, height)]
            if frames[0] is None:
                raise _tendril.Error(f"tendril env {env.env_id} describes no scene to draw")
            total, steps = 0.0, 0
            while True:
                observation, reward, terminated, truncated, _ = env.step(act(observation))
                total += float(reward)
                steps += 1
                if writer is None:
                    # The first step tells the environment's clock, and so the frame rate.
                    seconds = env._native.step_seconds or 1.0 / max_fps
                    fps = min(1.0 / (seconds * every), max_fps)
                    writer = _tendril.VideoWriter(os.fspath(path), width, height, fps)
                    for frame in frames:
                        writer.write(frame)
                    frames = []
                if steps % every == 0:
                    writer.write(env.picture(width, height))
                if terminated or truncated or (max_steps is not None and steps >= max_steps):
                    break
            returns.append(total)
        writer.finish()
    finally:
        if owned:
            env.close()
    return np.asarray(returns)


def episode_video(episode, path, *, size=(960, 540), speed=0.0, fps=0.0, max_fps=30.0,
                  trails=True):
    """Writes a video of a recorded episode file (.tep, `tendril run --record`): one fixed view of the
    whole episode, the arm tip's and targets' paths drawn up to each moment. speed 0: one frame
    per step at the recording's rate up to max_fps (slow motion for fast environments); speed
    > 0: that many episode seconds per video second. Returns the number of frames."""
    width, height = (int(v) for v in size)
    return _tendril.episode_video(os.fspath(episode), os.fspath(path), width, height, float(fps),
                                  float(max_fps), float(speed), 2, bool(trails))
