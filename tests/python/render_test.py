"""Seeing from Python: render_mode="rgb_array" and "human" on every environment that describes a
scene (through tendril.make and gymnasium.make), pictures that are non-trivial and
deterministic, and videos of a policy's episodes that ffprobe reads back."""
import json
import shutil
import subprocess
import warnings

import numpy as np
import pytest

from conftest import make_by_id, require_gymnasium

import tendril

# Environments that need nothing but their id to be made.
MADE = {}
for env_id in tendril.registry():
    try:
        MADE[env_id] = make_by_id(env_id)
    except tendril.Error:
        pass  # learned-model environments need a model file
WITH_SCENE = []
for env_id, env in MADE.items():
    env.reset(seed=0)
    if env.scene() is not None:
        WITH_SCENE.append(env_id)
    env.close()


def test_scene_environments_are_found():
    for env_id in ("Elastica/Tracking3D-v0", "Elastica/StructuredObstacles-v0"):
        assert env_id in WITH_SCENE
    assert "Pendulum-v1" in MADE and "Pendulum-v1" not in WITH_SCENE


@pytest.mark.parametrize("env_id", WITH_SCENE)
def test_rgb_array_is_a_deterministic_picture_of_the_scene(env_id):
    pictures = []
    for _ in range(2):
        env = make_by_id(env_id, render_mode="rgb_array", render_size=(160, 120))
        env.reset(seed=4)
        env.action_space.seed(4)
        for _ in range(3):
            env.step(env.action_space.sample())
        picture = env.render()
        env.close()
        pictures.append(picture)
    picture = pictures[0]
    assert picture.shape == (120, 160, 3) and picture.dtype == np.uint8
    # Something is drawn: a fair share of pixels differ from the background's colour.
    background = picture[0, 0]
    drawn = np.any(picture != background, axis=2).mean()
    assert drawn > 0.02, f"{env_id}: only {drawn:.1%} of the picture is drawn"
    np.testing.assert_array_equal(pictures[0], pictures[1])


def test_pictures_follow_the_arm():
    env = tendril.make("Elastica/Tracking3D-v0", render_mode="rgb_array", render_size=(160, 120))
    env.reset(seed=1)
    first = env.render()
    for _ in range(30):
        env.step(np.ones(env.action_space.shape, dtype=np.float32))
    later = env.render()
    assert np.any(first != later)


def test_gymnasium_make_accepts_render_mode():
    gymnasium = require_gymnasium()
    env = gymnasium.make("tendril/Elastica-Tracking3D-v0", render_mode="rgb_array")
    assert env.render_mode == "rgb_array"
    env.reset(seed=0)
    picture = env.render()
    assert picture.shape == (480, 640, 3)
    env.step(env.action_space.sample())
    assert env.unwrapped.metadata["render_fps"] >= 1
    with pytest.raises(tendril.Error, match="render_mode"):
        tendril.make("Elastica/Tracking3D-v0", render_mode="rgb")


def test_environment_without_a_scene_refuses_to_render():
    env = tendril.make("Pendulum-v1", render_mode="rgb_array")
    with pytest.raises(tendril.Error, match="no scene"):
        env.reset(seed=0)
    assert tendril.make("Pendulum-v1").render() is None  # no render_mode: nothing to do


def test_human_mode_shows_every_step(monkeypatch):
    import matplotlib

    matplotlib.use("Agg")  # no display here: the window is drawn, not shown
    env = tendril.make("Elastica/Tracking3D-v0", render_mode="human", render_size=(80, 60))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # Agg says it cannot show windows
        env.reset(seed=0)
        env.step(env.action_space.sample())
    image = env._viewer.figure.axes[0].images[0].get_array()
    np.testing.assert_array_equal(np.asarray(image), env.picture())
    assert env.render() is None
    env.close()


def probe(path):
    done = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                           "-show_entries", "stream=codec_name,width,height,nb_read_frames",
                           "-of", "json", str(path)], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)["streams"][0]


def test_record_video_of_a_policy(tmp_path):
    assert shutil.which("ffmpeg"), "ffmpeg is missing: scripts/setup installs it"
    path = tmp_path / "arm.mp4"
    shape = tendril.make("Elastica/Tracking3D-v0").action_space.shape
    returns = tendril.record_video("Elastica/Tracking3D-v0",
                                   lambda observation: np.full(shape, 0.5, dtype=np.float32),
                                   path, episodes=2, size=(160, 120), max_steps=25)
    assert returns.shape == (2,)
    stream = probe(path)
    assert stream["codec_name"] == "h264"
    assert (stream["width"], stream["height"]) == (160, 120)
    # Two episodes of 25 steps and their first pictures, at most 30 frames per second of the
    # environment's clock: never more frames than pictures taken.
    assert 2 <= int(stream["nb_read_frames"]) <= 52
    with pytest.raises(tendril.Error, match="exists already"):
        tendril.record_video("Elastica/Tracking3D-v0", lambda o: np.zeros(shape, np.float32),
                             path, size=(160, 120), max_steps=2)
