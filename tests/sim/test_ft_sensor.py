"""The simulated wrist sensor: sign, weight share, direction, noise."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.model.quaternion import orientation_along
from tautwire.model.tension import GRAVITY, G
from tautwire.sim import CableSpec, GripperSpec, HoldSpec, SimWorld, WorldSpec
from tautwire.sim.ft_sensor import FTSensor
from tautwire.sim.ground_truth import GroundTruth
from tests.sim.scenes import anchor_and_gripper, rest


def _angle_deg(a: np.ndarray, b: np.ndarray) -> float:
    c = float(a @ b / (np.linalg.norm(a) * np.linalg.norm(b)))
    return float(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))


@pytest.mark.parametrize("k", [10.0, 1000.0])
def test_sensed_force_at_rest_is_tension_plus_half_weight_pointing_at_anchor(k: float) -> None:
    # Moment balance of a uniform cable between A and G: the force on the
    # gripper plus half the cable's weight (added back upwards) points from G
    # to A, with magnitude H |G - A| / a_h (H the horizontal tension).
    anchor = np.array([0.0, 0.0, 0.3])
    gripper = np.array([0.3, 0.08, 0.36])
    chord = gripper - anchor
    length, rho = 0.3, 0.03
    stretch = 1.5 / k  # about 1.5 N of tension
    length = float(np.linalg.norm(chord)) - stretch
    world = anchor_and_gripper(
        anchor.tolist(), gripper.tolist(), length, k, rho, orientation_along(chord)
    )
    rest(world, 1.0)
    force, torque = world.wrench("left")
    weight = rho * length * G
    compensated = force - 0.5 * weight / G * GRAVITY
    assert _angle_deg(compensated, anchor - gripper) < 1.0
    truth = GroundTruth(world)
    p = truth.polyline("W")
    mid = len(p) // 2
    seg = p[mid + 1] - p[mid]
    horizontal = truth.tensions("W")[mid] * np.hypot(seg[0], seg[1]) / np.linalg.norm(seg)
    expected = horizontal * np.linalg.norm(chord) / np.hypot(chord[0], chord[1])
    assert np.linalg.norm(compensated) == pytest.approx(expected, rel=0.03)
    # the hold is a point grasp at the tool centre point: no moment about it
    assert np.linalg.norm(torque) < 1e-3 * np.linalg.norm(force) * 0.01


def test_sensor_sign_is_the_pull_of_the_cable_on_the_gripper() -> None:
    # A cable hanging freely from the gripper pulls it down by its whole weight.
    length, rho = 0.2, 0.05
    x_down = np.array([np.sqrt(0.5), 0.0, np.sqrt(0.5), 0.0])
    spec = WorldSpec(
        fixtures=(),
        cables=(CableSpec("W", length, rho, 100.0, 0.0025, holds=(HoldSpec("left", 0.0),)),),
        left=GripperSpec([0.0, 0.0, 0.6], x_down),
        right=GripperSpec([0.0, -0.5, 0.3]),
    )
    world = SimWorld(spec)
    rest(world, 1.0)
    force, _ = world.wrench("left")
    assert force == pytest.approx([0.0, 0.0, -rho * length * G], abs=2e-3 * rho * length * G)


def test_noise_is_seeded_gaussian_with_the_given_std() -> None:
    rng = np.random.default_rng(7)
    sensor = FTSensor("left", 0.05, 0.002, rng)
    force, torque = np.array([1.0, -2.0, 0.5]), np.array([0.01, 0.0, -0.02])
    samples = [sensor.measure(force, torque) for _ in range(4000)]
    f = np.array([s.force for s in samples])
    t = np.array([s.torque for s in samples])
    assert np.allclose(f.mean(axis=0), force, atol=4 * 0.05 / np.sqrt(4000))
    assert np.allclose(f.std(axis=0), 0.05, rtol=0.06)
    assert np.allclose(t.std(axis=0), 0.002, rtol=0.06)
    again = FTSensor("left", 0.05, 0.002, np.random.default_rng(7)).measure(force, torque)
    assert np.array_equal(again.force, samples[0].force)
    assert samples[0].arm == "left"


def test_noise_free_sensor_passes_the_wrench_through() -> None:
    sensor = FTSensor("right", 0.0, 0.0, np.random.default_rng(0))
    w = sensor.measure(np.array([1.0, 2.0, 3.0]), np.array([0.1, 0.2, 0.3]))
    assert np.array_equal(w.force, [1.0, 2.0, 3.0])
    assert np.array_equal(w.torque, [0.1, 0.2, 0.3])


@pytest.mark.parametrize("bad", [-0.1, float("nan")])
def test_sensor_rejects_bad_noise(bad: float) -> None:
    with pytest.raises(InvalidArgumentError, match="noise_force"):
        FTSensor("left", bad, 0.0, np.random.default_rng(0))
