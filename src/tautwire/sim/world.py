"""The simulated world: MuJoCo model and data behind one object.

:class:`SimWorld` owns the only :class:`mujoco.MjData`. It steps the physics,
drives the grippers kinematically (each physics step it writes the commanded
pose and twist into the grippers' free joints, so friction sees their real
velocity), grasps and releases the cable, measures the wrench each gripper
transmits, and guards against divergence. Robots
(:class:`tautwire.sim.sim_robot.SimRobot`) and the ground truth
(:class:`tautwire.sim.ground_truth.GroundTruth`) are views on it.
"""

from __future__ import annotations

import logging
import math
import re
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from tautwire.errors import SimulationError
from tautwire.model.quaternion import to_rotation
from tautwire.robot.arm import ARMS, Arm
from tautwire.robot.command import GripperCommand
from tautwire.sim.diverged import SimulationDiverged
from tautwire.sim.gripper_state import GripperState, integrate_pose
from tautwire.sim.mjcf import PAD_HALF, SceneModel, hold_equality, scene_model, vertex_body
from tautwire.sim.options import SimOptions, control_substeps
from tautwire.sim.spec import CableSpec, WorldSpec

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]

_BAD_WARNINGS = (
    mujoco.mjtWarning.mjWARN_INERTIA,
    mujoco.mjtWarning.mjWARN_BADQACC,
    mujoco.mjtWarning.mjWARN_BADQPOS,
    mujoco.mjtWarning.mjWARN_BADQVEL,
)


_LOG = logging.getLogger("tautwire.sim")


#: MuJoCo 4 also warns mjWARN_INERTIA when the flex's M+K solve stops at a
#: relative residual such as 1e-8 (stiff, long cables): converged for this
#: purpose. MuJoCo prints a warning type only the first time in a world; when
#: that first report names a converged residual, the world's inertia warnings
#: are not counted as divergence (a failed solve, with a larger residual or
#: none given, is). A real blow-up still shows as NaN, a bad qacc or a speed
#: beyond ``max_speed``. The verdict is per process: one world steps at a time.
CONVERGED_RESIDUAL = 1e-6
_RESIDUAL = re.compile(r"relative residual of ([0-9.eE+-]+)")
_inertia_converged: bool | None = None


def _log_warning(message: str) -> None:
    """MuJoCo's runtime warnings go to the log (stderr), never to stdout."""
    global _inertia_converged
    match = _RESIDUAL.search(message)
    if match is not None and _inertia_converged is None:
        try:
            _inertia_converged = float(match.group(1)) <= CONVERGED_RESIDUAL
        except ValueError:
            _inertia_converged = False
    _LOG.warning("MuJoCo: %s", message.strip())


def compile_model(xml: str) -> mujoco.MjModel:
    """Compile MJCF text, keeping MuJoCo's compile warnings off stdout.

    The one expected warning (a flex whose edges carry no passive force: the
    segment springs are tendons here) would otherwise be printed on stdout,
    where ``--json`` output goes; any other warning is raised. Afterwards
    MuJoCo's runtime warnings go to the ``tautwire.sim`` logger (unless the
    application installed its own handler); the world also counts them and
    raises :class:`SimulationDiverged` on an instability.

    Raises:
        SimulationError: if MuJoCo refuses the model or warns.
    """
    messages: list[str] = []
    previous = mujoco.get_mju_user_warning()
    mujoco.set_mju_user_warning(messages.append)
    try:
        model = mujoco.MjModel.from_xml_string(xml)
    except ValueError as exc:
        raise SimulationError(f"MuJoCo could not compile the scene: {exc}") from exc
    finally:
        mujoco.set_mju_user_warning(previous if previous is not None else _log_warning)
    unexpected = [msg for msg in messages if "is not rigid and has no equality" not in msg]
    if unexpected:
        raise SimulationError(f"MuJoCo warned while compiling the scene: {unexpected[0]}")
    return model


@dataclass(frozen=True)
class CableIndex:
    """Where a cable lives in the compiled model.

    Attributes:
        spec: The cable.
        body_ids: Body id of each vertex.  # (N + 1,)
        dof_ids: Three dof ids per free vertex, -1 for a fixed one.  # (N + 1, 3)
        tendon_ids: Spatial tendon id of each segment.  # (N,)
        flex_id: Flex id.
        hold_ids: Per arm, the connect equality id of each vertex (-1 for a
            fixed one).  # (N + 1,) each
    """

    spec: CableSpec
    body_ids: IntArray
    dof_ids: IntArray
    tendon_ids: IntArray
    flex_id: int
    hold_ids: dict[Arm, IntArray]


class SimWorld:
    """A MuJoCo world built from a :class:`WorldSpec`.

    Building it compiles the scene, grasps the cable where the spec says and
    lets everything settle (not part of the run's time).

    Args:
        spec: The world description.
        options: Physics settings (defaults: :class:`SimOptions`).

    Raises:
        SimulationError: if the scene cannot be built (wave-speed guard,
            over-stretched route, MuJoCo compile error) or diverges while
            settling.
    """

    def __init__(self, spec: WorldSpec, options: SimOptions | None = None) -> None:
        self._spec = spec
        self._options = options or SimOptions()
        opt = self._options
        self._substeps = control_substeps(spec.control_period, opt.timestep)
        self._scene: SceneModel = scene_model(spec, opt)
        self._model = compile_model(self._scene.xml)
        self._data = mujoco.MjData(self._model)
        m = self._model
        self._cables: dict[str, CableIndex] = {}
        for cable in spec.cables:
            self._cables[cable.name] = self._index_cable(cable)
        dofs = [c.dof_ids[c.dof_ids >= 0] for c in self._cables.values()]
        self._cable_dofs: IntArray = (
            np.concatenate(dofs).astype(np.int64) if dofs else np.zeros(0, np.int64)
        )
        self._cable_dof_mass = m.dof_M0[self._cable_dofs].copy() if len(dofs) else np.zeros(0)
        # the cable dofs as a slice where they are one run (the usual case): a view, no gather
        self._cable_sel: slice | IntArray = self._cable_dofs
        if self._cable_dofs.size and np.all(np.diff(self._cable_dofs) == 1):
            first = int(self._cable_dofs[0])
            self._cable_sel = slice(first, first + int(self._cable_dofs.size))
        self._gripper_qpos: dict[Arm, int] = {}
        self._gripper_dof: dict[Arm, int] = {}
        self._finger_qpos: dict[Arm, tuple[int, int]] = {}
        self._finger_dof: dict[Arm, tuple[int, int]] = {}
        self._finger_act: dict[Arm, tuple[int, int]] = {}
        self._grippers: dict[Arm, GripperState] = {}
        self._gripper_body: dict[Arm, int] = {}
        self._gripper_bodies: dict[Arm, IntArray] = {}
        for arm in ARMS:
            jid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"{arm}_free")
            self._gripper_qpos[arm] = int(m.jnt_qposadr[jid])
            self._gripper_dof[arm] = int(m.jnt_dofadr[jid])
            self._gripper_bodies[arm] = np.array(
                [
                    mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, f"{arm}_{part}")
                    for part in ("gripper", "finger_a", "finger_b")
                ],
                dtype=np.int64,
            )
            self._gripper_body[arm] = mujoco.mj_name2id(
                m, mujoco.mjtObj.mjOBJ_BODY, f"{arm}_gripper"
            )
            fa = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"{arm}_finger_a")
            fb = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"{arm}_finger_b")
            self._finger_qpos[arm] = (int(m.jnt_qposadr[fa]), int(m.jnt_qposadr[fb]))
            self._finger_dof[arm] = (int(m.jnt_dofadr[fa]), int(m.jnt_dofadr[fb]))
            self._finger_act[arm] = (
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_ACTUATOR, f"{arm}_finger_a"),
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_ACTUATOR, f"{arm}_finger_b"),
            )
            g = spec.gripper(arm)
            self._grippers[arm] = GripperState(
                g.position.copy(), g.orientation.copy(), np.zeros(3), np.zeros(3)
            )
        # views on MuJoCo's arrays for the per-period path (MjData never reallocates them)
        d = self._data
        self._qpos: FloatArray = d.qpos
        self._qvel: FloatArray = d.qvel
        self._qfrc_applied: FloatArray = d.qfrc_applied
        self._dt = float(m.opt.timestep)
        self._quat_buffer = np.empty(4)
        self._drive = tuple(
            (
                self._grippers[arm],
                d.qpos[self._gripper_qpos[arm] : self._gripper_qpos[arm] + 3],
                d.qpos[self._gripper_qpos[arm] + 3 : self._gripper_qpos[arm] + 7],
                d.qvel[self._gripper_dof[arm] : self._gripper_dof[arm] + 3],
                d.qvel[self._gripper_dof[arm] + 3 : self._gripper_dof[arm] + 6],
                np.array(self._finger_qpos[arm], dtype=np.int64),
                np.array(self._finger_dof[arm], dtype=np.int64),
            )
            for arm in ARMS
        )
        self._wrench: dict[Arm, tuple[FloatArray, FloatArray]] = {
            arm: (np.zeros(3), np.zeros(3)) for arm in ARMS
        }
        # the constraint force on each gripper's free joint: what its wrist transmits
        # (tautwire.sim.transmitted_wrench.free_joint_wrench, read in place), into
        # the world's own wrench arrays, rewritten every control period
        self._sensed = tuple(
            (
                self._grippers[arm],
                d.qfrc_constraint[self._gripper_dof[arm] : self._gripper_dof[arm] + 3],
                d.qfrc_constraint[self._gripper_dof[arm] + 3 : self._gripper_dof[arm] + 6],
                *self._wrench[arm],
            )
            for arm in ARMS
        )
        self._torque_sum = tuple(np.zeros(3) for _ in ARMS)
        # both free joints' constraint forces in one slice, summed over a period
        lo = min(self._gripper_dof.values())
        hi = max(self._gripper_dof.values()) + 6
        self._gripper_constraint: FloatArray = d.qfrc_constraint[lo:hi]
        self._constraint_sum = np.zeros(hi - lo)
        self._sensed_offset = tuple(self._gripper_dof[arm] - lo for arm in ARMS)
        self._max_force = 0.0
        self._warnings = 0
        global _inertia_converged
        _inertia_converged = None  # this world's first inertia report decides
        self._t0 = 0.0
        self._damping_time = opt.cable_damping_time
        self._damping = self._damping_force_per_velocity()
        # MuJoCo's warning counters, live views read after every control period
        self._warning_stats = tuple(
            (w == mujoco.mjtWarning.mjWARN_INERTIA, self._data.warning[int(w)])
            for w in _BAD_WARNINGS
        )
        # open every gripper, then grasp where the spec says
        for arm in ARMS:
            self._set_fingers(arm, "open", 0.0)  # nothing is held yet
        for cable in spec.cables:
            disc = self._scene.discretizations[cable.name]
            for h in cable.holds:
                self._grasp(h.arm, cable.name, disc.vertex_at(h.at))
                self._set_fingers(h.arm, "hold", opt.hold_grip_force)
        for arm in ARMS:
            held = self._grippers[arm].held
            q = (
                self._cables[held[0]].spec.radius + opt.hold_clearance
                if held
                else 0.5 * opt.max_opening
            )
            for adr in self._finger_qpos[arm]:
                self._data.qpos[adr] = q
        self._write_grippers()
        mujoco.mj_forward(m, self._data)
        self._settle()
        self._t0 = float(self._data.time)
        self._max_force = 0.0

    # ------------------------------------------------------------------ setup
    def _index_cable(self, cable: CableSpec) -> CableIndex:
        m = self._model
        disc = self._scene.discretizations[cable.name]
        n = disc.segments
        body_ids = np.array(
            [
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, vertex_body(cable.name, i))
                for i in range(n + 1)
            ],
            dtype=np.int64,
        )
        dof_ids = np.full((n + 1, 3), -1, dtype=np.int64)
        for i, b in enumerate(body_ids):
            if m.body_dofnum[b] == 3:
                dof_ids[i] = m.body_dofadr[b] + np.arange(3)
        tendon_ids = np.array(
            [
                mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_TENDON, f"{cable.name}_t{i}")
                for i in range(n)
            ],
            dtype=np.int64,
        )
        flex_id = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_FLEX, cable.name)
        hold_ids: dict[Arm, IntArray] = {}
        for arm in ARMS:
            hold_ids[arm] = np.array(
                [
                    mujoco.mj_name2id(
                        m, mujoco.mjtObj.mjOBJ_EQUALITY, hold_equality(arm, cable.name, i)
                    )
                    for i in range(n + 1)
                ],
                dtype=np.int64,
            )
        return CableIndex(cable, body_ids, dof_ids, tendon_ids, flex_id, hold_ids)

    def _settle(self) -> None:
        opt = self._options
        if opt.settle_time <= 0.0:
            return
        self._damping_time = opt.settle_damping_time
        self._damping = self._damping_force_per_velocity()
        steps = int(np.ceil(opt.settle_time / opt.timestep))
        min_steps = int(np.ceil(0.1 / opt.timestep))
        try:
            for k in range(steps):
                self._physics_step()
                if k >= min_steps and k % 10 == 0:
                    v = self._data.qvel[self._cable_dofs]
                    if v.size == 0 or float(np.max(np.abs(v))) < opt.settle_speed:
                        break
        finally:
            self._damping_time = opt.cable_damping_time
            self._damping = self._damping_force_per_velocity()
            if not self._damping.size:  # no damping left over from settling
                self._data.qfrc_applied[self._cable_sel] = 0.0

    def _damping_force_per_velocity(self) -> FloatArray:
        """-m_i / tau per cable dof [N s/m]: the light mass-proportional damping."""
        if self._damping_time <= 0.0:
            return np.zeros(0)
        damping: FloatArray = -self._cable_dof_mass / self._damping_time
        return damping

    # --------------------------------------------------------------- queries
    @property
    def spec(self) -> WorldSpec:
        """The world description."""
        return self._spec

    @property
    def options(self) -> SimOptions:
        """The physics settings."""
        return self._options

    @property
    def time(self) -> float:
        """Time [s] since the run started (after settling)."""
        return float(self._data.time) - self._t0

    @property
    def timestep(self) -> float:
        """Physics step dt [s]."""
        return float(self._model.opt.timestep)

    @property
    def control_period(self) -> float:
        """Period [s] of one robot command."""
        return self._spec.control_period

    @property
    def substeps(self) -> int:
        """Physics steps per control period."""
        return self._substeps

    @property
    def max_force(self) -> float:
        """Largest force [N] either gripper transmitted since the last reset.

        Of the noise-free period means (:meth:`wrench`), as a robot's force
        monitor reads them; a runner ends a step with cause "force_limit"
        when it exceeds the scenario's limit.
        """
        return self._max_force

    def reset_max_force(self) -> None:
        """Start a new window for :attr:`max_force` (e.g. at each task step)."""
        self._max_force = 0.0

    @property
    def scene(self) -> SceneModel:
        """The generated scene (MJCF text, discretisations, clip designs)."""
        return self._scene

    @property
    def model(self) -> mujoco.MjModel:
        """The compiled MuJoCo model (for viewers and renderers; do not change its physics)."""
        return self._model

    @property
    def data(self) -> mujoco.MjData:
        """The world's only MuJoCo data (for viewers and renderers; step it through this object).

        Writing to it bypasses the grippers' kinematic drive and the divergence
        guard: read it, do not change it.
        """
        return self._data

    def gripper_pose(self, arm: Arm) -> tuple[FloatArray, FloatArray]:
        """Tool centre point [m] and orientation [w, x, y, z] of ``arm``'s gripper."""
        g = self._grippers[arm]
        return g.position.copy(), g.orientation.copy()

    def gripper_opening(self, arm: Arm) -> float:
        """Distance [m] between the finger pads of ``arm``'s gripper."""
        a, b = self._finger_qpos[arm]
        return float(self._qpos[a] + self._qpos[b])

    def gripper_grip_force(self, arm: Arm) -> float:
        """Force [N] with which ``arm``'s fingers squeeze (0 when open)."""
        return self._grippers[arm].grip_force

    def gripper_mode(self, arm: Arm) -> str:
        """Current finger mode of ``arm``."""
        return self._grippers[arm].mode

    def held(self, arm: Arm) -> tuple[str, int] | None:
        """(cable, vertex) that ``arm`` holds rigidly, or None."""
        return self._grippers[arm].held

    def wrench(self, arm: Arm, copy: bool = True) -> tuple[FloatArray, FloatArray]:
        """Noise-free wrench on ``arm``'s gripper, the mean over the last control period.

        The mean of the physics steps' constraint wrenches over the period
        (one step when :meth:`step` was given ``n=1``): what a wrist sensor
        filtered at the control rate reads.

        Args:
            arm: The gripper.
            copy: False returns the world's own arrays, rewritten in place
                every control period, which a reader must neither keep nor
                change (the sensor model, which only adds noise to them).

        Returns:
            Force [N] that the cable and the gripper's contacts exert on the
            gripper, world frame, and torque [N m] about the tool centre
            point, world frame.
        """
        f, t = self._wrench[arm]
        return (f.copy(), t.copy()) if copy else (f, t)

    # ------------------------------------------------------------- commands
    def set_gripper(self, arm: Arm, command: GripperCommand) -> None:
        """Apply a finger command: hold (grasp), open (release) or grip_force (slide).

        A command that repeats the fingers' current state changes nothing (the
        usual case, once per control period) and returns at once.
        """
        g = self._grippers[arm]
        mode = command.mode
        if mode == "hold":
            force = self._options.hold_grip_force
        else:
            force = command.grip_force if mode == "grip_force" else 0.0
        if mode == g.mode and g.grip_force == force and (mode == "hold" or g.held is None):
            return
        if command.mode == "open":
            self._release(arm)
            self._set_fingers(arm, "open", 0.0)
        elif command.mode == "grip_force":
            self._release(arm)
            self._set_fingers(arm, "grip_force", command.grip_force)
        else:
            if g.mode != "hold" and g.held is None:
                target = self._nearest_vertex(arm)
                if target is not None:
                    self._grasp(arm, *target)
            self._set_fingers(arm, "hold", self._options.hold_grip_force)

    def set_twist(self, twist: FloatArray) -> None:
        """Set the grippers' world-frame twist [v_l, w_l, v_r, w_r] in [m/s, rad/s], shape (12,)."""
        tw = np.array(twist, dtype=float)  # the world's own copy, never changed in place
        v = tw.tolist()
        for k, arm in enumerate(ARMS):
            g = self._grippers[arm]
            i = 6 * k
            g.linear = tw[i : i + 3]
            g.angular = tw[i + 3 : i + 6]
            g.moving = v[i] != 0.0 or v[i + 1] != 0.0 or v[i + 2] != 0.0
            g.turning = v[i + 3] != 0.0 or v[i + 4] != 0.0 or v[i + 5] != 0.0

    def step(self, n: int | None = None) -> None:
        """Advance the physics by ``n`` steps (default: one control period).

        Raises:
            SimulationDiverged: on NaN/inf or a velocity blow-up.
        """
        self._physics_step(self._substeps if n is None else n)

    # ------------------------------------------------------------- internals
    def _set_fingers(self, arm: Arm, mode: str, force: float) -> None:
        g = self._grippers[arm]
        g.mode = mode  # type: ignore[assignment]
        ctrl = {"open": self._options.open_force, "hold": 0.0}.get(mode, -force)
        g.grip_force = 0.0 if mode == "open" else force
        for a in self._finger_act[arm]:
            self._data.ctrl[a] = ctrl

    def _grasp(self, arm: Arm, cable: str, vertex: int) -> None:
        idx = self._cables[cable]
        eq = int(idx.hold_ids[arm][vertex])
        if eq < 0:
            return
        g = self._grippers[arm]
        p_vertex = self._data.xpos[idx.body_ids[vertex]] if self._data.time > 0 else None
        if p_vertex is None:
            anchor = np.zeros(3)  # the vertex was built at the tool centre point
        else:
            anchor = to_rotation(g.orientation).inv().apply(p_vertex - g.position)
            # closing fingers centre the cable between their pads (tool y), and
            # the pads' lips keep it within their height (tool z): a vertex held
            # where it was, beside the centre line, sat inside a pad and the weld
            # and the pad's contact pushed 250 N against each other, which put
            # the wrench's line of action 15 mm beside the cable (random board
            # 1652323633, after E's regrip)
            anchor[1] = 0.0
            reach = max(PAD_HALF[2] - idx.spec.radius, 0.0)
            anchor[2] = float(np.clip(anchor[2], -reach, reach))
        self._model.eq_data[eq, 0:3] = anchor
        self._model.eq_data[eq, 3:6] = 0.0
        self._data.eq_active[eq] = 1
        g.held = (cable, vertex)

    def _release(self, arm: Arm) -> None:
        g = self._grippers[arm]
        if g.held is not None:
            cable, vertex = g.held
            eq = int(self._cables[cable].hold_ids[arm][vertex])
            self._data.eq_active[eq] = 0
            g.held = None

    def _nearest_vertex(self, arm: Arm) -> tuple[str, int] | None:
        g = self._grippers[arm]
        best: tuple[str, int] | None = None
        best_d = self._options.grasp_distance
        for name, idx in self._cables.items():
            pts = self._data.xpos[idx.body_ids]
            d = np.linalg.norm(pts - g.position, axis=1)
            d[idx.hold_ids[arm] < 0] = np.inf
            i = int(np.argmin(d))
            if d[i] <= best_d:
                best, best_d = (name, i), float(d[i])
        return best

    def _write_grippers(self) -> None:
        inverse = self._quat_buffer
        for g, position, orientation, linear, angular, finger_qpos, finger_dof in self._drive:
            position[:] = g.position
            orientation[:] = g.orientation
            linear[:] = g.linear
            # free-joint angular velocity is in the body frame
            mujoco.mju_negQuat(inverse, g.orientation)
            mujoco.mju_rotVecQuat(angular, g.angular, inverse)
            if g.mode == "hold":  # fingers closed around the held cable, not squeezing
                gap = 0.0
                if g.held is not None:
                    gap = self._cables[g.held[0]].spec.radius + self._options.hold_clearance
                self._qpos[finger_qpos] = gap
                self._qvel[finger_dof] = 0.0

    def _physics_step(self, n: int = 1) -> None:
        """Advance ``n`` physics steps with the grippers' twist held constant.

        The grippers' pose and twist are written once; with their large
        armature and gravity compensation the free joints then move at that
        constant twist on their own (the constraint forces change a gripper's
        velocity by about 1e-7 m/s per N and step), and the pose is rewritten
        exactly at the next call. This runs once per control period: it reads
        and writes MuJoCo's arrays through views made once, when the world
        was built.
        """
        self._write_grippers()
        if self._damping.size:
            sel = self._cable_sel
            if isinstance(sel, slice):
                np.multiply(self._damping, self._qvel[sel], out=self._qfrc_applied[sel])
            else:
                self._qfrc_applied[sel] = self._damping * self._qvel[sel]
        dt = self._dt
        duration = n * dt
        sensed = self._sensed
        model, data = self._model, self._data
        if n == 1 or any(g.turning for g, *_ in sensed):
            # the forces were computed at the pose before each step
            for j in range(n):
                mujoco.mj_step(model, data, 1)
                for a, (g, constraint_force, constraint_torque, force, torque) in enumerate(sensed):
                    q = g.orientation
                    if g.turning and j > 0:
                        q = integrate_pose(g.position, q, g.linear, g.angular, j * dt)[1]
                    if j == 0:
                        force[:] = constraint_force
                        mujoco.mju_rotVecQuat(torque, constraint_torque, q)
                    else:
                        force += constraint_force
                        body = self._torque_sum[a]
                        mujoco.mju_rotVecQuat(body, constraint_torque, q)
                        torque += body
            if n > 1:
                for _, _, _, force, torque in sensed:
                    force /= n
                    torque /= n
        else:
            # the wrist measures the period's mean wrench, as a sensor filtered
            # at the control rate does: the last physics step alone aliases the
            # cable's vibration near the grasp, which the period's twist update
            # excites at the control rate, into a steady false pull (0.1 N
            # normal to the cable on random board 303464894, read as a bias)
            total, view = self._constraint_sum, self._gripper_constraint
            mujoco.mj_step(model, data, 1)
            total[:] = view
            for _ in range(n - 1):
                mujoco.mj_step(model, data, 1)
                total += view
            total /= n
            for a, (g, _, _, force, torque) in enumerate(sensed):
                o = self._sensed_offset[a]
                force[:] = total[o : o + 3]
                mujoco.mju_rotVecQuat(torque, total[o + 3 : o + 6], g.orientation)
        for g, _, _, force, _ in sensed:
            fn = math.sqrt(float(force @ force))
            if fn > self._max_force:
                self._max_force = fn
            if g.moving or g.turning:
                g.position, g.orientation = integrate_pose(
                    g.position, g.orientation, g.linear, g.angular, duration
                )
        self._check()

    def _check(self) -> None:
        """Raise :class:`SimulationDiverged` on an instability warning, NaN/inf or a blow-up.

        Runs after every control period: the common case (all finite, every
        cable dof slower than ``max_speed``) is decided from two dot products
        (a NaN or inf in the state makes them non-finite; a sum of squares
        below max_speed^2 bounds every component); only otherwise is the
        state searched element by element.
        """
        d = self._data
        converged = _inertia_converged
        bad = 0
        for inertia, stat in self._warning_stats:
            if not (inertia and converged):
                bad += stat.number
        qvel = self._qvel
        squares = float(qvel @ qvel)  # bounds every dof's speed, the cable's among them
        limit = self._options.max_speed
        if bad > self._warnings or not squares <= limit * limit:
            v = qvel[self._cable_sel]
            speed = float(np.max(np.abs(v))) if v.size else 0.0
            if bad > self._warnings or not np.isfinite(speed) or speed > limit:
                self._warnings = bad
                raise SimulationDiverged(
                    f"the simulation diverged at t = {self.time:.4f} s (cable speed"
                    f" {speed:.3g} m/s, MuJoCo instability warnings {bad})"
                )
        if not math.isfinite(float(self._qpos @ self._qpos) + squares) and not (
            np.all(np.isfinite(d.qpos)) and np.all(np.isfinite(d.qvel))
        ):
            raise SimulationDiverged(f"the simulation produced NaN/inf at t = {self.time:.4f} s")
