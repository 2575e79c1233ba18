"""eyehand.run with built-in and Python learners: the run folder, errors, the GIL."""

import json
import threading
import time

import numpy as np
import pytest

import eyehand


class PythonIk:
    """A Python learner that wraps the analytic inverse kinematics."""

    name = "pyik"

    def __init__(self):
        self.ik = eyehand.Learner("ik")
        self.learned = 0

    def propose(self, query):
        return self.ik.propose(query)

    def learn(self, path):
        assert path.shape[1] == 6
        self.learned += 1


def test_a_python_ik_learner_reaches_epsilon_in_one_step(repo, tmp_path):
    learner = PythonIk()
    result = eyehand.run(learner, trials=40, config=repo / "configs" / "ik.conf", data=tmp_path)
    first = result["distances_mm"][0]
    assert len(first) == 40 and np.all(first <= 0.5)
    assert learner.learned == 8 + 40, "pre-learning moves and trials are learned"
    assert result["folder"] == tmp_path / "pyik" / "0"
    assert result["summary"]["method"] == "pyik"


def test_a_python_learner_run_is_a_folder_eyehand_plot_draws(cli, tmp_path):
    result = eyehand.run(PythonIk(), trials=30, data=tmp_path)
    folder = result["folder"]
    summary = json.loads((folder / "summary.json").read_text())
    assert summary == result["summary"]
    cli("plot", folder)
    assert (folder / "plot.png").stat().st_size > 0


def test_a_builtin_run_returns_the_summary_and_the_step_distances(tmp_path):
    result = eyehand.run(method="lin5", trials=200, seed=2, data=tmp_path)
    summary = result["summary"]
    assert summary["method"] == "lin5" and summary["trials"] == 200 and summary["seed"] == 2
    trials, distances = result["trials"][0], result["distances_mm"][0]
    assert isinstance(distances, np.ndarray) and trials.dtype == np.int64
    assert len(trials) >= 200 - summary["failures"] and np.all(np.diff(trials) > 0)
    window = distances[trials > 200 - summary["window"]]
    assert summary["mean_distance_mm"][0] == pytest.approx(window.mean(), rel=1e-5)


class Failing(PythonIk):
    """Raises (or answers NaN) at a given call of propose."""

    name = "failing"

    def __init__(self, at, answer_nan=False):
        super().__init__()
        self.calls, self.at, self.answer_nan = 0, at, answer_nan

    def propose(self, query):
        self.calls += 1
        if self.calls == self.at:
            if self.answer_nan:
                return np.array([0.0, np.nan, 0.0])
            raise KeyError("the learner broke")
        return super().propose(query)


@pytest.mark.parametrize("answer_nan", [False, True])
def test_a_learner_failure_stops_the_run_and_leaves_its_files(tmp_path, answer_nan):
    learner = Failing(at=5 * 7 + 2, answer_nan=answer_nan)
    expected = ValueError if answer_nan else KeyError
    match = "non-finite move" if answer_nan else "the learner broke"
    with pytest.raises(expected, match=match):
        eyehand.run(learner, trials=50, data=tmp_path)
    assert learner.calls == learner.at, "no call after the failure"
    folder = tmp_path / "failing" / "0"
    lines = (folder / "1step").read_text().splitlines()
    assert [int(line.split()[0]) for line in lines] == list(range(1, 8)), "7 whole trials, flushed"
    assert (folder / "info").read_text().startswith("# eyehand")


def test_a_learner_whose_learn_raises_stops_the_run(tmp_path):
    class BadLearn(PythonIk):
        name = "badlearn"

        def learn(self, path):
            raise RuntimeError("cannot learn")

    with pytest.raises(RuntimeError, match="cannot learn"):
        eyehand.run(BadLearn(), trials=5, data=tmp_path)


def test_bad_arguments_are_value_errors(tmp_path):
    with pytest.raises(ValueError, match="not both"):
        eyehand.run(PythonIk(), method="lin5", data=tmp_path)
    with pytest.raises(ValueError, match="bad event"):
        eyehand.run(method="ik", trials=1, events=["rotate:x"], data=tmp_path)
    with pytest.raises(ValueError, match="trials"):
        eyehand.run(method="ik", trials=0, data=tmp_path)


def main_thread_pauses(trials, data):
    """Runs lin5 for ``trials`` in a thread while the main thread ticks every millisecond;
    the run's seconds and the longest pause between ticks."""
    done = []
    worker = threading.Thread(
        target=lambda: done.append(eyehand.run(method="lin5", trials=trials, data=data))
    )
    ticks = []
    started = time.perf_counter()
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - started
    assert done, "the run finished"
    return elapsed, np.diff([started, *ticks, time.perf_counter()]).max()


def test_the_gil_is_released_during_a_long_run(tmp_path):
    trials = 1000
    elapsed, pause = main_thread_pauses(trials, tmp_path)
    while elapsed < 0.5 and trials < 256_000:
        trials *= 4
        elapsed, pause = main_thread_pauses(trials, tmp_path)
    assert elapsed >= 0.5, f"a run long enough to tell ({elapsed:.2f} s)"
    assert pause < elapsed / 3, f"the main thread went on (longest pause {pause:.3f} s of {elapsed:.2f} s)"


def test_patterns_are_the_adjusted_patterns_in_the_query_order():
    path = np.array(
        [
            [10.0, -20.0, 5.0, 0.0, 40.0, 100.0],
            [0.0, 0.0, 0.0, 0.0, 45.0, 98.0],
            [1.0, 2.0, 3.0, 0.0, 45.0, 98.05],
        ]
    )
    inputs, targets = eyehand.patterns(path, minimal_joint_move=0.1)
    assert inputs.shape == (2, 5) and targets.shape == (2, 3), "the 0.05° move is no pattern"
    assert np.allclose(inputs[0], [10.0, -20.0, 5.0, 40.0, 100.0])
    assert np.allclose(targets[0], [0.0, 5.0, -2.0])
    assert np.allclose(inputs[1], [9.0, -22.0, 2.0, 40.0, 100.0])


CHILD_RUN = """
import sys
import eyehand

class Slow:
    name = "slowik"
    def __init__(self):
        self.ik = eyehand.Learner("ik")
    def propose(self, query):
        return self.ik.propose(query)
    def learn(self, path):
        pass

learner = Slow() if sys.argv[2] == "python" else None
method = None if learner else "lin5"
eyehand.run(learner, method=method, trials=2_000_000, data=sys.argv[1])
"""


@pytest.mark.parametrize("learner", ["builtin", "python"])
def test_ctrl_c_stops_a_run_after_its_trial_and_keeps_its_folder(tmp_path, learner):
    import signal
    import subprocess
    import sys

    child = subprocess.Popen(
        [sys.executable, "-c", CHILD_RUN, str(tmp_path), learner],
        stderr=subprocess.PIPE,
        text=True,
    )
    name = "slowik" if learner == "python" else "lin5"
    flushed = tmp_path / name / "0" / "1step"
    deadline = time.monotonic() + 60
    while not (flushed.exists() and flushed.stat().st_size > 0):
        assert child.poll() is None, f"the run ended before the signal: {child.stderr.read()}"
        assert time.monotonic() < deadline, "the run wrote no trial in 60 s"
        time.sleep(0.05)
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=60)
    assert child.returncode != 0 and "KeyboardInterrupt" in stderr, stderr
    summary = json.loads((tmp_path / name / "0" / "summary.json").read_text())
    assert summary["interrupted"] is True
    assert 0 < summary["trials"] < 2_000_000
