"""A scikit-learn nearest-neighbour learner run through ``eyehand.run`` on the testbed's
trial loop, next to the built-in lin5, in one table.

    python examples/python/knn_vs_lin5.py [TRIALS] [SEED]

The learner keeps the latest learning patterns of its trials (``eyehand.patterns``: the
adjusted inputs lin5 learns from, in the query's order) and answers a query with the mean
move of its K nearest stored patterns, inputs scaled by the config's boundaries.
"""

import sys
import tempfile

import numpy as np
from sklearn.neighbors import KNeighborsRegressor

import eyehand

#: Input scale: the width of the config's boundaries of cx, cy, cz, θ2, θ3.
SCALE = np.array([768.0, 768.0, 450.0, 90.0, 105.0])


class SklearnNeighbours:
    """The K nearest of the latest ``capacity`` patterns answer a query."""

    name = "sklearn_knn"

    def __init__(self, k=4, capacity=20_000, refit_every=10):
        self.k, self.capacity, self.refit_every = k, capacity, refit_every
        self.inputs = np.zeros((0, 5))
        self.targets = np.zeros((0, 3))
        self.model = None
        self.trials = 0

    def propose(self, query):
        if self.model is None:
            return np.zeros(3)
        return self.model.predict((np.asarray(query) / SCALE)[None, :])[0]

    def learn(self, path):
        inputs, targets = eyehand.patterns(path)
        self.inputs = np.vstack([self.inputs, inputs / SCALE])[-self.capacity :]
        self.targets = np.vstack([self.targets, targets])[-self.capacity :]
        self.trials += 1
        if len(self.targets) >= self.k and (self.model is None or self.trials % self.refit_every == 0):
            self.model = KNeighborsRegressor(n_neighbors=self.k).fit(self.inputs, self.targets)


def row(name, result):
    summary = result["summary"]
    means = " | ".join(f"{m:.2f}" if m is not None else "-" for m in summary["mean_distance_mm"])
    return f"| {name} | {means} | {summary['failures']} | {summary['trials_per_second']:.0f} |"


def main():
    trials = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    with tempfile.TemporaryDirectory() as data:
        knn = eyehand.run(SklearnNeighbours(), trials=trials, seed=seed, data=data)
        lin5 = eyehand.run(method="lin5", trials=trials, seed=seed, data=data)
    window = knn["summary"]["window"]
    print(f"{trials} trials, seed {seed}: mean distance (mm) after steps 1..5, last {window} trials")
    print("| learner | step 1 | step 2 | step 3 | step 4 | step 5 | failures | trials/s |")
    print("|---|---|---|---|---|---|---|---|")
    print(row("sklearn k-NN (Python)", knn))
    print(row("lin5 (built in)", lin5))


if __name__ == "__main__":
    main()
