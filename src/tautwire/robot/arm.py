"""Names of the two arms and their slots in the 12-D task space."""

from typing import Literal

from tautwire.errors import InvalidArgumentError

Arm = Literal["left", "right"]
ARMS: tuple[Arm, Arm] = ("left", "right")


def arm_index(arm: str) -> int:
    """Return 0 for ``"left"`` and 1 for ``"right"``.

    Raises:
        InvalidArgumentError: for any other name.
    """
    if arm == "left":
        return 0
    if arm == "right":
        return 1
    raise InvalidArgumentError(f"arm must be 'left' or 'right', got {arm!r}")
