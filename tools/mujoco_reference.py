#!/usr/bin/env python3
"""Reference dynamics of the OSCAR-6 from MuJoCo, for eyehand's dynamic simulator tests.

Loads urdf/oscar6.urdf (and the Panda of tests/data/panda) into MuJoCo (its own URDF reader, contacts off, joint damping,
friction loss and armature zero, gravity 9.81 m/s² along -z) and writes into tests/data/:

  mujoco_accelerations.csv   joint accelerations from rest at 50 fixed poses
  mujoco_swing_N.csv         passive swings from 3 start poses (servos off, no joint
                             limits), RK4 at 0.1 ms for 1 s, a row every 10 ms
  mujoco_stretched.csv       the arm with link 2 10 cm longer, its mass properties scaled
                             as a uniform rod (see docs/DYNAMIC.md): holding torques
                             (gravity) and accelerations from rest at the same 50 poses
  mujoco_moves.csv           servoed moves: each move's number, start and goal (rad)
  mujoco_move_N.csv          move N driven by eyehand's servo law (src/robot/dynamic/
                             servo_law.rs) at its default settings: every 5 ms tick the
                             set-point of the trapezoidal profile (90°/s, 180°/s² for the
                             joint with the farthest to go) with its speed and acceleration,
                             the servo's accelerations s = [a* + k(x* - x - dt v) + c(v* - v)]
                             / (1 + k dt²/2 + c dt) made torques by MuJoCo's own mass
                             matrix, MuJoCo's bias at the set-point's angles and speeds
                             (gravity, Coriolis and centrifugal torques, and the joints'
                             damping) fed forward, each within the URDF effort, held over
                             the tick (qfrc_applied) while MuJoCo integrates RK4 at 0.1 ms;
                             a row every tick
  mujoco_panda_moves.csv,    the same for the Franka Panda (tests/data/panda, its fingers
  mujoco_panda_move_N.csv    held shut)
  held_out/oscar6_V.urdf,    variants of the OSCAR-6 (masses x1.3, a rotated tensor with
  held_out/mujoco_swing_V.csv  a repeated moment, centres of mass off the axis, joint
                             damping, all of them) and a passive swing of each
  held_out/mujoco_move_damped.csv  the damped variant (2 N m s/rad, MuJoCo's own damping
                             on) servoed through the OSCAR-6's move 2 as above

Needs `pip install mujoco numpy`; run from the repository root:
    python3 tools/mujoco_reference.py
The tests read the files; they never run this script.
"""

import pathlib
import re

import mujoco
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT = ROOT / "tests" / "data"
SEED = 13
POSES = 50
SWING_STARTS = [
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.0, 0.6, 1.2, 0.0, 1.0, 0.0],
    [0.5, 0.3, 0.9, 0.0, 0.6, 0.0],
]
SWING_SECONDS = 1.0
SWING_DT = 1e-4
SWING_EVERY = 100  # steps between rows: 10 ms
STRETCH_LINK = "link_2"
STRETCH_JOINT = "joint_3"  # the joint at the link's far end
STRETCH_M = 0.10
TICK = 0.005  # eyehand's default dt
TICK_SUBSTEPS = 50  # MuJoCo steps of 0.1 ms per tick
STIFFNESS = 400_000.0  # motor_stiffness (1/s²)
DAMPING = 1265.0  # motor_damping (1/s)
SPEED = np.radians(90.0)  # robot_speed
ACCEL = np.radians(180.0)  # robot_accel
SETTLE_SECONDS = 0.5  # simulated after each move's profile
# Small, large, and onto joint 3's upper limit (2.967 rad), in degrees but the limit.
MOVES = [
    (np.radians([0, 30, 60, 0, 40, 0]), np.radians([2, 31, 58, 0, 41, 0])),
    (np.radians([-60, 10, 30, 0, 20, 0]), np.radians([70, 60, 110, 30, 80, -40])),
    (np.radians([20, 40, 100, 0, 30, 0]), np.array([*np.radians([25, 45]), 2.967, *np.radians([10, 60, 20])])),
]
# The Panda (tests/data/panda), fingers held shut; in degrees but joint 4's upper limit (0).
PANDA_MOVES = [
    (np.radians([0, 0, 0, -90, 0, 90, 45]), np.radians([2, 1, -1, -88, 1, 92, 44])),
    (np.radians([-40, -30, 20, -120, 10, 80, 0]), np.radians([50, 40, -30, -60, -40, 140, 60])),
    (np.radians([0, 20, 0, -60, 0, 100, 0]), np.array([0.0, np.radians(25), 0.0, 0.0, 0.0, np.radians(110), 0.0])),
]
MJCF_OPTIONS = (
    '<mujoco><compiler discardvisual="true" fusestatic="false" '
    'balanceinertia="false"/></mujoco>'
)


def with_mujoco_options(urdf: str) -> str:
    """The URDF with MuJoCo's compiler options inside <robot>."""
    return re.sub(r"(<robot[^>]*>)", r"\1" + MJCF_OPTIONS, urdf, count=1)


def stretched(urdf: str) -> str:
    """The URDF with STRETCH_LINK longer by STRETCH_M along its far joint's origin, its
    mass, centre of mass and inertia scaled as a uniform rod: mass by s = L'/L, every
    coordinate along the link by s, the second moments of mass by s·A·S·A."""
    joint = re.search(
        r'<joint name="%s".*?<origin xyz="([^"]+)"' % STRETCH_JOINT, urdf, re.S
    )
    far = np.array([float(v) for v in joint.group(1).split()])
    length = np.linalg.norm(far)
    d = far / length
    s = (length + STRETCH_M) / length
    urdf = urdf[: joint.start(1)] + fmt(far * s) + urdf[joint.end(1) :]

    link = re.search(r'<link name="%s">.*?</link>' % STRETCH_LINK, urdf, re.S)
    body = link.group(0)
    com = np.array(
        [float(v) for v in re.search(r'<inertial>\s*<origin xyz="([^"]+)"', body).group(1).split()]
    )
    mass = float(re.search(r'<mass value="([^"]+)"', body).group(1))
    names = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
    values = {n: float(re.search(r'%s="([^"]+)"' % n, body).group(1)) for n in names}
    tensor = np.array(
        [
            [values["ixx"], values["ixy"], values["ixz"]],
            [values["ixy"], values["iyy"], values["iyz"]],
            [values["ixz"], values["iyz"], values["izz"]],
        ]
    )
    stretch = np.eye(3) + (s - 1.0) * np.outer(d, d)
    moments = 0.5 * np.trace(tensor) * np.eye(3) - tensor
    moments = s * stretch @ moments @ stretch
    tensor = np.trace(moments) * np.eye(3) - moments
    new = re.sub(
        r'(<inertial>\s*<origin xyz=")[^"]+"', lambda m: m.group(1) + fmt(stretch @ com) + '"', body
    )
    new = re.sub(r'(<mass value=")[^"]+"', lambda m: m.group(1) + repr(float(mass * s)) + '"', new)
    index = {"ixx": (0, 0), "ixy": (0, 1), "ixz": (0, 2), "iyy": (1, 1), "iyz": (1, 2), "izz": (2, 2)}
    for n, (i, j) in index.items():
        new = re.sub(r'(%s=")[^"]+"' % n, lambda m, v=tensor[i, j]: m.group(1) + repr(float(v)) + '"', new)
    return urdf[: link.start()] + new + urdf[link.end() :]


def panda_urdf() -> str:
    """The Panda's URDF as eyehand reads it: its fingers (prismatic joints off the chain)
    held at 0, its meshes found from here."""
    path = ROOT / "tests" / "data" / "panda" / "panda.urdf"
    urdf = path.read_text().replace('type="prismatic"', 'type="fixed"')
    return urdf.replace('filename="./', 'filename="%s/' % path.parent)


def write_moves(prefix: str, arm: str, urdf: str, moves, joints: int) -> None:
    """The servoed `moves` of `urdf` into PREFIXmoves.csv and PREFIXmove_N.csv."""
    q_cols = ",".join("q%d" % i for i in range(1, joints + 1))
    write(
        "%smoves.csv" % prefix,
        "servoed moves of %s: n,start q1..q%d,goal q1..q%d (rad)" % (arm, joints, joints),
        [[n, *start, *goal] for n, (start, goal) in enumerate(moves, 1)],
    )
    for n, (start, goal) in enumerate(moves, 1):
        write(
            "%smove_%d.csv" % (prefix, n),
            "MuJoCo %s, %s, servoed move %d (eyehand's servo law, 5 ms ticks), "
            "RK4 %g s, no limits; t,%s,v1..v%d"
            % (mujoco.__version__, arm, n, TICK / TICK_SUBSTEPS, q_cols, joints),
            servoed_move(load(urdf, joints), efforts(urdf), start, goal),
        )


def scaled_masses(urdf: str, links, factor: float) -> str:
    """The mass and inertia tensor of each of `links` times `factor` (the whole arm
    scaled alike would move as before)."""
    names = "ixx|ixy|ixz|iyy|iyz|izz"
    for link in links:
        block = re.search(r'<link name="%s">.*?</link>' % link, urdf, re.S)
        body = re.sub(r'(<mass value=")([^"]+)"', lambda m: m.group(1) + repr(float(m.group(2)) * factor) + '"', block.group(0))
        body = re.sub(r'\b(%s)="([^"]+)"' % names, lambda m: '%s="%r"' % (m.group(1), float(m.group(2)) * factor), body)
        urdf = urdf[: block.start()] + body + urdf[block.end() :]
    return urdf


def with_inertial(urdf: str, link: str, com, tensor) -> str:
    """`link` with its centre of mass at `com` (m) and its inertia `tensor` (3x3, kg m²)."""
    block = re.search(r'<link name="%s">.*?</link>' % link, urdf, re.S)
    body = re.sub(r'(<inertial>\s*<origin xyz=")[^"]+"', lambda m: m.group(1) + fmt(com) + '"', block.group(0))
    index = {"ixx": (0, 0), "ixy": (0, 1), "ixz": (0, 2), "iyy": (1, 1), "iyz": (1, 2), "izz": (2, 2)}
    for n, (i, j) in index.items():
        body = re.sub(r'\b(%s=")[^"]+"' % n, lambda m, v=tensor[i][j]: m.group(1) + repr(float(v)) + '"', body)
    return urdf[: block.start()] + body + urdf[block.end() :]


def rotated_repeated(a: float, b: float, rpy) -> np.ndarray:
    """diag(a, a, b) turned by roll, pitch and yaw `rpy`: a tensor with a repeated
    moment whose axes are not the link's."""
    r, p, y = rpy
    rx = np.array([[1, 0, 0], [0, np.cos(r), -np.sin(r)], [0, np.sin(r), np.cos(r)]])
    ry = np.array([[np.cos(p), 0, np.sin(p)], [0, 1, 0], [-np.sin(p), 0, np.cos(p)]])
    rz = np.array([[np.cos(y), -np.sin(y), 0], [np.sin(y), np.cos(y), 0], [0, 0, 1]])
    turn = rz @ ry @ rx
    return turn @ np.diag([a, a, b]) @ turn.T


def with_damping(urdf: str, damping: float) -> str:
    """Every revolute joint with viscous `damping` (N m s/rad)."""
    return re.sub(
        r'(<joint name="[^"]+" type="revolute">)',
        lambda m: m.group(1) + '<dynamics damping="%r"/>' % damping,
        urdf,
    )


def held_out(urdf: str) -> dict:
    """Variants of the OSCAR-6 the other references never saw, by name."""
    heavy = scaled_masses(urdf, ["link_2", "link_3"], 1.3)
    rotated = with_inertial(urdf, "link_2", [0.30, 0.0, 0.0], rotated_repeated(0.3, 0.05, (0.3, 0.5, 0.7)))
    off_axis = with_inertial(
        with_inertial(urdf, "link_2", [0.30, 0.02, 0.04], [[0.0544, 0, 0], [0, 0.5372, 0], [0, 0, 0.5372]]),
        "link_3", [0.275, -0.03, 0.02], [[0.0144, 0, 0], [0, 0.2089, 0], [0, 0, 0.2089]],
    )
    damped = with_damping(urdf, 2.0)
    everything = with_damping(
        with_inertial(scaled_masses(off_axis, ["link_2", "link_3"], 1.3), "link_1", [0.01, -0.02, 0.275],
                      rotated_repeated(0.9, 0.16, (0.2, -0.4, 0.9))),
        2.0,
    )
    return {"heavy": heavy, "rotated": rotated, "off_axis": off_axis, "damped": damped, "everything": everything}


def fmt(v) -> str:
    return " ".join(repr(float(x)) for x in v)


def load(urdf: str, joints: int = 6, damping: bool = False) -> mujoco.MjModel:
    """The arm of `urdf` in MuJoCo: contacts and limits off, friction loss and armature
    zero, the joints' damping the URDF's with `damping` (else zero)."""
    model = mujoco.MjModel.from_xml_string(with_mujoco_options(urdf))
    if not damping:
        model.dof_damping[:] = 0.0
    model.dof_frictionloss[:] = 0.0
    model.dof_armature[:] = 0.0
    model.jnt_limited[:] = 0
    model.opt.gravity[:] = [0.0, 0.0, -9.81]
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    assert model.nq == joints, "%d revolute joints" % joints
    return model


def poses(model: mujoco.MjModel) -> np.ndarray:
    """POSES poses drawn uniformly inside the joint limits (seeded)."""
    rng = np.random.default_rng(SEED)
    low, high = model.jnt_range[:, 0], model.jnt_range[:, 1]
    return rng.uniform(low, high, size=(POSES, 6))


def at_rest(model: mujoco.MjModel, q: np.ndarray):
    """Accelerations from rest and the holding (gravity) torques at q."""
    data = mujoco.MjData(model)
    data.qpos[:] = q
    data.qvel[:] = 0.0
    mujoco.mj_forward(model, data)
    return data.qacc.copy(), data.qfrc_bias.copy()


def swing(model: mujoco.MjModel, start) -> list:
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    model.opt.timestep = SWING_DT
    data = mujoco.MjData(model)
    data.qpos[:] = start
    mujoco.mj_forward(model, data)
    rows = [[0.0, *data.qpos, *data.qvel]]
    for k in range(1, int(round(SWING_SECONDS / SWING_DT)) + 1):
        mujoco.mj_step(model, data)
        if k % SWING_EVERY == 0:
            rows.append([k * SWING_DT, *data.qpos, *data.qvel])
    return rows


def efforts(urdf: str) -> np.ndarray:
    """Each revolute joint's URDF effort (N m), in the file's order."""
    joints = re.findall(r'<joint name="[^"]+" type="revolute">.*?</joint>', urdf, re.S)
    return np.array([float(re.search(r'effort="([^"]+)"', j).group(1)) for j in joints])


def fraction(distance: float, t: float) -> float:
    """The share of a trapezoidal move of `distance` (rad) done at time t."""
    full_ramp = SPEED / ACCEL
    if ACCEL * full_ramp**2 >= distance:
        ramp, cruise = np.sqrt(distance / ACCEL), 0.0
    else:
        ramp, cruise = full_ramp, (distance - ACCEL * full_ramp**2) / SPEED
    duration = 2 * ramp + cruise
    if distance == 0.0 or t >= duration:
        return 1.0
    t = max(t, 0.0)
    top = ACCEL * ramp
    if t < ramp:
        covered = 0.5 * ACCEL * t * t
    elif t < ramp + cruise:
        covered = 0.5 * top * ramp + top * (t - ramp)
    else:
        covered = distance - 0.5 * ACCEL * (duration - t) ** 2
    return min(max(covered / distance, 0.0), 1.0)


def servoed_move(model: mujoco.MjModel, effort: np.ndarray, start, goal) -> list:
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    model.opt.timestep = TICK / TICK_SUBSTEPS
    data, probe = mujoco.MjData(model), mujoco.MjData(model)
    data.qpos[:] = start
    mujoco.mj_forward(model, data)
    distance = np.max(np.abs(goal - start))
    at = lambda k: start + (goal - start) * fraction(distance, k * TICK)
    duration = next(k for k in range(10**6) if fraction(distance, k * TICK) == 1.0) * TICK
    rows = [[0.0, *data.qpos, *data.qvel]]
    mass = np.zeros((model.nv, model.nv))
    for k in range(int(round((duration + SETTLE_SECONDS) / TICK))):
        x, v = data.qpos.copy(), data.qvel.copy()
        target = at(k + 1)
        speed = (at(k + 2) - at(k)) / (2 * TICK)
        accel = (at(k + 2) - 2 * at(k + 1) + at(k)) / TICK**2
        s = (accel + STIFFNESS * (target - x - TICK * v) + DAMPING * (speed - v)) / (
            1 + 0.5 * STIFFNESS * TICK**2 + DAMPING * TICK
        )
        mujoco.mj_forward(model, data)
        mujoco.mj_fullM(model, data, mass)
        probe.qpos[:] = target
        probe.qvel[:] = speed
        mujoco.mj_forward(model, probe)
        held = np.clip(probe.qfrc_bias + model.dof_damping * speed, -effort, effort)
        left = effort - np.abs(held)
        data.qfrc_applied[:] = held + np.clip(mass @ s, -left, left)
        for _ in range(TICK_SUBSTEPS):
            mujoco.mj_step(model, data)
        rows.append([(k + 1) * TICK, *data.qpos, *data.qvel])
    return rows


def write(name: str, header: str, rows) -> None:
    path = OUT / name
    with open(path, "w") as out:
        out.write("# " + header + "\n")
        for row in rows:
            out.write(",".join("%.17g" % v for v in row) + "\n")
    print("wrote", path.relative_to(ROOT))


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    urdf = (ROOT / "urdf" / "oscar6.urdf").read_text()
    model = load(urdf)
    qs = poses(model)
    q_cols = ",".join("q%d" % i for i in range(1, 7))
    write(
        "mujoco_accelerations.csv",
        "MuJoCo %s, oscar6.urdf, accelerations from rest (rad/s^2); %s,a1..a6"
        % (mujoco.__version__, q_cols),
        [[*q, *at_rest(model, q)[0]] for q in qs],
    )
    for n, start in enumerate(SWING_STARTS, 1):
        write(
            "mujoco_swing_%d.csv" % n,
            "MuJoCo %s, oscar6.urdf, passive swing, RK4 %g s, no limits; t,%s,v1..v6"
            % (mujoco.__version__, SWING_DT, q_cols),
            swing(load(urdf), start),
        )
    long_model = load(stretched(urdf))
    rows = []
    for q in qs:
        acc, torque = at_rest(long_model, q)
        rows.append([*q, *torque, *acc])
    write(
        "mujoco_stretched.csv",
        "MuJoCo %s, oscar6.urdf with %s %g m longer (uniform rod); %s,tau1..tau6 (N m),a1..a6"
        % (mujoco.__version__, STRETCH_LINK, STRETCH_M, q_cols),
        rows,
    )
    write_moves("mujoco_", "oscar6.urdf", urdf, MOVES, 6)
    (OUT / "held_out").mkdir(exist_ok=True)
    for name, variant in held_out(urdf).items():
        (OUT / "held_out" / ("oscar6_%s.urdf" % name)).write_text(variant)
        write(
            "held_out/mujoco_swing_%s.csv" % name,
            "MuJoCo %s, held_out/oscar6_%s.urdf, passive swing from swing 3's start, RK4 %g s, "
            "no limits, the URDF's damping; t,%s,v1..v6" % (mujoco.__version__, name, SWING_DT, q_cols),
            swing(load(variant, damping=True), SWING_STARTS[2]),
        )
    write_moves("mujoco_panda_", "panda.urdf", panda_urdf(), PANDA_MOVES, 7)
    damped = held_out(urdf)["damped"]
    write(
        "held_out/mujoco_move_damped.csv",
        "MuJoCo %s, held_out/oscar6_damped.urdf, servoed move 2 (eyehand's servo law, 5 ms "
        "ticks), RK4 %g s, no limits, the URDF's damping; t,%s,v1..v6"
        % (mujoco.__version__, TICK / TICK_SUBSTEPS, q_cols),
        servoed_move(load(damped, damping=True), efforts(damped), *MOVES[1]),
    )


if __name__ == "__main__":
    main()
