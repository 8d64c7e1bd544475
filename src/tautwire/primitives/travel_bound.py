"""How far a gripper may pull the cable it holds: its slack plus its stretch at the force limit.

The cable between the gripper and the nearest point behind it that holds it
fixed (an anchor, a clip, the other gripper) has a rest length l_0 in the
path graph. Pulled taut, the route there (gripper to contact to ... to the
fixed point) is at most l_0 plus the stretch that the force limit F_max
allows, F_max / k. A gripper further away than that cannot still hold an
intact cable: the cable has slipped through the fingers (or the model of
the route is wrong), and a tensioning primitive that keeps pulling only
drives the gripper out of the workspace.

The stiffness k of that bound errs on the soft side (a larger bound):

* the route's stiffness from the elasticity estimate, k_trusted l_e / l_0
  (the estimate is of the gripper's edge, rest length l_e; the whole route
  has the same EA over a longer length), and
* the secant T / (l - l_0) at the largest tension seen so far: an intact
  cable's tension never falls while the gripper pulls further, so the
  stretch per newton seen at that tension bounds it from then on. Before
  the stiffness fit converges this is what keeps a soft cable (which
  stretches far) from tripping the bound on a stiff prior; after a slip the
  peak stays where it was, so the bound stays too.

A margin (``margin`` + ``relative_margin`` l_0) covers what the model does
not know exactly: a contact estimate a few cm off the design, where the
gripper holds the cable, and the sag the chord still has.
"""

from __future__ import annotations

import math
from collections.abc import Collection
from typing import NamedTuple

from tautwire.errors import InvalidArgumentError
from tautwire.model.vector3 import norm3
from tautwire.primitives.model_estimator import ModelEstimator, TensionState


class TravelBound:
    """The longest route [m] from a gripper to the fixed point behind it.

    Args:
        force_limit: F_max [N], the robot's force limit.
        margin: Absolute margin [m].
        relative_margin: Margin as a fraction of the rest length l_0.
        taut_tension: Least tension [N] at which a stretch is taken as the
            secant's reference.
    """

    def __init__(
        self,
        force_limit: float,
        margin: float = 0.03,
        relative_margin: float = 0.05,
        taut_tension: float = 0.3,
    ) -> None:
        if not (force_limit > 0.0 and math.isfinite(force_limit)):
            raise InvalidArgumentError(f"force_limit must be > 0 N, got {force_limit}")
        if not (margin >= 0.0 and math.isfinite(margin)):
            raise InvalidArgumentError(f"margin must be >= 0 m, got {margin}")
        if not (relative_margin >= 0.0 and math.isfinite(relative_margin)):
            raise InvalidArgumentError(f"relative_margin must be >= 0, got {relative_margin}")
        self.force_limit = float(force_limit)
        self.margin = float(margin)
        self.relative_margin = float(relative_margin)
        self.taut_tension = float(taut_tension)
        self.reset()

    def reset(self) -> None:
        """Forget the peak tension (a new route, e.g. after a regrasp)."""
        self._peak_tension = 0.0
        self._peak_stretch = 0.0
        #: The latest bound [m] (inf before the first update).
        self.allowed = math.inf

    def stiffness(self, k_route: float) -> float:
        """The stiffness [N/m] of the bound: the softer of ``k_route`` and the peak's secant."""
        k = float(k_route)
        if self._peak_tension >= self.taut_tension and self._peak_stretch > 0.0:
            k = min(k, self._peak_tension / self._peak_stretch)
        return k

    def update(self, route: float, rest_length: float, tension: float, k_route: float) -> bool:
        """Add the current route; True if it is longer than an intact cable allows.

        Args:
            route: Length [m] of the modelled route from the gripper to the
                fixed point (through the contact estimates).
            rest_length: Its rest length l_0 [m] in the path graph.
            tension: Tension [N] of the gripper's edge (low-passed).
            k_route: The route's stiffness [N/m] from the elasticity
                estimate (k_trusted l_e / l_0).
        """
        if not all(math.isfinite(v) for v in (route, rest_length, tension, k_route)):
            return False
        stretch = route - rest_length
        if tension > self._peak_tension:
            self._peak_tension, self._peak_stretch = tension, stretch
        k = self.stiffness(k_route)
        extra = self.force_limit / k if k > 0.0 else math.inf
        self.allowed = rest_length * (1.0 + self.relative_margin) + self.margin + extra
        return route > self.allowed


class Route(NamedTuple):
    """The modelled route from a gripper to the fixed point that holds its cable.

    Attributes:
        length: Its length [m] now (gripper to contact estimate to ... to
            the fixed point).
        rest_length: Its rest length l_0 [m] in the path graph.
        edge_rest_length: The rest length [m] of the gripper's own edge.
        through: The clips (graph index, slack [m] before it) the pull
            draws slack through on its way to the fixed point.
    """

    length: float
    rest_length: float
    edge_rest_length: float
    through: tuple[tuple[int, float], ...] = ()

    def stiffness(self, k_edge: float) -> float:
        """The route's stiffness [N/m] from the edge's: the same EA over l_0."""
        return k_edge * self.edge_rest_length / max(self.rest_length, 1e-9)


#: Slack [m] in the model's span behind a clip, beyond its straight length,
#: from which a pull counts as drawing cable through the clip.
SLACK_THROUGH = 0.004


def route_to_fixed_point(
    estimator: ModelEstimator,
    state: TensionState,
    clips: Collection[str] = (),
    through_all: bool = False,
) -> Route | None:
    """The route from the sensing gripper to the nearest point that holds the cable fixed.

    It runs from the gripper through the contact estimate and the model's
    points to an anchor or clip (``fixed``) or the other gripper; None if
    there is none (a free end). ``state`` (the latest update's) gives the
    gripper's span when the contact is the one it was measured against; a
    contact the update has just changed is measured afresh.

    A clip (a fixed point labelled with a name in ``clips``) holds the cable
    across its slot, not along it: where the model's span behind it holds
    more than ``SLACK_THROUGH`` of slack beyond its straight length, the pull
    draws that slack through the clip, and the route runs on, straight, to
    the next constrained point (the near span a parallel clip's release
    leaves loose: random board 1808415002's F5). With ``through_all`` the
    route runs through every clip, slack or not, to the next point that
    truly holds the cable: the pull has drawn slack the model does not
    know of through a clip (D's retake), and the cable between that point
    and the gripper is what bounds its travel.
    """
    graph = estimator.graph
    g = estimator.gripper_index
    c = estimator.contact_index
    if c is None:
        return None
    step = -1 if c < g else 1
    points = graph.points
    s = graph.arc_lengths()
    contact = estimator.contact_position()
    length = state.span
    if contact is not None and norm3(contact - state.contact) > 1e-9:
        length = norm3(points[g].position - contact)
    i = c
    while points[i].kind not in ("fixed", "gripper"):
        j = i + step
        if not 0 <= j < len(points):
            return None
        length += norm3(points[j].position - points[i].position)
        i = j
    through: list[tuple[int, float]] = []
    while points[i].kind == "fixed" and points[i].label in clips:
        j = i + step
        while 0 <= j < len(points) and not points[j].is_constrained:
            j += step
        if not 0 <= j < len(points):
            break
        straight = norm3(points[j].position - points[i].position)
        slack = abs(float(s[i] - s[j])) - straight
        if slack <= SLACK_THROUGH and not through_all:
            break
        through.append((i, max(slack, 0.0)))
        length += straight
        i = j
    return Route(length, abs(float(s[g] - s[i])), abs(float(s[g] - s[c])), tuple(through))
