import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.control.safety_limits import ForceLimitExceededError, SafetyLimits
from tautwire.errors import InvalidArgumentError, TautwireError

twists = st.lists(
    st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False), min_size=12, max_size=12
).map(np.array)


@settings(max_examples=100, deadline=None)
@given(twists)
def test_limit_twist_clamps_each_block_keeping_direction(twist: np.ndarray) -> None:
    limits = SafetyLimits(max_force=20.0, max_linear_speed=(0.1, 0.2), max_angular_speed=0.5)
    out = limits.limit_twist(twist)
    for block, limit in enumerate((0.1, 0.5, 0.2, 0.5)):
        s = slice(3 * block, 3 * block + 3)
        n_in, n_out = np.linalg.norm(twist[s]), np.linalg.norm(out[s])
        assert n_out <= limit * (1 + 1e-12)
        if n_in <= limit:
            np.testing.assert_array_equal(out[s], twist[s])
        else:
            np.testing.assert_allclose(n_out, limit)
            np.testing.assert_allclose(out[s] * n_in, twist[s] * n_out, atol=1e-12)


def test_limit_twist_does_not_modify_its_input() -> None:
    twist = np.full(12, 5.0)
    SafetyLimits(20.0).limit_twist(twist)
    assert np.all(twist == 5.0)


def test_check_force() -> None:
    limits = SafetyLimits(max_force=10.0)
    ok = limits.check_force([3.0, 4.0, 0.0], "right")
    assert ok.within_limit and ok.force == pytest.approx(5.0) and ok.arm == "right"
    breach = limits.check_force([6.0, 8.0, 0.1])
    assert not breach.within_limit
    assert breach.limit == 10.0


def test_enforce_force_raises_with_the_numbers() -> None:
    limits = SafetyLimits(max_force=10.0)
    limits.enforce_force([0.0, 0.0, 9.9])
    with pytest.raises(ForceLimitExceededError, match="left") as info:
        limits.enforce_force([0.0, 0.0, -12.0], "left")
    assert isinstance(info.value, TautwireError)
    assert info.value.force == pytest.approx(12.0)
    assert info.value.limit == 10.0


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"max_force": 0.0}, "max_force"),
        ({"max_force": 1.0, "max_linear_speed": -1.0}, "max_linear_speed"),
        ({"max_force": 1.0, "max_angular_speed": (1.0, 2.0, 3.0)}, "pair"),
        ({"max_force": float("inf")}, "max_force"),
    ],
)
def test_rejects_bad_limits(kwargs: dict[str, object], match: str) -> None:
    with pytest.raises(InvalidArgumentError, match=match):
        SafetyLimits(**kwargs)  # type: ignore[arg-type]


def test_rejects_bad_inputs() -> None:
    limits = SafetyLimits(10.0)
    with pytest.raises(InvalidArgumentError, match="'left' or 'right'"):
        limits.check_force([0.0, 0.0, 1.0], "middle")
    with pytest.raises(InvalidArgumentError, match="force"):
        limits.check_force([0.0, np.nan, 1.0])
    with pytest.raises(InvalidArgumentError, match="twist"):
        limits.limit_twist(np.zeros(6))
