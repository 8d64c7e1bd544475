"""The wave-speed guard: closed forms, per-vertex scaling, refusal, and accuracy."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError, SimulationError
from tautwire.model.tension import G
from tautwire.sim.wave_speed import (
    max_stable_timestep,
    required_mass_scaling,
    vertex_mass_scaling,
    vertex_timestep_limit,
)
from tests.sim.scenes import X_UP, anchor_and_gripper, rest


def test_limit_is_l_sqrt_rho_over_t() -> None:
    assert max_stable_timestep(0.02, 0.03, 20.0) == pytest.approx(0.02 * np.sqrt(0.03 / 20.0))
    assert max_stable_timestep(0.02, 0.03, 20.0, 4.0) == pytest.approx(
        2.0 * max_stable_timestep(0.02, 0.03, 20.0)
    )


def test_required_scaling_reaches_the_limit_exactly() -> None:
    dt, seg, rho, t = 0.001, 0.0075, 0.03, 20.0
    alpha = required_mass_scaling(dt, seg, rho, t, safety=0.8)
    assert alpha > 1.0
    assert max_stable_timestep(seg, rho, t, alpha) * 0.8 == pytest.approx(dt)
    assert required_mass_scaling(1e-5, seg, rho, t) == 1.0


def test_uniform_vertex_scaling_equals_the_segment_formula() -> None:
    n, seg, rho, t, dt = 10, 0.01, 0.03, 15.0, 0.001
    rest = np.full(n, seg)
    masses = np.full(n + 1, rho * seg)
    masses[[0, -1]] *= 0.5
    alpha = vertex_mass_scaling(dt, rest, masses, t, 0.8)
    assert np.allclose(alpha, required_mass_scaling(dt, seg, rho, t, 0.8))
    assert vertex_timestep_limit(rest, alpha * masses, t) * 0.8 == pytest.approx(dt)


def test_only_vertices_beside_a_short_segment_get_heavier() -> None:
    rest = np.array([0.02, 0.02, 0.02, 0.005, 0.02])
    masses = 0.03 * (np.r_[rest, 0.0] + np.r_[0.0, rest]) / 2
    alpha = vertex_mass_scaling(0.001, rest, masses, 15.0, 0.8)
    assert alpha[3] > alpha[1] and alpha[4] > alpha[1]
    assert alpha[0] == pytest.approx(alpha[1])


def test_bad_arguments_are_refused() -> None:
    with pytest.raises(InvalidArgumentError):
        max_stable_timestep(0.0, 0.03, 1.0)
    with pytest.raises(InvalidArgumentError):
        vertex_mass_scaling(0.001, np.array([0.01]), np.array([1.0]), 1.0)


def test_build_refuses_a_scene_the_guard_cannot_fix() -> None:
    with pytest.raises(SimulationError, match="wave-speed"):
        anchor_and_gripper(
            [0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.3, 100.0, force_limit=500.0, max_mass_scaling=4.0
        )


def test_many_short_segments_under_high_tension_still_obey_hooke() -> None:
    # N = 80 segments, T about 10 N at dt = 1 ms: far beyond the unscaled
    # limit; the guard's mass scaling keeps the force exact.
    k, length, rho = 1000.0, 0.4, 0.03
    dl = 10.0 / k
    top = np.array([0.0, 0.0, 0.9])
    world = anchor_and_gripper(
        top.tolist(),
        (top - [0.0, 0.0, length + dl]).tolist(),
        length,
        k,
        rho,
        orientation=X_UP,
        segment_length=0.005,
    )
    assert world.scene.discretizations["W"].mass_scaling.max() > 10.0
    rest(world, 0.5)
    force, _ = world.wrench("left")
    assert force[2] + 0.5 * rho * length * G == pytest.approx(k * dl, rel=0.02)


def test_without_the_scaling_the_instability_is_caught_not_missimulated(monkeypatch) -> None:
    # The same taut horizontal cable with the guard's mass scaling switched
    # off: MuJoCo's solver fails and the world raises instead of reporting a
    # wrong force.
    import tautwire.sim.discretization as discretization
    from tautwire.model.quaternion import orientation_along
    from tautwire.sim import SimulationDiverged

    k, rho = 1000.0, 0.03
    anchor, gripper = np.array([0.0, 0.0, 0.3]), np.array([0.4, 0.0, 0.3])
    args = (
        anchor.tolist(),
        gripper.tolist(),
        0.4 - 10.0 / k,
        k,
        rho,
        orientation_along(gripper - anchor),
    )
    guarded = anchor_and_gripper(*args, segment_length=0.0075)
    rest(guarded, 0.3)
    assert np.linalg.norm(guarded.wrench("left")[0]) == pytest.approx(10.0, rel=0.01)
    monkeypatch.setattr(
        discretization, "vertex_mass_scaling", lambda dt, r, m, t, s: np.ones(len(m))
    )
    with pytest.raises(SimulationDiverged):
        unguarded = anchor_and_gripper(*args, segment_length=0.0075)
        rest(unguarded, 0.3)
