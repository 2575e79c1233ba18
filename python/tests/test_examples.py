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


def test_the_mlp_example_learns_online_through_the_whole_learner_api(repo):
    out = run_example(repo, "mlp_online.py", 300, 1)
    row = next(line for line in out.splitlines() if line.startswith("| sklearn MLP"))
    cells = [cell.strip() for cell in row.strip("|").split("|")]
    start, steps, nodes = float(cells[1]), [float(c) for c in cells[2:7]], int(cells[7])
    assert start > 100.0, "targets start far away"
    assert steps[4] < 0.15 * start, f"after 5 steps well below the start distance: {row}"
    assert steps[4] < steps[0], row
    assert nodes == 128, "size() reports the hidden units"
    assert "| lin5 (built in) |" in out
