"""The Python examples run and print their tables."""

import subprocess
import sys


def run_example(repo, name, *args):
    script = repo / "examples" / "python" / name
    out = subprocess.run(
        [sys.executable, str(script), *map(str, args)], check=True, capture_output=True, text=True
    )
    return out.stdout


def test_the_nearest_neighbour_example_prints_both_learners(repo):
    out = run_example(repo, "knn_vs_lin5.py", 60, 1)
    assert "| sklearn k-NN (Python) |" in out and "| lin5 (built in) |" in out


def test_the_rollout_example_prints_both_policies(repo):
    out = run_example(repo, "gym_rollout.py", 40)
    assert "| random | 40 |" in out and "| lin5, learning as it goes | 40 |" in out
