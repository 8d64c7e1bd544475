import numpy as np
import pytest

from tautwire.control.grip_force_controller import YUMI_MAX_GRIP_FORCE, GripForceController
from tautwire.errors import InvalidArgumentError

DT = 0.004


def sliding_plant(controller: GripForceController, mu: float, f_slid, steps: int) -> np.ndarray:  # type: ignore[no-untyped-def]
    """Cable sliding all the time: f_c = 2 mu F_grip, measured one period later."""
    grip = controller.grip_force
    tension = np.empty(steps)
    for n in range(steps):
        f_c = 2.0 * mu * grip
        tension[n] = f_c
        target = f_slid(n) if callable(f_slid) else f_slid
        grip = controller.update(target, f_c, DT)
    return tension


def stick_slip_plant(
    controller: GripForceController, mu: float, k: float, speed: float, f_slid: float, steps: int
) -> tuple[np.ndarray, np.ndarray]:
    """Coulomb contact pulled through a spring of stiffness k at a constant speed.

    The spring stretches while the cable sticks; when its tension would exceed the
    friction limit 2 mu F_grip, the cable slides and the tension is that limit.
    """
    stretch = 0.0
    grip = controller.grip_force
    tension = np.empty(steps)
    slid = np.zeros(steps, dtype=bool)
    for n in range(steps):
        stretch += speed * DT
        limit = 2.0 * mu * grip
        if k * stretch > limit:
            stretch = limit / k
            slid[n] = True
        tension[n] = k * stretch
        grip = controller.update(f_slid, tension[n], DT)
    return tension, slid


def test_converges_to_the_set_friction_force_for_unknown_mu() -> None:
    rng = np.random.default_rng(21)
    for mu in rng.uniform(0.1, 1.5, size=8):
        controller = GripForceController()
        f_slid = rng.uniform(0.5, 5.0)
        tension = sliding_plant(controller, mu, f_slid, steps=2500)  # 10 s
        assert abs(tension[-1] - f_slid) < 1e-3
        np.testing.assert_allclose(controller.grip_force, f_slid / (2 * mu), rtol=1e-3)


def test_converges_with_stick_slip() -> None:
    rng = np.random.default_rng(22)
    for mu in rng.uniform(0.1, 1.0, size=5):
        controller = GripForceController()
        k = rng.uniform(50.0, 1000.0)
        tension, slid = stick_slip_plant(controller, mu, k, speed=0.02, f_slid=2.0, steps=3000)
        assert slid[-500:].all()  # sliding at the end
        assert np.max(np.abs(tension[-500:] - 2.0)) < 1e-3


def test_stability_bound_on_mu() -> None:
    # stable iff 2 mu k_p < 1 and 2 mu (2 k_p + k_i dt) < 2; defaults: mu < 1 / 0.24
    mu_max = 1.0 / (2 * 0.1 + 10.0 * DT)
    inside = sliding_plant(GripForceController(), 0.95 * mu_max, 2.0, steps=5000)
    outside = sliding_plant(GripForceController(), 1.05 * mu_max, 2.0, steps=5000)
    assert abs(inside[-1] - 2.0) < 1e-3
    assert np.ptp(outside[-100:]) > 1.0  # keeps oscillating between the grip-force limits


def test_output_is_clamped() -> None:
    controller = GripForceController(k_p=1.0)
    assert controller.update(1000.0, 0.0, DT) == YUMI_MAX_GRIP_FORCE
    assert controller.update(-1000.0, 0.0, DT) == 0.0


def test_grip_never_falls_below_its_floor_and_the_integral_does_not_wind_down() -> None:
    # a tension spike far above f_slid (the cable caught beyond the gripper)
    # would drive an unbounded grip to zero; the floor holds it, the integral
    # (the friction learnt so far) does not wind down below the floor, and
    # once the spike is gone the grip is back where the integral stands
    controller = GripForceController(initial_grip_force=1.0, min_grip_force=0.75)
    grips = [controller.update(1.5, 6.0, DT) for _ in range(500)]
    assert min(grips) == pytest.approx(0.75)
    assert 0.75 <= controller.integral <= 1.0
    assert controller.update(1.5, 1.5, DT) == pytest.approx(controller.integral)
    assert controller.update(1.5, 0.5, DT) > controller.integral - 0.01
    unbounded = GripForceController(initial_grip_force=1.0)
    assert min(unbounded.update(1.5, 6.0, DT) for _ in range(500)) == 0.0


def test_anti_windup() -> None:
    # f_slid unreachable (above 2 mu F_max = 8 N) for 5 s, then reachable
    mu = 0.2

    def f_slid(n: int) -> float:
        return 20.0 if n < 1250 else 2.0

    controller = GripForceController()
    tension = sliding_plant(controller, mu, f_slid, steps=1250)
    # without anti-windup the integral would have grown by k_i * 12 N * 5 s = 600 N
    assert controller.integral <= YUMI_MAX_GRIP_FORCE
    tension = np.concatenate((tension, sliding_plant(controller, mu, lambda n: 2.0, 1250)))
    assert tension[1249] == pytest.approx(2 * mu * YUMI_MAX_GRIP_FORCE)
    # recovers from saturation no slower than a fresh start from F_max: the
    # integral did not wind up past the limit
    fresh = GripForceController(initial_grip_force=YUMI_MAX_GRIP_FORCE)
    reference = sliding_plant(fresh, mu, 2.0, steps=1250)

    def settling_step(t: np.ndarray) -> int:
        return int(np.nonzero(np.abs(t - 2.0) > 0.02)[0][-1]) + 1

    assert settling_step(tension[1250:]) <= settling_step(reference) < 1250
    assert abs(tension[-1] - 2.0) < 1e-3


def test_reset() -> None:
    controller = GripForceController(initial_grip_force=5.0)
    controller.update(3.0, 0.0, DT)
    assert controller.grip_force != 5.0
    controller.reset()
    assert controller.grip_force == controller.integral == 5.0
    controller.reset(100.0)
    assert controller.integral == YUMI_MAX_GRIP_FORCE


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"k_p": -1.0}, "k_p"),
        ({"k_i": 0.0}, "k_i"),
        ({"max_grip_force": float("nan")}, "max_grip_force"),
        ({"min_grip_force": -0.1}, "min_grip_force"),
        ({"min_grip_force": 20.0}, "min_grip_force"),
        ({"min_grip_force": 2.0, "initial_grip_force": 1.0}, "initial_grip_force"),
        ({"initial_grip_force": 30.0}, r"\[0, 20.0\]"),
    ],
)
def test_rejects_bad_arguments(kwargs: dict[str, float], match: str) -> None:
    with pytest.raises(InvalidArgumentError, match=match):
        GripForceController(**kwargs)
    with pytest.raises(InvalidArgumentError, match="dt"):
        GripForceController().update(1.0, 0.0, 0.0)
