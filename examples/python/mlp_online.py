"""scikit-learn's ``MLPRegressor`` as an online learner through ``eyehand.run``, with the
whole learner API: named inputs (``eyehand_api = 2``), ``setup(config)`` for the run's
boundaries and seed, and ``size()`` for the summary; next to the built-in lin5.

    python examples/python/mlp_online.py [TRIALS] [SEED]

The net learns each trial's patterns with ``partial_fit`` (a few passes over them and an
equal share of earlier patterns replayed from a bounded buffer), inputs scaled to [−1, 1]
by the config's boundaries, moves by ``MOVE_SCALE``. It prints the mean distance to the
target at a trial's start and after steps 1..5 over the last trials, for both learners.
"""

import sys
import tempfile

import numpy as np
from sklearn.neural_network import MLPRegressor

import eyehand

#: Degrees of a move per unit of the net's output.
MOVE_SCALE = 10.0


class SklearnMlp:
    """An MLP fitted online, one trial's patterns (and as many replayed ones) at a time."""

    name = "sklearn_mlp"
    eyehand_api = 2

    def __init__(self, hidden=(64, 64), passes=3, replay=20_000, rate=2e-3):
        self.hidden, self.passes, self.capacity, self.rate = hidden, passes, replay, rate
        self.net = None

    def setup(self, config):
        """Takes the input boundaries and the seed of the run."""
        self.low, self.high = eyehand.input_bounds(config)
        self.rng = np.random.default_rng(config["seed"])
        self.net = MLPRegressor(
            hidden_layer_sizes=self.hidden,
            learning_rate_init=self.rate,
            random_state=config["seed"],
        )
        self.inputs = np.zeros((0, len(eyehand.INPUTS)))
        self.targets = np.zeros((0, len(eyehand.TARGETS)))
        self.fitted = False

    def scaled(self, inputs):
        return 2.0 * (inputs - self.low) / (self.high - self.low) - 1.0

    def propose(self, query):
        if not self.fitted:
            return np.zeros(3)
        return self.net.predict(self.scaled(query.inputs)[None, :])[0] * MOVE_SCALE

    def learn(self, patterns):
        if len(patterns) == 0:
            return
        inputs, targets = self.scaled(patterns.inputs), patterns.targets / MOVE_SCALE
        if len(self.targets):
            old = self.rng.integers(len(self.targets), size=len(targets))
            batch_inputs = np.vstack([inputs, self.inputs[old]])
            batch_targets = np.vstack([targets, self.targets[old]])
        else:
            batch_inputs, batch_targets = inputs, targets
        for _ in range(self.passes):
            self.net.partial_fit(batch_inputs, batch_targets)
        self.fitted = True
        self.inputs = np.vstack([self.inputs, inputs])[-self.capacity :]
        self.targets = np.vstack([self.targets, targets])[-self.capacity :]

    def size(self):
        """Hidden units of the net."""
        return sum(self.hidden)


def start_distance_mm(seed, trials=200):
    """Mean distance (mm) of the camera to the target at the start of ``trials`` seeded
    trials, as a run draws them."""
    testbed = eyehand.Testbed(seed=seed)
    distances = []
    for _ in range(trials):
        testbed.reset()
        distances.append(testbed.distance_mm)
    return float(np.mean(distances))


def row(name, start, result):
    summary = result["summary"]
    means = " | ".join(f"{m:.2f}" if m is not None else "-" for m in summary["mean_distance_mm"])
    return f"| {name} | {start:.1f} | {means} | {summary['nodes']} | {summary['trials_per_second']:.0f} |"


def main():
    trials = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    with tempfile.TemporaryDirectory() as data:
        mlp = eyehand.run(SklearnMlp(), trials=trials, seed=seed, data=data)
        lin5 = eyehand.run(method="lin5", trials=trials, seed=seed, data=data)
    start = start_distance_mm(seed)
    window = mlp["summary"]["window"]
    print(f"{trials} trials, seed {seed}: mean distance (mm) at the start and after steps 1..5, last {window} trials")
    print("| learner | start | step 1 | step 2 | step 3 | step 4 | step 5 | nodes | trials/s |")
    print("|---|---|---|---|---|---|---|---|---|")
    print(row("sklearn MLP, partial_fit (Python)", start, mlp))
    print(row("lin5 (built in)", start, lin5))


if __name__ == "__main__":
    main()
