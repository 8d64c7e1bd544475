"""SimWorld: stepping, grasping, friction sliding, the sensor computation, guards."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tautwire.errors import SimulationError
from tautwire.experiments.run_scenario import run_scenario
from tautwire.robot import GripperCommand
from tautwire.scenario import load_scenario
from tautwire.sim import SimulationDiverged
from tautwire.sim import world as world_module
from tautwire.sim.gripper_state import integrate_pose
from tautwire.sim.transmitted_wrench import explicit_wrench, free_joint_wrench
from tests.sim.scenes import anchor_and_gripper, peg_scene, rest

MU_PAD = 0.5  # SimOptions.pad_friction default


def _slide(world, grip: float, speed: float, seconds: float, window: float) -> np.ndarray:
    world.set_gripper("left", GripperCommand("grip_force", grip))
    twist = np.zeros(12)
    twist[0] = speed
    world.set_twist(twist)
    forces = []
    steps = round(seconds / world.control_period)
    for k in range(steps):
        world.step()
        if k >= steps - round(window / world.control_period):
            forces.append(world.wrench("left")[0])
    return np.array(forces)


@pytest.mark.parametrize("grip", [1.0, 4.0])
def test_sliding_friction_through_gripper_is_two_mu_grip(grip: float) -> None:
    # The gripper squeezes the cable with two pads and pulls away from the
    # anchor along it: once the cable slides, the pull is 2 mu F_grip.
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.32, 0.0, 0.3], 0.4, 1000.0, held_at=0.32)
    rest(world, 0.2)
    start = world.held("left")
    forces = _slide(world, grip, 0.01, 3.0, 1.0)
    assert world.held("left") is None and start is not None
    assert -forces[:, 0].mean() == pytest.approx(2.0 * MU_PAD * grip, rel=0.10)


@pytest.mark.parametrize("turning", [False, True])
def test_a_control_period_reads_the_mean_of_its_physics_steps(
    turning: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    # the period's wrench is the mean of its physics steps' wrenches (each read
    # as free_joint_wrench at the pose before its step), not the last one's
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.2, 0.0, 0.3], 0.4, 1000.0, held_at=0.2)
    rest(world, 0.1)
    twist = np.zeros(12)
    twist[0] = 0.02  # pull along the cable: the force changes step by step
    if turning:
        twist[3:6] = [0.0, 0.0, 0.8]
    world.set_twist(twist)
    dof = world._gripper_dof["left"]
    g = world._grippers["left"]
    steps: list[tuple[np.ndarray, np.ndarray]] = []
    mujoco = world_module.mujoco  # the simulator module the world steps with
    real_step = mujoco.mj_step

    def recorded(m: object, d: object, n: int = 1) -> None:
        assert n == 1
        q = integrate_pose(
            g.position, g.orientation, g.linear, g.angular, len(steps) * world.timestep
        )[1]
        real_step(m, d, n)
        steps.append(free_joint_wrench(d, dof, q))

    monkeypatch.setattr(mujoco, "mj_step", recorded)
    world.step()
    monkeypatch.undo()
    assert len(steps) == world.substeps > 1
    force, torque = world.wrench("left")
    forces = np.array([f for f, _ in steps])
    assert np.ptp(forces[:, 0]) > 1e-3  # the steps differ
    assert np.allclose(force, forces.mean(axis=0), rtol=0.0, atol=1e-12)
    assert np.allclose(torque, np.mean([t for _, t in steps], axis=0), rtol=0.0, atol=1e-12)


def test_free_joint_wrench_equals_sum_of_equality_and_contact_forces() -> None:
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.2, 0.0, 0.3], 0.4, 1000.0, held_at=0.2)
    rest(world, 0.1)
    hold_ids = np.concatenate(list(world._cables["W"].hold_ids.values()))

    def explicit() -> tuple[np.ndarray, np.ndarray]:
        p, q = world.gripper_pose("left")
        return explicit_wrench(
            world._model, world._data, world._gripper_bodies["left"], hold_ids, p, q
        )

    # held: the connect equality carries the force (one physics step: its own wrench)
    world.step(1)
    force, torque = world.wrench("left")
    f2, t2 = explicit()
    assert np.linalg.norm(force) > 0.01
    assert np.allclose(force, f2, atol=1e-9) and np.allclose(torque, t2, atol=1e-9)
    # squeezed: only contacts (pads and lips) carry it
    world.set_gripper("left", GripperCommand("grip_force", 3.0))
    twist = np.zeros(12)
    twist[3:6] = [0.0, 0.0, 0.5]  # turn about z so contact torques are not trivial
    world.set_twist(twist)
    for _ in range(50):
        world.step(1)
        world.set_twist(np.zeros(12))
    world.step(1)
    force, torque = world.wrench("left")
    f2, t2 = explicit()
    assert world._data.ncon > 0 and np.linalg.norm(force) > 0.1
    assert np.allclose(force, f2, atol=1e-8) and np.allclose(torque, t2, atol=1e-8)


def test_hold_grasps_the_nearest_vertex_without_a_jump_and_open_releases() -> None:
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.2, 0.0, 0.3], 0.4, 100.0, held_at=0.2)
    rest(world, 0.1)
    held = world.held("left")
    assert held is not None and world.scene.discretizations["W"].arc[held[1]] == 0.2
    world.set_gripper("left", GripperCommand("open"))
    rest(world, 0.02)
    assert world.held("left") is None
    # grasp again: the vertex nearest to the tool centre point, where it is
    world.set_gripper("left", GripperCommand("hold"))
    held = world.held("left")
    assert held is not None
    before = world._data.xpos[world._cables["W"].body_ids[held[1]]].copy()
    world.step()
    after = world._data.xpos[world._cables["W"].body_ids[held[1]]]
    assert np.linalg.norm(after - before) < 2e-4
    assert world.gripper_grip_force("left") == world.options.hold_grip_force
    # open and let the cable fall away: the gripper feels nothing
    world.set_gripper("left", GripperCommand("open"))
    rest(world, 0.3)
    assert world.held("left") is None and world.gripper_grip_force("left") == 0.0
    assert world.gripper_opening("left") == pytest.approx(world.options.max_opening, abs=1e-3)
    assert np.linalg.norm(world.wrench("left")[0]) < 1e-9


@pytest.mark.parametrize("beside", [-0.002, 0.0015])
def test_a_grasp_centres_the_cable_between_the_pads(beside: float) -> None:
    """Closing fingers put the held cable on the tool's centre line, not in a pad.

    Held where it lay, 2 mm towards one pad, the vertex's capsule sat inside that
    pad: the weld and the pad's contact pushed hundreds of newtons against each
    other, and the wrench's line of action moved 15 mm beside the cable.
    """
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.2, 0.0, 0.3], 0.4, 300.0, held_at=0.2)
    rest(world, 0.1)
    world.set_gripper("left", GripperCommand("open"))
    twist = np.zeros(12)
    twist[1] = beside / 0.02  # the open gripper moves along its tool y, beside the cable
    world.set_twist(twist)
    for _ in range(round(0.02 / world.control_period)):
        world.step()
    world.set_gripper("left", GripperCommand("hold"))
    held = world.held("left")
    assert held is not None
    twist = np.zeros(12)
    twist[0] = 0.05  # pull the cable taut towards +x
    world.set_twist(twist)
    for _ in range(round(0.4 / world.control_period)):
        world.step()
    rest(world, 0.3)
    p, _ = world.gripper_pose("left")
    vertex = world._data.xpos[world._cables["W"].body_ids[held[1]]]
    assert abs(float(vertex[1] - p[1])) < 3e-4  # on the centre line (tool y is world y)
    force, torque = world.wrench("left")
    assert np.linalg.norm(force) > 1.0  # taut
    # the line of action passes the held vertex, not a pad's contact
    assert abs(float(torque[2])) / np.linalg.norm(force[:2]) < 1e-3


def test_time_starts_after_settling_and_advances_by_control_periods() -> None:
    world = peg_scene()
    assert world.time == 0.0
    world.step()
    assert world.time == pytest.approx(world.control_period)
    assert world.substeps == 4


def test_max_force_tracks_and_resets() -> None:
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.2, 0.0, 0.3], 0.2, 100.0)
    rest(world, 0.05)
    world.reset_max_force()
    twist = np.zeros(12)
    twist[0] = 0.05  # stretch by 2 cm -> about 2 N
    world.set_twist(twist)
    for _ in range(100):
        world.step()
    peak = world.max_force
    assert peak >= np.linalg.norm(world.wrench("left")[0]) > 1.5
    world.reset_max_force()
    assert world.max_force == 0.0


def test_nan_in_state_raises_diverged() -> None:
    world = peg_scene()
    world._data.qvel[world._cable_dofs[5]] = np.nan
    with pytest.raises(SimulationDiverged) as info:
        world.step()
    assert info.value.cause == "diverged"
    assert isinstance(info.value, SimulationError)


def test_velocity_blow_up_raises_diverged() -> None:
    world = peg_scene()
    world._data.qvel[world._cable_dofs[5]] = 10.0 * world.options.max_speed
    with pytest.raises(SimulationDiverged, match="diverged"):
        world.step()


def test_timestep_must_divide_control_period() -> None:
    with pytest.raises(SimulationError, match="divide"):
        peg_scene(timestep=0.0015)


def test_stiff_held_cable_reads_without_one_step_spikes() -> None:
    # Table I's trial C:30 (a 566 N/m cable held by both grippers): at
    # MuJoCo's default solver tolerance (1e-8) the reading jumped from 1 N to
    # 17.6 N for one physics step while the grippers turned over the clip, a
    # force-limit breach the cable never felt; SimOptions.solver_tolerance
    # (1e-10) solves the flex's M+K system closely enough to remove it.
    # (the scene as drawn then, saved: Table I's scenes have since widened)
    scenario = load_scenario(Path(__file__).parent / "data" / "table1-c30-stiff-pair.yaml")
    seed = scenario.seed
    # (at 1e-8 the scene no longer reproduces the spike since C turns no
    # gripper by more than a quarter; the guard would reject it as an
    # outlier anyway: what remains to check is that the world at its
    # tolerance reads no force the cable did not exert)
    tight, _, _ = run_scenario(scenario, seed)
    assert tight.success and tight.max_force < 12.0 and tight.true_max_force < 12.0


def test_model_and_data_are_the_worlds_own() -> None:
    import mujoco

    world = peg_scene()
    assert isinstance(world.model, mujoco.MjModel) and isinstance(world.data, mujoco.MjData)
    t = float(world.data.time)
    world.step()  # the world steps the data it hands out
    assert float(world.data.time) == pytest.approx(t + world.control_period)
    assert world.model.opt.timestep == world.timestep


def test_repeated_finger_commands_change_nothing_and_new_ones_apply() -> None:
    world = peg_scene()
    right = world._finger_act["right"]
    assert world.gripper_mode("right") == "open"  # a gripper that holds nothing starts open
    assert all(world._data.ctrl[a] == world.options.open_force for a in right)
    for _ in range(2):  # the second, identical command returns at once
        world.set_gripper("left", GripperCommand("hold"))
        assert world.held("left") is not None and world.gripper_mode("left") == "hold"
    for force in (2.0, 2.0, 3.0):
        world.set_gripper("left", GripperCommand("grip_force", force))
        assert world.held("left") is None and world.gripper_grip_force("left") == force
        left = world._finger_act["left"]
        assert all(world._data.ctrl[a] == -force for a in left)
    world.set_gripper("left", GripperCommand("open"))
    world.set_gripper("left", GripperCommand("open"))
    assert world.gripper_grip_force("left") == 0.0
    assert all(world._data.ctrl[a] == world.options.open_force for a in world._finger_act["left"])


def test_without_cable_damping_no_settling_force_is_left_applied() -> None:
    # settling damps the cable (settle_damping_time); a run without damping
    # (cable_damping_time = 0) must not keep the last settling force applied
    world = peg_scene(cable_damping_time=0.0)
    assert not world._data.qfrc_applied[world._cable_dofs].any()
    world.step()
    assert not world._data.qfrc_applied[world._cable_dofs].any()
