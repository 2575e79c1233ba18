"""The named learner API (``eyehand_api = 2``: ``eyehand.Query`` and ``eyehand.Patterns``),
``setup(config)``, ``minimal_joint_move`` from the config and ``size()``."""

import numpy as np
import pytest

import eyehand

#: A path of three poses: the move to the third changes θ3 by 0.05° only.
PATH = np.array(
    [
        [10.0, -20.0, 5.0, 0.0, 40.0, 100.0],
        [0.0, 0.0, 0.0, 0.0, 45.0, 98.0],
        [1.0, 2.0, 3.0, 0.0, 45.0, 98.05],
    ]
)


def query_order(query):
    """A named query as the old API's array (cx, cy, cz, θ2, θ3)."""
    return [query.cx, query.cy, query.cz, query.theta2_deg, query.theta3_deg]


class NamedIk:
    """The analytic inverse kinematics behind the named API; it keeps what it is given."""

    name = "namedik"
    eyehand_api = 2

    def __init__(self):
        self.ik = eyehand.Learner("ik")
        self.queries, self.patterns = [], []

    def propose(self, query):
        self.queries.append(query)
        return self.ik.propose(query_order(query))

    def learn(self, patterns):
        self.patterns.append(patterns)


def test_named_inputs_come_in_the_boundaries_order():
    assert eyehand.INPUTS == ["theta2_deg", "theta3_deg", "cx", "cy", "cz"]
    assert eyehand.INPUT_UNITS[:4] == ["°", "°", "px", "px"]
    assert eyehand.TARGETS == ["dtheta1_deg", "dtheta2_deg", "dtheta3_deg"]
    query = eyehand.Query(theta2_deg=40.0, theta3_deg=100.0, cx=10.0, cy=-20.0, cz=5.0)
    assert np.array_equal(query.inputs, [40.0, 100.0, 10.0, -20.0, 5.0])
    assert (query.cx, query.theta3_deg) == (10.0, 100.0)
    patterns = eyehand.Patterns(PATH, minimal_joint_move=0.1)
    assert len(patterns) == 2 and patterns.inputs.shape == (2, 5)
    assert np.allclose(patterns.inputs[0], [40.0, 100.0, 10.0, -20.0, 5.0])
    assert np.allclose(patterns.targets[0], [0.0, 5.0, -2.0])
    assert np.array_equal(patterns.path, PATH)
    old_inputs, old_targets = eyehand.patterns(PATH, minimal_joint_move=0.1)
    assert np.allclose(patterns.inputs, old_inputs[:, [3, 4, 0, 1, 2]])
    assert np.allclose(patterns.targets, old_targets)


def test_input_bounds_follow_the_inputs():
    config = {f"boundary_{i}_{end}": float(10 * i + (end == "high")) for i in range(5) for end in ("low", "high")}
    low, high = eyehand.input_bounds(config)
    assert np.array_equal(low, [0.0, 10.0, 20.0, 30.0, 40.0])
    assert np.array_equal(high, [1.0, 11.0, 21.0, 31.0, 41.0])


def test_a_named_learner_gets_queries_and_patterns_by_name(repo, tmp_path):
    learner = NamedIk()
    result = eyehand.run(learner, trials=20, config=repo / "configs" / "ik.conf", data=tmp_path)
    assert np.all(result["distances_mm"][0] <= 0.5), "the named fields are the right ones"
    assert all(isinstance(q, eyehand.Query) for q in learner.queries)
    assert len(learner.patterns) == 8 + 20
    trial = learner.patterns[-1]
    assert isinstance(trial, eyehand.Patterns) and len(trial) > 0
    starts = trial.path[:, [4, 5, 0, 1, 2]]
    assert np.allclose(trial.inputs[0, :2], starts[0, :2]), "θ2, θ3 of the pose the move starts from"
    old_inputs, _ = eyehand.patterns(trial.path, minimal_joint_move=0.01)
    assert np.allclose(trial.inputs, old_inputs[:, [3, 4, 0, 1, 2]])


def test_a_testbed_hands_a_named_learner_patterns():
    testbed, learner = eyehand.Testbed(seed=3), NamedIk()
    testbed.prelearn(learner)
    query = testbed.reset()
    while not testbed.done:
        testbed.step(learner.propose(eyehand.Query(*query[[3, 4, 0, 1, 2]])))
        query = testbed.observation
    testbed.learn(learner)
    assert len(learner.patterns) == 8 + 1 and all(isinstance(p, eyehand.Patterns) for p in learner.patterns)
    assert np.array_equal(learner.patterns[-1].path, testbed.path)

def test_the_old_api_is_kept_without_the_attribute(tmp_path):
    class Arrays:
        name = "arrays"

        def __init__(self):
            self.ik, self.given = eyehand.Learner("ik"), []

        def propose(self, query):
            self.given.append(query)
            return self.ik.propose(query)

        def learn(self, path):
            self.given.append(path)

    learner = Arrays()
    eyehand.run(learner, trials=3, data=tmp_path)
    assert all(isinstance(a, np.ndarray) for a in learner.given)
    assert {a.shape[-1] for a in learner.given} == {5, 6}


def test_an_unknown_api_is_a_value_error_before_the_run(tmp_path):
    learner = NamedIk()
    learner.eyehand_api = 3
    with pytest.raises(ValueError, match="eyehand_api is 1 .* or 2"):
        eyehand.run(learner, trials=3, data=tmp_path)
    assert not (tmp_path / "namedik").exists()


class Configured(NamedIk):
    """Keeps the config its ``setup`` gets and what it was called before."""

    name = "configured"

    def setup(self, config):
        self.config = dict(config)
        self.before_setup = len(self.queries) + len(self.patterns)


def test_setup_gets_the_run_s_resolved_config_typed_before_any_call(tmp_path):
    learner = Configured()
    eyehand.run(learner, trials=3, seed=7, data=tmp_path, minimal_joint_move=0.05, obstacle="60,0,-10,5,5,5")
    config = learner.config
    assert learner.before_setup == 0, "setup comes before pre-learning"
    assert set(eyehand.ENTRY_NAMES) <= set(config)
    assert config["seed"] == 7 and isinstance(config["trials"], int) and config["trials"] == 3
    assert config["minimal_joint_move"] == 0.05 and isinstance(config["robot_speed"], float)
    assert config["camera_offset"] == (0.0, 0.0, 0.0)
    assert config["method"] == "lin5" and config["sim"] == "kinematic"
    assert config["obstacle"] == [(60.0, 0.0, -10.0, 5.0, 5.0, 5.0)]
    low, high = eyehand.input_bounds(config)
    assert low[0] == config["boundary_0_low"] and high[4] == config["boundary_4_high"]


# Its one-trial run of a recording learner learns nothing, and says so.
@pytest.mark.filterwarnings("ignore::eyehand.NotLearnedWarning")
def test_setup_gets_the_boundaries_fitted_to_another_arm(repo, tmp_path):
    config = tmp_path / "ur_style.conf"
    # The reach space `eyehand reach` fits to the arm, given so that the test is quick.
    config.write_text(f"urdf {repo / 'tests' / 'data' / 'ur_style.urdf'}\nreach_space 31.8,64.2,2.0,37.9\n")
    learner = Configured()
    result = eyehand.run(learner, trials=1, config=config, data=tmp_path)
    info = (result["folder"] / "info").read_text().splitlines()
    fitted = [line for line in info if line.endswith("# fitted to the arm") and line.startswith("boundary_")]
    assert len(fitted) == 5  # boundaries 0 and 1 from the joints, 4 (cz) from the space
    for line in fitted:
        name, value = line.split()[:2]
        assert learner.config[name] == float(value), line
    assert (learner.config["boundary_0_low"], learner.config["boundary_0_high"]) != (-10.0, 80.0)


def test_a_setup_that_raises_stops_the_run_before_its_folder(tmp_path):
    class Broken(NamedIk):
        def setup(self, config):
            raise KeyError("no such setting")

    with pytest.raises(KeyError, match="no such setting"):
        eyehand.run(Broken(), trials=3, data=tmp_path)
    assert not (tmp_path / "namedik").exists()


def test_patterns_default_to_the_config_s_minimal_joint_move(tmp_path):
    config_file = tmp_path / "coarse.conf"
    config_file.write_text("minimal_joint_move 0.1\n")
    assert len(eyehand.Patterns(PATH)) == 3, "the declared default, 0.01°, keeps the 0.05° move"
    assert len(eyehand.patterns(PATH)[0]) == 3
    for config in ({"minimal_joint_move": 0.1}, config_file, str(config_file)):
        assert len(eyehand.Patterns(PATH, config=config)) == 2
        assert len(eyehand.patterns(PATH, config=config)[0]) == 2
    assert len(eyehand.patterns(PATH, minimal_joint_move=0.01, config={"minimal_joint_move": 0.1})[0]) == 3
    with pytest.raises(ValueError, match="dict of entries"):
        eyehand.patterns(PATH, config=3)


def test_a_named_learner_s_patterns_use_the_run_s_minimal_joint_move(tmp_path):
    learner = NamedIk()
    eyehand.run(learner, trials=10, data=tmp_path, minimal_joint_move=9.0)
    for patterns in learner.patterns:
        expected, _ = eyehand.patterns(patterns.path, minimal_joint_move=9.0)
        assert len(patterns) == len(expected)
    assert sum(len(p) for p in learner.patterns) < sum(
        len(eyehand.patterns(p.path)[0]) for p in learner.patterns
    ), "9° drops pairs the default keeps"


class Sized(NamedIk):
    """Reports the patterns it has learned as its size."""

    name = "sized"

    def __init__(self, answer=None):
        super().__init__()
        self.answer = answer

    def size(self):
        return self.answer if self.answer is not None else sum(len(p) for p in self.patterns)


def test_a_learner_s_size_goes_into_the_summary_and_the_report(tmp_path):
    learner = Sized()
    result = eyehand.run(learner, trials=12, data=tmp_path)
    size = learner.size()
    assert size > 0 and result["summary"]["nodes"] == size
    assert f"model: {size} nodes" in result["report"]
    last = (result["folder"] / "nodes").read_text().splitlines()[-1].split()
    assert last[:2] == ["12", str(size)]
    plain = eyehand.run(NamedIk(), trials=2, data=tmp_path)
    assert plain["summary"]["nodes"] == 0, "no size() is 0"


@pytest.mark.parametrize("answer", [-1, 2.5, "many"])
def test_a_size_that_is_no_count_stops_the_run(tmp_path, answer):
    with pytest.raises((ValueError, TypeError), match="size\\(\\) must be a count"):
        eyehand.run(Sized(answer), trials=5, data=tmp_path)


class Still:
    """A learner that answers zero moves: the arm never leaves its starts."""

    name = "still"

    def propose(self, query):
        return np.zeros(3)

    def learn(self, path):
        pass


def test_a_learner_that_never_moves_the_arm_is_reported(tmp_path):
    expected = "nothing was learned: no trial of 30 gave"
    with pytest.warns(eyehand.NotLearnedWarning, match=expected):
        result = eyehand.run(Still(), trials=30, seed=1, data=tmp_path)
    assert result["learned"] is False
    assert result["summary"]["learned"] is False
    assert result["summary"]["not_learned"]["kind"] == "no_pattern"
    assert "answered zero moves" in result["summary"]["not_learned"]["reason"]


def test_a_run_that_learns_says_so_without_a_warning(tmp_path, recwarn):
    result = eyehand.run(method="lin5", trials=30, seed=1, data=tmp_path)
    assert result["learned"] is True
    assert result["summary"]["not_learned"] is None
    assert not [w for w in recwarn if issubclass(w.category, eyehand.NotLearnedWarning)]
