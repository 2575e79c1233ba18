"""The Testbed drives the run's trial loop step by step: same draws, same moves, same bytes,
a learner started (pre-learned) as a run starts it."""

import numpy as np
import pytest

import eyehand


def step_lines(distances):
    """A step file's lines as the run writes them, minutes aside."""
    return [f"{trial} {d:.6f}" for trial, d in distances]


def strip_minutes(path):
    return [" ".join(line.split()[:2]) for line in path.read_text().splitlines()]


@pytest.mark.parametrize("method", ["ik", "lin5"])
def test_a_testbed_loop_gives_the_cli_run_byte_for_byte(repo, cli, tmp_path, method):
    trials = 60
    cli("run", "--config", f"configs/{method}.conf", "--trials", trials, "--seed", 1,
        "--data", tmp_path, "--quiet", "--no-plot")
    folder = tmp_path / method / "0"
    testbed = eyehand.Testbed(config=repo / "configs" / f"{method}.conf", seed=1)
    learner = eyehand.Learner(method)
    testbed.prelearn(learner)
    recorded = [[] for _ in range(eyehand.RECORDED_STEPS)]
    for trial in range(1, trials + 1):
        testbed.reset()
        while not testbed.done:
            _reading, _joints, distance, seen = testbed.step(learner.propose(testbed.observation))
            if seen and testbed.steps <= eyehand.RECORDED_STEPS:
                recorded[testbed.steps - 1].append((trial, distance))
        testbed.learn(learner)
    for step in range(eyehand.RECORDED_STEPS):
        expected = strip_minutes(folder / f"{step + 1}step")
        assert step_lines(recorded[step]) == expected, f"{step + 1}step"
    assert len(recorded[0]) > trials // 2, "most trials see the object after their first step"
    if method == "ik":
        assert len(recorded[0]) == trials, "ik's first step keeps it in view in every trial"


def test_a_testbed_learner_finds_a_camera_turn_as_the_run_does(repo, cli, tmp_path):
    """Each trial begins for the learner as a run begins it, so its change watch dates the
    turn and recovers on the same trials, byte for byte."""
    trials, turn = 300, 250
    cli("run", "--config", "configs/lin5.conf", "--trials", trials, "--seed", 1,
        "--set", "merge_strategy=change_detection", "--event", f"rotate:{turn}:90",
        "--data", tmp_path, "--quiet", "--no-plot")
    folder = tmp_path / "lin5" / "0"
    assert (folder / "changes").read_text().split()[1] == str(turn), "the run finds the turn"
    testbed = eyehand.Testbed(config=repo / "configs" / "lin5.conf", seed=1)
    learner = eyehand.Learner("lin5", merge_strategy="change_detection")
    testbed.prelearn(learner)
    first_step = []
    for trial in range(1, trials + 1):
        if trial == turn:
            testbed.rotate_camera(90.0)
        testbed.reset()
        while not testbed.done:
            _reading, _joints, distance, seen = testbed.step(learner.propose(testbed.observation))
            if seen and testbed.steps == 1:
                first_step.append((trial, distance))
        testbed.learn(learner)
    assert step_lines(first_step) == strip_minutes(folder / "1step")


def test_a_trial_ends_as_the_trial_loop_ends_it():
    testbed = eyehand.Testbed(seed=3)
    start = testbed.reset()
    assert start.shape == (5,)
    assert testbed.steps == 0 and testbed.end is None and not testbed.done
    for step in range(1, testbed.feedback_steps + 1):
        reading, joints, distance, seen = testbed.step([0.0, 0.0, 0.0])
        assert seen and reading.shape == (3,) and joints.shape == (3,)
        assert distance == pytest.approx(testbed.distance_mm)
        assert testbed.steps == step
    assert testbed.end == "steps_used" and testbed.done
    with pytest.raises(RuntimeError, match="no trial is going on"):
        testbed.step([0.0, 0.0, 0.0])
    assert testbed.path.shape == (1 + testbed.feedback_steps, 6)


def test_a_move_that_loses_the_object_ends_the_trial():
    testbed = eyehand.Testbed(seed=5)
    testbed.reset()
    reading, _joints, distance, seen = testbed.step([90.0, 0.0, 0.0])
    assert reading is None and not seen and distance > 0
    assert testbed.end == "lost"


def test_bad_moves_and_events_are_value_errors():
    testbed = eyehand.Testbed()
    testbed.reset()
    with pytest.raises(ValueError, match="not finite"):
        testbed.step([np.nan, 0.0, 0.0])
    with pytest.raises(ValueError, match="three numbers"):
        testbed.step([1.0, 2.0])
    assert testbed.steps == 0, "a refused move moves nothing"
    with pytest.raises(ValueError):
        testbed.stretch_link(7, 2.0)


def test_events_change_the_robot_as_fk_sees_it():
    testbed = eyehand.Testbed()
    before = testbed.fk([0.0, 45.0, 90.0])
    assert before["joints_deg"].shape == (6,)
    testbed.stretch_link(2, 5.0)
    after = testbed.fk([0.0, 45.0, 90.0])
    assert np.linalg.norm(after["camera_cm"] - before["camera_cm"]) == pytest.approx(5.0, rel=1e-6)


def test_fk_matches_the_cli(cli):
    import json

    out = json.loads(cli("fk", "--joints", "10,40,100", "--json").stdout)
    fk = eyehand.Testbed().fk([10.0, 40.0, 100.0])
    assert np.allclose(fk["camera_cm"], out["camera_cm"], atol=1e-9)
    assert np.allclose(fk["joints_deg"], out["joints_deg"], atol=1e-9)


def test_a_bad_config_file_is_a_value_error_naming_file_and_line(repo, tmp_path):
    text = (repo / "configs" / "lin5.conf").read_text().splitlines()
    line = len(text)
    text.append("feedback_steps   many")
    bad = tmp_path / "bad.conf"
    bad.write_text("\n".join(text) + "\n")
    with pytest.raises(ValueError, match=f"^{bad}:{line + 1}: "):
        eyehand.Testbed(config=bad)
    with pytest.raises(ValueError, match=f"^{bad}:{line + 1}: "):
        eyehand.run(config=bad, data=tmp_path)
    with pytest.raises(ValueError, match="unknown entry `no_such_entry`"):
        eyehand.Testbed(no_such_entry=3)


@pytest.mark.parametrize("order", ["sim first", "entries first"])
def test_keyword_entries_are_applied_together_and_checked_once(order):
    # camera_fps above 0 needs the dynamic simulator: given together, in either order, the
    # pair is one valid config.
    given = {"sim": "dynamic", "camera_fps": 30} if order == "sim first" else {"camera_fps": 30, "sim": "dynamic"}
    testbed = eyehand.Testbed(seed=2, **given)
    assert testbed.reset().shape == (5,)
    _reading, _joints, distance, _seen = testbed.step([0.5, 0.5, 0.5])
    assert np.isfinite(distance)
    learner = eyehand.Learner("lin5", **given)
    assert learner.name == "lin5"


def test_a_bad_keyword_entry_is_refused_with_its_name():
    with pytest.raises(ValueError, match="camera_fps"):
        eyehand.Testbed(sim="dynamic", camera_fps=-1)
    with pytest.raises(ValueError, match="camera_fps"):
        eyehand.Testbed(camera_fps=30)
    with pytest.raises(ValueError, match="tree_depth"):
        eyehand.Learner("lin5", tree_depth="deep")
