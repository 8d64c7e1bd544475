import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.robot import Command, GripperCommand, GripperState, Observation, Wrench, arm_index


def test_command_defaults_and_validation() -> None:
    c = Command()
    assert c.twist.shape == (12,) and not np.any(c.twist)
    assert c.gripper("left").mode == "hold"
    with pytest.raises(InvalidArgumentError):
        Command(twist=np.zeros(6))
    with pytest.raises(InvalidArgumentError):
        Command(twist=np.full(12, np.nan))
    with pytest.raises(InvalidArgumentError):
        GripperCommand(mode="squeeze")  # type: ignore[arg-type]
    with pytest.raises(InvalidArgumentError):
        GripperCommand(mode="grip_force", grip_force=-1.0)


def test_observation_lookup() -> None:
    g = GripperState(np.zeros(3), np.array([1.0, 0, 0, 0]))
    w = Wrench("left", np.array([1.0, 0, 0]), np.zeros(3))
    obs = Observation(0.0, g, g, (w,))
    assert obs.wrench() is w and obs.wrench("left") is w
    assert obs.has_sensor("left") and not obs.has_sensor("right")
    with pytest.raises(LookupError):
        obs.wrench("right")
    assert arm_index("right") == 1
    with pytest.raises(InvalidArgumentError):
        arm_index("middle")
