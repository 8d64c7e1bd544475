"""The error a robot driver raises for a transient loss of communication."""

from tautwire.errors import TautwireError


class RobotCommunicationError(TautwireError):
    """One command or sample did not get through (a lost packet).

    A driver raises it from :meth:`Robot.act` when the command of this
    control period was lost; the robot then keeps applying its previous
    command for the period, as real robot controllers do. It is transient:
    the next call may succeed. A guard survives a single one and ends the
    step with cause ``robot_error`` when they repeat (see
    :class:`tautwire.tasks.robot_guard.RobotGuard`).
    """
