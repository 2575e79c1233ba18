"""render() and the camera image observation of the environments."""

import gymnasium as gym
import numpy as np
import pytest

import eyehand  # noqa: F401  (registers the environments)

#: A frame: arm.png's 1120 × 900 beside the 512 × (512 + 44) camera image.
FRAME_SHAPE = (900, 1120 + 512, 3)


@pytest.mark.parametrize("name", ["eyehand/Reach-v0", "eyehand/ReachGoal-v0"])
def test_render_draws_the_arm_and_the_camera_and_changes_when_the_arm_moves(name):
    env = gym.make(name, render_mode="rgb_array")
    assert "rgb_array" in env.metadata["render_modes"]
    env.reset(seed=4)
    before = env.render()
    assert before.shape == FRAME_SHAPE and before.dtype == np.uint8
    camera = before[:512, 1120:]
    assert camera.max() == 255, "the target sphere is white in the camera image"
    assert np.array_equal(env.render(), before), "the same pose, the same frame"
    env.step(np.array([0.5, -0.5, 0.5], dtype=np.float32))
    after = env.render()
    assert after.shape == FRAME_SHAPE
    changed = np.any(after != before, axis=2)
    assert changed[:, :1120].sum() > 500, "the arm view shows the new pose"
    assert changed[:512, 1120:].sum() > 500, "the camera sees from elsewhere"


def test_render_without_a_mode_or_a_reset_says_so():
    env = gym.make("eyehand/Reach-v0").unwrapped
    env.reset(seed=1)
    with pytest.warns(UserWarning, match="render_mode"):
        assert env.render() is None
    fresh = eyehand.Testbed()
    assert fresh.render() is None
    with pytest.raises(ValueError, match="render_mode"):
        gym.make("eyehand/Reach-v0", render_mode="video")


def test_the_camera_image_observation_is_the_ray_cast_view_at_the_chosen_resolution():
    env = gym.make("eyehand/Reach-v0", image_resolution=48).unwrapped
    obs, _ = env.reset(seed=6)
    assert env.observation_space.contains(obs)
    image = obs["image"]
    assert image.shape == (48, 48, 1) and image.dtype == np.uint8
    assert image.max() == 255 and (image == 255).sum() < 48 * 48 / 4, "a small white blob"
    bright = np.argwhere(image[:, :, 0] > 128).mean(axis=0)
    cx, cy = obs["reading"][:2]
    # The blob's centre in the image agrees with the reading (pixels of 512 / 48).
    assert np.allclose(bright[::-1], (np.array([cx, cy]) + 256) * 48 / 512 - 0.5, atol=2.0)
    moved, *_ = env.step(np.array([0.4, 0.4, -0.4], dtype=np.float32))
    assert not np.array_equal(moved["image"], image)
    with pytest.raises(ValueError, match="image_resolution"):
        gym.make("eyehand/Reach-v0", image_resolution=1)
