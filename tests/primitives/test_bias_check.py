"""I's closing check of the force sensor's bias (primitives/bias_check.py)."""

import math

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.primitives import RotateAroundFeaturePoint, SingleArmTension
from tautwire.primitives.bias_check import (
    LOWER,
    MAX_STROKE,
    MEASURE,
    SETTLE,
    SHIFT_LIMIT,
    BiasCheck,
)
from tautwire.robot import Observation, Wrench
from tautwire.tasks import run_step
from tests.primitives.conftest import CONTACT, GRIPPER, context
from tests.primitives.spring_robot import SpringCableRobot


def test_schedule_steps_down_and_back() -> None:
    check = BiasCheck(10.0, 3.0, 1000.0, 0.5)
    assert check.lower == pytest.approx(LOWER * 3.0)
    assert check.duration == pytest.approx(3 * SETTLE + 2 * MEASURE)
    assert check.set_point(10.0) == 3.0
    assert check.set_point(10.0 + SETTLE + MEASURE + 0.5 * SETTLE) == pytest.approx(2.25)
    assert check.set_point(10.0 + 2 * SETTLE + MEASURE + 0.1) == pytest.approx(1.5)
    assert check.set_point(10.0 + check.duration) == pytest.approx(3.0)
    end = 10.0 + check.duration
    assert not check.done(end - 1e-3, 3.0) and check.done(end, 3.0)
    # not before the tension is back, but a settle later in any case
    assert not check.done(end, 2.0) and check.done(end + SETTLE, 2.0)
    # a peg's check always waits that settle (its filter follows the height again)
    assert not check.done(end, 3.0, settle=True) and check.done(end + SETTLE, 3.0, settle=True)
    assert not check.restoring(end - SETTLE - 1e-3) and check.restoring(end - SETTLE)


def test_a_soft_or_short_span_steps_by_its_stroke() -> None:
    # 10 N/m over 0.5 m: a half step (1.5 N) would pull 150 mm; MAX_STROKE caps it
    assert BiasCheck(0.0, 3.0, 10.0, 0.5).lower == pytest.approx(3.0 - 10.0 * MAX_STROKE)
    # a 0.1 m span: at most 30 mm of it
    assert BiasCheck(0.0, 3.0, 10.0, 0.1).lower == pytest.approx(3.0 - 10.0 * 0.03)


def test_bad_arguments_are_refused() -> None:
    with pytest.raises(InvalidArgumentError, match="stiffness"):
        BiasCheck(0.0, 3.0, 0.0, 0.5)
    with pytest.raises(InvalidArgumentError, match="span"):
        BiasCheck(0.0, 3.0, 100.0, math.nan)


def _fed(
    bias: np.ndarray,
    span: float = 0.4,
    seed: int = 0,
    noise: float = 0.08,
    peg: tuple[np.ndarray, float, float] | None = None,
) -> BiasCheck:
    """A check fed T u + b + noise at its own set points, every 4 ms."""
    rng = np.random.default_rng(seed)
    u = np.array([0.8, -0.6, 0.0])
    check = BiasCheck(0.0, 2.0, 300.0, span, peg=peg)
    t = 0.0
    while not check.done(t, check.set_point(t)):
        check.add(t, check.set_point(t) * u + bias + rng.normal(scale=noise, size=3))
        t += 0.004
    return check


def test_no_bias_passes_and_a_bias_fails() -> None:
    ok, detail, shift = _fed(np.zeros(3)).verdict()
    assert ok and shift is not None and np.linalg.norm(shift) < 3 * SHIFT_LIMIT
    assert "held still" in detail
    # 0.1 N normal to the cable at 2 N, 0.4 m from the contact: 20 mm
    ok, detail, shift = _fed(np.array([0.06, 0.08, 0.0])).verdict()
    assert not ok and shift is not None
    assert np.linalg.norm(shift) == pytest.approx(0.02, abs=0.004)
    assert "20." in detail or "19." in detail or "21." in detail


def test_an_unmeasured_check_fails_and_says_so() -> None:
    ok, detail, shift = BiasCheck(0.0, 2.0, 300.0, 0.4).verdict()
    assert not ok and shift is None and "could not be measured" in detail


def test_a_bias_drifting_during_a_level_fails_it() -> None:
    # 0.3 N/s normal to the cable while the gripper holds still
    rng = np.random.default_rng(5)
    u = np.array([0.8, -0.6, 0.0])
    normal = np.array([0.6, 0.8, 0.0])
    check = BiasCheck(0.0, 2.0, 300.0, 0.4)
    t = 0.0
    while not check.done(t, check.set_point(t)):
        f = check.set_point(t) * u + 0.3 * t * normal + rng.normal(scale=0.05, size=3)
        check.add(t, f)
        t += 0.004
    ok, detail, _ = check.verdict()
    assert not ok and "turned by" in detail


class _LateBiasRobot(SpringCableRobot):
    """A spring cable whose sensor gains a bias once I's check has begun."""

    def __init__(self, bias: np.ndarray) -> None:
        super().__init__(CONTACT, GRIPPER, 200.0, seed=21)
        self.bias = bias
        self.primitive: RotateAroundFeaturePoint | None = None

    def observe(self) -> Observation:
        obs = super().observe()
        w = obs.wrenches[0]
        on = self.primitive is not None and self.primitive._check is not None
        f = w.force + (self.bias if on else 0.0)
        return Observation(obs.time, obs.left, obs.right, (Wrench("left", f, w.torque),))


@pytest.mark.parametrize("bias", [np.zeros(3), np.array([0.0, 0.0, 0.4])])
def test_rotation_ends_with_the_check(bias: np.ndarray) -> None:
    """The lines before the check are clean: only the check can tell a bias."""
    robot = _LateBiasRobot(bias)
    ctx = context(estimation_period=0.04)
    assert run_step(robot, SingleArmTension("left", 3.0), ctx).success
    rotate = RotateAroundFeaturePoint("left", math.pi, speed=0.5)
    robot.primitive = rotate
    report = run_step(robot, rotate, ctx)
    if np.any(bias):
        # 0.4 N normal to the cable at 3 N, 0.3 m from the contact: 40 mm
        assert not report.success and report.cause == "sensor_bias", report
        assert "held still" in report.detail
    else:
        assert report.success, report
        assert "held still" in report.detail
    assert ctx.estimator.circling


def _fed_peg(bias: np.ndarray, radius: float = 0.006, bearing: float = 0.0) -> BiasCheck:
    return _fed(bias, seed=3, noise=0.03, peg=(np.array([0.0, 0.0, 1.0]), radius, bearing))


def test_a_pegs_shift_is_judged_normal_to_and_along_its_axis() -> None:
    check = _fed_peg(np.zeros(3))
    assert check.limit == pytest.approx(0.0045) and check.axial_limit == pytest.approx(0.009)
    # 0.03 N up at 2 N over 0.4 m: 6 mm along the axis, within its 9 mm
    ok, detail, _ = _fed_peg(np.array([0.0, 0.0, 0.03])).verdict()
    assert ok and "along the peg's axis" in detail
    # 0.06 N up: 12 mm, beyond it
    ok, _, _ = _fed_peg(np.array([0.0, 0.0, 0.06])).verdict()
    assert not ok
    # 0.03 N sideways: 6 mm normal to the axis, beyond half the tolerance
    ok, detail, _ = _fed_peg(np.array([0.018, 0.024, 0.0])).verdict()
    assert not ok and "normal to the peg's axis" in detail


def test_a_pegs_axial_limit_is_its_bearing_radius_and_its_normal_one_its_own() -> None:
    """Robustness trial 6: 9.2 mm normal to a 9.9 mm peg's axis is beyond half its tolerance."""
    check = _fed_peg(np.zeros(3), radius=0.0099, bearing=0.0154)
    assert check.limit == pytest.approx(0.5 * (0.0099 + 0.003))
    assert check.axial_limit == pytest.approx(0.0154 + 0.003)
    # 0.04 N up at 2 N over 0.4 m: 8 mm along the axis, within the bearing's 18.4 mm
    ok, _, _ = _fed_peg(np.array([0.0, 0.0, 0.04]), radius=0.0099, bearing=0.0154).verdict()
    assert ok
    # 0.04 N sideways: 8 mm normal to the axis, beyond 6.45 mm
    ok, detail, _ = _fed_peg(np.array([0.024, 0.032, 0.0]), radius=0.0099, bearing=0.0154).verdict()
    assert not ok and "normal to the peg's axis" in detail
