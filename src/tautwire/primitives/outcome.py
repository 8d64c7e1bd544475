"""How a primitive ends: success, or failure with a named cause."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Status = Literal["running", "success", "failure"]

#: Causes a primitive or the runner may report for a failure.
CAUSES: tuple[str, ...] = (
    "force_limit",  # the measured force exceeded the robot's force limit
    "timeout",  # the success criteria were not met in time
    "slipped",  # the cable left a gripper or the tension vanished unexpectedly
    "not_clipped",  # no snap was felt while pushing into a clip
    "left_fixture",  # the cable left a fixture the model had it at (pulled out of a clip)
    "no_contact",  # no tension could be built: nothing holds the cable
    "precondition",  # the model's state does not allow the primitive (e.g. not held by two)
    "missed",  # a grasp closed on nothing
    "not_aligned",  # the gripper could not be aligned with the cable
    "not_turned",  # a rotation's pull did not turn by the angle asked, even taken up again
    "not_wound",  # a rotation about a peg ended with the model's contact at another point
    "sensor_stale",  # the sensor's data stopped advancing or was unusable for too long
    "sensor_bias",  # the force sensor's bias drifted beyond what the estimates tolerate
    "robot_error",  # the robot failed: repeated lost commands or any other robot exception
    "workspace",  # the primitive kept driving a gripper out of the workspace
    "diverged",  # the simulated world blew up
    "error",  # an exception inside the primitive or the robot
)


@dataclass(frozen=True)
class Outcome:
    """State of a primitive after a step.

    Attributes:
        status: ``running``, ``success`` or ``failure``.
        cause: For a failure, one of :data:`CAUSES`.
        detail: A sentence a reader can act on.
    """

    status: Status = "running"
    cause: str | None = None
    detail: str = ""

    @property
    def done(self) -> bool:
        """Whether the primitive has finished (either way)."""
        return self.status != "running"

    @staticmethod
    def success(detail: str = "") -> Outcome:
        """A successful end."""
        return Outcome("success", None, detail)

    @staticmethod
    def failure(cause: str, detail: str = "") -> Outcome:
        """A failed end with ``cause`` (one of :data:`CAUSES`)."""
        return Outcome("failure", cause, detail)


RUNNING = Outcome()
