"""Truth checks: did the simulator confirm what a step reported?

After each step of a simulated run, :func:`check_step` compares what the
step reported with the simulator's state (:class:`GroundTruth` only, never
the robot's observations): the result's ``truth`` field of SCENARIO.md,
``{"agrees": bool, "detail": str}``.

What a success claims, and how it is checked:

tension held (A, D)
    The true tension of the span between the gripper and the fixture it is
    taut against (the mean elastic tension of its segments) is there: its
    mean over the step's last ``hold_time`` (0.5 s, what D judges) is within
    :data:`TENSION_TOLERANCE` of the set point (D's own 10 % band plus its
    5 % set-point swing), and every segment of the span is stretched at the
    end. (The weight-compensated tension D controls is the tension along the
    chord, which the span's mean tension is for a shallow sag.)
rotation done (I)
    The cable truly turned by the angle, to within :data:`ANGLE_TOLERANCE`:
    the chord of the span's free straight part, from where it leaves its
    fixture (a peg: the tangent point on the circle the cable keeps round
    it) to where it enters the fingers, projected onto the plane normal to
    the axis, sampled every 10 control periods (a rotation turns at most
    0.04 rad in between, far below the half turn that unwrapping needs). Not
    the direction of the cable's middle, which on a soft cable bows behind a
    moving gripper by several degrees, nor the direction to the tool centre
    point, which a cable leaving through a fingertip misses by up to
    atan(20 mm / span).
clipped (C, F)
    The cable sits in the clip's jaws (:meth:`GroundTruth.clipped`).
grasped (H)
    The gripper truly holds the cable.
the model (every successful step)
    Each trusted contact estimate of the model (a contact or fixed point
    whose filter std is at most the estimator's ``trusted_std``, 10 mm: the
    estimates the robot acts on) is within tolerance of the true contact it
    stands for: :data:`CONTACT_TOLERANCE` (3 mm) for an anchor or a clip,
    the peg's radius + 3 mm for a peg (whose truth is the point on its axis
    nearest the estimate within the band of heights over which the peg
    holds the cable, :meth:`GroundTruth.peg_band`: a winding climbs the peg,
    and the model's point is where the span leaves it). And no point is
    made up: every contact or fixed point of the model stands for a fixture
    the cable truly touches (a point named after a fixture stands for it; an
    unnamed, estimated point for the nearest true contact within
    :data:`ASSOCIATION_RADIUS` that no other point stands for). And every
    peg lies on the side of the cable the model has it on (its wrap's
    sign, else the turn of the model's cable there; :data:`SIDE_TURN`),
    whatever the point's std: a cable that came unwound from a peg while
    the model still has it wound is a wrong model.

A failed step always agrees: a failure with a named cause claims nothing
about the world, so it cannot be false (the detail still says what the
simulator showed). Only successes can disagree: those are the run's
``false_successes``.

Contact consistency (NEES coverage): :class:`FilterWatch` records, at every
contact filter iteration, the contact estimate as the model reports it
(:meth:`ModelEstimator.contact_estimate`: the accepted estimate, a change
under test not counted until accepted, with its reported covariance, the
filter's P plus the line model's systematic error) against the true contact
of the span the filter observes: an anchor, a clip's exit, a peg's axis
point at the cable's height for a round estimate, or where the cable leaves
the peg for a point estimate. A sample counts once the model trusts the
estimate (the robot acts on it: std within ``trusted_std`` on the axes that
matter, near its design); it is consistent when the error is within 3
reported std on every axis (per axis; :attr:`FilterSample.nees` gives the
3-D NEES).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from tautwire.model import PathGraph
from tautwire.model.sag_length import sag_excess_length
from tautwire.model.vector3 import nearest_on_segment
from tautwire.primitives import PrimitiveContext
from tautwire.robot import Arm
from tautwire.sim.ground_truth import GroundTruth, TautSpan, closest_on_polyline

FloatArray = NDArray[np.float64]
#: The largest std [m] of an estimate the robot trusts: one number, or the
#: model's rule per point (:meth:`ModelEstimator.trust_limit`).
TrustLimit = float | Callable[[Any], float]

#: Tolerance [m] of a contact estimate: for an anchor or a clip; a peg adds its radius.
CONTACT_TOLERANCE = 0.003
#: Smallest turn [rad] of the model's cable at a peg (or of its wrap) that
#: says which side of the cable the peg is on.
SIDE_TURN = math.radians(10.0)
#: Largest height difference [m] from where a peg holds the cable of the
#: cable's vertices that tell which side of it the peg is on.
SIDE_HEIGHT = 0.01
#: An unnamed model point further [m] from every free true contact stands for none.
ASSOCIATION_RADIUS = 0.03
#: Allowed relative error of the true mean tension against the set point.
TENSION_TOLERANCE = 0.15
#: Window [s] over which the true tension is averaged (D's hold time).
TENSION_WINDOW = 0.5
#: Allowed error [rad] of the true angle turned against the commanded one.
ANGLE_TOLERANCE = 0.1
#: Window [s] over which a step's end shows whether the cable slides round a peg (one swing
#: of D's set point).
STIFFNESS_WINDOW = 2.0
#: Control periods between two samples of the true span direction.
DIRECTION_EVERY = 10
#: The world's vertical (pegs stand along it).
Z_AXIS = np.array([0.0, 0.0, 1.0])
#: Primitives whose success claims a tension (letters).
TENSION_PRIMITIVES = ("A", "D")
#: Primitives whose success claims a clipped cable (letters).
CLIP_PRIMITIVES = ("C", "F")


@dataclass(frozen=True)
class TruthCheck:
    """Whether the simulator agrees with a step's outcome (SCENARIO.md ``truth``).

    Attributes:
        agrees: True unless the step reported a success the simulator denies.
        detail: What was checked and what the simulator showed.
    """

    agrees: bool
    detail: str

    def to_dict(self) -> dict[str, Any]:
        """``{"agrees": bool, "detail": str}``."""
        return {"agrees": self.agrees, "detail": self.detail}


@dataclass(frozen=True)
class ContactCheck:
    """One contact or fixed point of the model against the truth.

    Attributes:
        label: The point's label (a fixture name, or ``"estimated"``).
        fixture: The fixture the point stands for; None if it stands for
            no real contact (made up).
        fixture_type: ``"anchor"``, ``"peg"`` or ``"clip"`` (None if made up).
        estimate: The model's position [m].  # (3,)
        truth: The true contact [m] (None if made up).  # (3,)
        error: Distance [m] from the true contact (None if made up).
        tolerance: Allowed error [m] (None if made up).
        std: sqrt(diag(covariance)) [m], None for a design point without one.  # (3,)
        trusted: Whether the robot trusts the estimate (std at most trusted_std).
        reason: Why the point is made up ("" otherwise).
        cable: The cable whose model holds the point ("" when not said).
        side: For a peg, the side of the cable the model has it on
            (``"left"``/``"right"`` along the cable from its start; ""
            where the model's cable turns by less than :data:`SIDE_TURN`).
        true_side: The side of the cable the peg truly is on ("" unknown).
    """

    label: str
    fixture: str | None
    fixture_type: str | None
    estimate: FloatArray
    truth: FloatArray | None
    error: float | None
    tolerance: float | None
    std: FloatArray | None
    trusted: bool
    reason: str = ""
    cable: str = ""
    side: str = ""
    true_side: str = ""

    @property
    def wrong_side(self) -> bool:
        """Whether the model has the cable round the peg on the other side than it is."""
        return bool(self.side and self.true_side and self.side != self.true_side)

    @property
    def made_up(self) -> bool:
        """Whether the point stands for no real contact."""
        return self.fixture is None

    @property
    def within(self) -> bool:
        """Whether the point is within tolerance of the contact it stands for."""
        return (
            self.error is not None and self.tolerance is not None and self.error <= self.tolerance
        )

    def text(self) -> str:
        """One phrase for a reader."""
        if self.made_up:
            return f"{self.label} at {_mm(self.estimate)} is made up ({self.reason})"
        assert self.error is not None and self.tolerance is not None
        std = "" if self.std is None else f", std {1e3 * float(np.max(self.std)):.1f} mm"
        side = (
            f"; the cable truly passes it on its {self.true_side}, the model on its {self.side}"
            if self.wrong_side
            else ""
        )
        return (
            f"{self.label}: {1e3 * self.error:.1f} mm from the true {self.fixture_type} "
            f"{self.fixture} (tolerance {1e3 * self.tolerance:.1f} mm{std}){side}"
        )


def _mm(p: FloatArray) -> str:
    return "(" + ", ".join(f"{1e3 * float(v):.0f}" for v in p) + ") mm"


def contact_tolerance(truth: GroundTruth, fixture: str) -> float:
    """Allowed error [m] of an estimate of ``fixture``: 3 mm, plus the radius for a peg."""
    if truth.fixture_type(fixture) == "peg":
        return CONTACT_TOLERANCE + truth.peg_radius(fixture)
    return CONTACT_TOLERANCE


def true_contacts(truth: GroundTruth, cable: str) -> dict[str, FloatArray]:
    """The true contact point [m] of every fixture ``cable`` touches, by fixture name.

    A clip that holds the cable in its jaws (:meth:`GroundTruth.clipped`)
    counts even where the cable lies in its seat unloaded, touching none of
    its geoms (F and C lift back to leave it so); its point is then the
    cable's point nearest the seat. A peg that the cable lies against
    within a millimetre of its surface counts too, at that height
    (:meth:`GroundTruth.against_peg`: a released cable falling down a peg).
    """
    out = {c.fixture: c.point for c in truth.contacts() if c.cable == cable}
    for name in truth.fixture_names():
        if name in out:
            continue
        kind = truth.fixture_type(name)
        if kind == "clip" and truth.clipped(name, cable):
            out[name] = truth.seat(name, cable)
        elif kind == "peg":
            point = truth.against_peg(name, cable)
            if point is not None:
                out[name] = point
    return out


def check_contacts(
    graph: PathGraph, truth: GroundTruth, cable: str, trusted_std: TrustLimit
) -> list[ContactCheck]:
    """Every contact and fixed point of ``graph`` against the true contacts of ``cable``.

    Points named after a fixture stand for it (made up if the cable does not
    touch it). Each unnamed point, nearest first, stands for the nearest
    true contact within :data:`ASSOCIATION_RADIUS` that no other point
    stands for, else it is made up.

    Args:
        graph: The model.
        truth: The simulator's truth.
        cable: The cable the model is of.
        trusted_std: Largest std [m] of an estimate the robot acts on, or the
            model's rule per point (:meth:`ModelEstimator.trust_limit`).
    """
    real = true_contacts(truth, cable)
    fixtures = set(truth.fixture_names())
    claimed: set[str] = set()
    checks: list[ContactCheck | None] = []
    unnamed: list[int] = []
    points = [p for p in graph.points if p.kind in ("contact", "fixed")]
    for k, pt in enumerate(points):
        if pt.label in fixtures:
            checks.append(_check(truth, pt.label, pt, real, trusted_std, claimed, cable))
        else:
            checks.append(None)
            unnamed.append(k)

    def nearest(k: int) -> tuple[float, str | None]:
        best: tuple[float, str | None] = (math.inf, None)
        for name, point in real.items():
            if name not in claimed:
                d = float(np.linalg.norm(points[k].position - point))
                best = min(best, (d, name), key=lambda b: b[0])
        return best

    while unnamed:
        k = min(unnamed, key=lambda j: nearest(j)[0])
        unnamed.remove(k)
        d, name = nearest(k)
        if name is not None and d <= ASSOCIATION_RADIUS:
            checks[k] = _check(truth, name, points[k], real, trusted_std, claimed, cable)
        else:
            where = "no true contact left" if name is None else f"{1e3 * d:.0f} mm from {name}"
            checks[k] = _made_up(
                points[k], trusted_std, f"the nearest free true contact is {where}"
            )
    polyline = truth.polyline(cable)
    out: list[ContactCheck] = []
    for pt, c in zip(points, checks, strict=True):
        assert c is not None
        if c.fixture_type == "peg" and c.truth is not None:
            c = replace(c, side=model_side(graph, pt), true_side=peg_side(polyline, c.truth))
        out.append(replace(c, cable=cable))
    return out


def model_side(graph: PathGraph, point: Any) -> str:
    """The side of the cable the model has ``point`` (a peg's) on: its wrap, else its turn.

    ``"left"`` or ``"right"`` along the cable from its start; "" where the
    model's cable turns by less than :data:`SIDE_TURN` there (or the point
    has no neighbour on either side).
    """
    if point.wrap is not None:
        if abs(point.wrap) < SIDE_TURN:
            return ""
        return "left" if point.wrap > 0.0 else "right"
    k = next((i for i, p in enumerate(graph.points) if p is point), None)
    if k is None or k == 0 or k == len(graph.points) - 1:
        return ""
    a = point.position[:2] - graph.points[k - 1].position[:2]
    b = graph.points[k + 1].position[:2] - point.position[:2]
    na, nb = float(np.hypot(*a)), float(np.hypot(*b))
    if na < 1e-9 or nb < 1e-9:
        return ""
    cross = float(a[0] * b[1] - a[1] * b[0]) / (na * nb)
    dot = float(a @ b) / (na * nb)
    if abs(math.atan2(cross, dot)) < SIDE_TURN:
        return ""
    return "left" if cross > 0.0 else "right"


def peg_side(polyline: FloatArray, axis: FloatArray) -> str:
    """The side of the cable (``"left"``/``"right"`` along it from its start) a peg is on.

    Seen at the cable's vertex nearest the peg's axis (horizontally) among
    those within :data:`SIDE_HEIGHT` of the height of ``axis`` (the point
    on the axis where the peg holds the cable): the shipped harness's W2,
    wound round P2 at 86 mm, has its tail lying on the table round P2's
    foot the other way.
    """
    flat = polyline[:, :2] - axis[:2]
    d = np.hypot(flat[:, 0], flat[:, 1])
    level = np.abs(polyline[:, 2] - axis[2]) <= SIDE_HEIGHT
    i = int(np.argmin(np.where(level, d, np.inf))) if level.any() else int(np.argmin(d))
    lo, hi = max(i - 1, 0), min(i + 1, len(polyline) - 1)
    t = polyline[hi] - polyline[lo]
    r = axis - polyline[i]
    return "left" if float(t[0] * r[1] - t[1] * r[0]) > 0.0 else "right"


def _std(covariance: FloatArray | None) -> FloatArray | None:
    if covariance is None:
        return None
    out: FloatArray = np.sqrt(np.maximum(np.diag(covariance), 0.0))
    return out


def _limit(trusted_std: TrustLimit, pt: Any) -> float:
    """The largest std [m] at which the robot trusts ``pt``: a number, or its model's rule."""
    return float(trusted_std(pt)) if callable(trusted_std) else float(trusted_std)


def _made_up(pt: Any, trusted_std: TrustLimit, reason: str) -> ContactCheck:
    std = _std(pt.covariance)
    trusted = std is not None and float(np.max(std)) <= _limit(trusted_std, pt)
    return ContactCheck(
        pt.label, None, None, pt.position.copy(), None, None, None, std, trusted, reason
    )


def _check(
    truth: GroundTruth,
    name: str,
    pt: Any,
    real: dict[str, FloatArray],
    trusted_std: TrustLimit,
    claimed: set[str],
    cable: str,
) -> ContactCheck:
    if name not in real:
        return _made_up(pt, trusted_std, f"the cable does not touch {name}")
    if name in claimed:
        return _made_up(pt, trusted_std, f"another point already stands for {name}")
    claimed.add(name)
    std = _std(pt.covariance)
    trusted = std is not None and float(np.max(std)) <= _limit(trusted_std, pt)
    t = real[name]
    if truth.fixture_type(name) == "clip":
        # the cable runs straight through the slot: its point there nearest the
        # estimate (F and C put the clip's point at its seat; the lines meet at
        # the slot's end the cable leaves by)
        seat = truth.seat(name, cable)
        entry = seat + (seat - t)
        t = nearest_on_segment(pt.position, entry, t)
    elif truth.fixture_type(name) == "peg":
        # a peg holds the cable over a band of heights (a winding climbs it):
        # its axis point there nearest the estimate
        band = truth.peg_band(name, cable)
        if band is not None:
            t = t.copy()
            t[2] = min(max(float(pt.position[2]), band[0]), band[1])
    return ContactCheck(
        pt.label,
        name,
        truth.fixture_type(name),
        pt.position.copy(),
        t.copy(),
        float(np.linalg.norm(pt.position - t)),
        contact_tolerance(truth, name),
        std,
        trusted,
    )


def judge_model(checks: list[ContactCheck]) -> TruthCheck:
    """Agrees when the model makes nothing up and has every contact right.

    Every trusted estimate is within tolerance, and every peg is on the side
    of the cable the model has it on (whatever its std: the route the robot
    plans on depends on it).
    """
    made_up = [c for c in checks if c.made_up]
    wrong = [c for c in checks if not c.made_up and ((c.trusted and not c.within) or c.wrong_side)]
    if made_up or wrong:
        return TruthCheck(
            False, "the model is wrong: " + "; ".join(c.text() for c in made_up + wrong)
        )
    trusted = [c for c in checks if c.trusted]
    if not trusted:
        return TruthCheck(True, "no trusted contact estimate, none made up")
    return TruthCheck(True, "; ".join(c.text() for c in trusted))


def _direction(span: TautSpan, axis: FloatArray, round_contact: bool) -> FloatArray | None:
    """Unit direction of the span's free straight part towards the gripper, normal to ``axis``.

    The chord from where the span leaves its fixture to where it enters the
    fingers (:attr:`TautSpan.entry`): the direction the taut cable takes, a
    soft cable's bow behind a moving gripper aside (a chord between two
    points of the cable does not bow), and the one the force at the fingers
    measures. From an anchor (or a clip) it starts at the contact; from a
    peg at the tangent point, seen from the entry vertex, on the circle the
    cable keeps about the peg's axis (its radius measured at the vertex where
    the cable leaves the peg). None without a contact.
    """
    if span.contact is None:
        return None
    start = span.contact
    if round_contact:
        start = _tangent_point(span.entry, span.contact, span.leave, axis)
    d = span.entry - start
    d = d - axis * float(axis @ d)
    n = float(np.linalg.norm(d))
    if n < 1e-6:
        return None
    out: FloatArray = d / n
    return out


def _tangent_point(
    held: FloatArray,
    centre: FloatArray,
    leave: FloatArray,
    axis: FloatArray,
    radius: float | None = None,
) -> FloatArray:
    """The tangent point from ``held`` (any point) on a circle about ``centre``.

    The circle lies in the plane normal to ``axis``, with ``radius`` (default:
    through ``leave``); of the two tangent points the one nearer ``leave`` is
    taken.
    """

    def planar(v: FloatArray) -> FloatArray:
        out: FloatArray = v - axis * float(axis @ v)
        return out

    g, r_leave = planar(held - centre), planar(leave - centre)
    if radius is None:
        radius = float(np.linalg.norm(r_leave))
    dist = float(np.linalg.norm(g))
    if dist <= radius or radius < 1e-9:
        return leave.copy()
    u = g / dist
    w = np.cross(axis, u)
    beta = math.acos(radius / dist)
    candidates = [
        centre + radius * (math.cos(beta) * u + sign * math.sin(beta) * w) for sign in (1.0, -1.0)
    ]
    best: FloatArray = min(candidates, key=lambda c: float(np.linalg.norm(planar(c - leave))))
    return best


class StepWatch:
    """Samples the truth of one step while it runs (cheaply, every control period).

    Every control period the true mean tension of the gripper's span; every
    :data:`DIRECTION_EVERY` periods the span itself (its fixture, vertices
    and direction), from which the true angle it turned about ``axis``.

    Args:
        truth: The simulator's truth.
        cable: The cable the step works on.
        arm: The gripper that holds it.
        axis: Rotation axis (world frame) to measure the angle turned about;
            None: do not measure it.  # (3,)
    """

    def __init__(
        self, truth: GroundTruth, cable: str, arm: Arm, axis: FloatArray | None = None
    ) -> None:
        self.truth = truth
        self.cable = cable
        self.arm: Arm = arm
        self.axis = (
            None if axis is None else np.asarray(axis, dtype=float) / float(np.linalg.norm(axis))
        )
        self.times: list[float] = []
        self.tensions: list[float] = []
        self.taut: list[bool] = []
        #: The span's elastic length [m] with each tension sample: the chord
        #: from where it leaves its fixture (a peg: the tangent point on the
        #: circle of peg + cable radius) to the tool centre point, plus the
        #: length its sag takes (:func:`sag_excess_length`).
        self.lengths: list[float] = []
        self.turned = 0.0
        self.span: TautSpan | None = None
        #: The robot's stiffness estimate k_hat [N/m] when the step ended.
        self.k_hat: float | None = None
        self._ticks = 0
        self._previous: FloatArray | None = None
        self._rho = truth.mass_per_length(cable)
        self._peg_radius: float | None = None
        self._start = np.zeros(3)
        self._sample_span()

    def _sample_span(self) -> None:
        self.span = self.truth.span(self.cable, self.arm)
        if self.span is None:
            return
        fixture = self.span.fixture
        round_contact = fixture is not None and self.truth.fixture_type(fixture) == "peg"
        self._peg_radius = (
            self.truth.peg_radius(fixture) + self.truth.cable_radius(self.cable)
            if round_contact and fixture is not None
            else None
        )
        self._start = self.span.leave
        if self.axis is None:
            return
        d = _direction(self.span, self.axis, round_contact)
        if d is None:
            return
        if self._previous is not None:
            cross = float(self.axis @ np.cross(self._previous, d))
            self.turned += math.atan2(cross, float(self._previous @ d))
        self._previous = d

    def tick(self, time: float, resample: bool = False) -> None:
        """Record the truth after one control period ending at ``time`` [s].

        The span itself is sampled every :data:`DIRECTION_EVERY` periods, or
        now with ``resample`` (the contact filter just ran).
        """
        self._ticks += 1
        if resample or self._ticks >= DIRECTION_EVERY:
            self._ticks = 0
            self._sample_span()
        if self.span is None:
            return
        self._record(time)

    def _record(self, time: float) -> None:
        assert self.span is not None
        tension, taut = self.truth.span_tension(self.span)
        self.times.append(time)
        self.tensions.append(tension)
        self.taut.append(taut)
        tcp = self.truth.gripper_position(self.arm)
        start = self._start
        if self._peg_radius is not None and self.span.contact is not None:
            # a smooth tangent point (the leave point jumps as vertices pass the peg)
            start = _tangent_point(
                tcp, self.span.contact, self.span.leave, Z_AXIS, self._peg_radius
            )
        chord = tcp - start
        self.lengths.append(
            math.sqrt(float(chord @ chord)) + sag_excess_length(chord, tension, self._rho)
        )

    def finish(self) -> None:
        """Take the last sample (the step's end state)."""
        self._sample_span()
        if self.span is not None:
            self._record(self.times[-1] if self.times else 0.0)

    def measured_stiffness(self, window: float = STIFFNESS_WINDOW) -> float | None:
        """The spring constant [N/m] the gripper truly pulls against at the step's end.

        The least-squares slope of the span's true tension against its true
        elastic length (:attr:`lengths`) over the step's last ``window`` [s]
        of taut samples: D swings its set point by +-5 % with a 2 s period,
        so the window holds one whole swing. What k_hat claims, measured:
        from an anchor it is k L / L_s; round a peg the cable slides, sticks
        or both as its friction (0.2) and the bend decide, and the contact
        gives a little, so no closed form holds there. None with fewer than
        50 samples or under 20 um of swing.
        """
        if not self.times:
            return None
        end = self.times[-1]
        picked = [
            (length, f)
            for t, f, length, taut in zip(
                self.times, self.tensions, self.lengths, self.taut, strict=True
            )
            if t >= end - window and taut
        ]
        if len(picked) < 50:
            return None
        x = np.array([p[0] for p in picked])
        y = np.array([p[1] for p in picked])
        if float(np.ptp(x)) < 2e-5:
            return None
        slope = float(np.polyfit(x, y, 1)[0])
        return slope if slope > 0.0 else None

    def mean_tension(self, window: float = TENSION_WINDOW) -> float | None:
        """Mean true span tension [N] over the last ``window`` [s], None without samples."""
        if not self.tensions:
            return None
        end = self.times[-1]
        recent = [f for t, f in zip(self.times, self.tensions, strict=True) if t >= end - window]
        return float(np.mean(recent))

    @property
    def edge_stiffness(self) -> float | None:
        """The nominal spring constant [N/m] of the span, k L / L_s (None without a span).

        L_s is the span's rest length from where it leaves its fixture (an
        anchor; where it touches a peg) to the held vertex: exact from an
        anchor; round a peg it holds only while the cable sticks there (see
        :meth:`measured_stiffness`).
        """
        span = self.span
        if span is None or span.contact is None or span.rest_length <= 0.0:
            return None
        length = float(self.truth.arc_lengths(self.cable)[-1])
        return self.truth.stiffness(self.cable) * length / span.rest_length


def check_step(
    letter: str,
    params: dict[str, Any],
    success: bool,
    watch: StepWatch,
    ctx: PrimitiveContext,
    truth: GroundTruth,
    primitive: str = "",
) -> TruthCheck:
    """The truth of one finished step (see the module docstring).

    Args:
        letter: The primitive's letter ("" for moves without one).
        params: The step's parameters (``force``, ``angle``, ``clip``, ``arm``).
        success: Whether the step reported success.
        watch: The step's :class:`StepWatch`, finished.
        ctx: The primitives' context after the step (the model).
        truth: The simulator's truth.
        primitive: The primitive's name (tells the moves ``move`` and
            ``release`` apart).
    """
    parts: list[str] = []
    agrees = True
    if primitive == "release":
        held = truth.held(watch.arm)
        ok = held is None
        agrees &= ok
        parts.append(
            f"the {watch.arm} gripper truly "
            + ("let go" if ok else f"still holds {held[0] if held else ''}")
        )
    if primitive == "move" and params.get("taut", True) and watch.span is not None:
        ok = bool(watch.taut[-1]) if watch.taut else False
        agrees &= ok
        parts.append(
            f"the cable is {'' if ok else 'not '}taut at the end of the move "
            f"(true tension {watch.tensions[-1] if watch.tensions else 0.0:.2f} N)"
        )
    if letter in TENSION_PRIMITIVES and "force" in params:
        ok, text = _tension_truth(float(params["force"]), watch)
        agrees &= ok
        parts.append(text)
    if letter == "I" and watch.axis is not None:
        ok, text = _rotation_truth(float(params["angle"]), watch)
        agrees &= ok
        parts.append(text)
    if letter in CLIP_PRIMITIVES and "clip" in params:
        clip = str(params["clip"])
        ok = truth.clipped(clip, watch.cable)
        agrees &= ok
        parts.append(f"the cable is {'' if ok else 'not '}in the jaws of {clip}")
    if letter == "H":
        held = truth.held(watch.arm)
        ok = held is not None and held[0] == watch.cable
        agrees &= ok
        parts.append(f"the {watch.arm} gripper {'holds' if ok else 'does not hold'} {watch.cable}")
    model = judge_model(check_contacts(ctx.graph, truth, watch.cable, ctx.estimator.trust_limit))
    agrees &= model.agrees
    parts.append(model.detail)
    detail = "; ".join(parts)
    if not success:
        return TruthCheck(True, f"a failure claims nothing; the simulator showed: {detail}")
    return TruthCheck(agrees, detail)


def _tension_truth(force: float, watch: StepWatch) -> tuple[bool, str]:
    mean = watch.mean_tension()
    if mean is None or watch.span is None:
        return False, "the gripper holds no cable"
    taut = bool(watch.taut[-1]) if watch.taut else False
    error = abs(mean - force) / force
    ok = taut and error <= TENSION_TOLERANCE
    against = watch.span.fixture or "no fixture (the other gripper or a free end)"
    return ok, (
        f"true tension {mean:.2f} N against {against} (set point {force:.2f} N, "
        f"{100 * error:.0f} % off, tolerance {100 * TENSION_TOLERANCE:.0f} %), "
        f"{'taut' if taut else 'not taut'}"
    )


def _rotation_truth(angle: float, watch: StepWatch) -> tuple[bool, str]:
    ok = abs(watch.turned - angle) <= ANGLE_TOLERANCE
    return ok, (
        f"the cable truly turned {math.degrees(watch.turned):.0f} deg "
        f"(asked {math.degrees(angle):.0f} deg, tolerance {math.degrees(ANGLE_TOLERANCE):.0f} deg)"
    )


@dataclass(frozen=True)
class FilterSample:
    """The contact filter's estimate at one iteration against the truth.

    Attributes:
        time: Simulator time [s].
        iteration: The filter iteration.
        fixture: The fixture the observed span leaves from (None: none).
        round: Whether the filter estimates a round contact's axis.
        estimate: The filter's estimate [m].  # (3,)
        truth: What it estimates, truly [m]: the anchor, the clip's exit, a
            peg's axis point at the cable's height (round) or the point where
            the cable leaves the peg (a point estimate).  # (3,)
        std: sqrt(diag(P)) [m].  # (3,)
        trusted: Whether the largest std is at most the estimator's trusted_std.
        covariance: The filter's P [m^2].  # (3, 3)
    """

    time: float
    iteration: int
    fixture: str | None
    round: bool
    estimate: FloatArray
    truth: FloatArray
    std: FloatArray
    trusted: bool
    covariance: FloatArray | None = None

    @property
    def nees(self) -> float | None:
        """The 3-D normalised estimation error squared e' P^-1 e (None without P)."""
        if self.covariance is None:
            return None
        e = self.estimate - self.truth
        try:
            return float(e @ np.linalg.solve(self.covariance, e))
        except np.linalg.LinAlgError:
            return None

    @property
    def error(self) -> float:
        """Distance [m] of the estimate from the truth."""
        return float(np.linalg.norm(self.estimate - self.truth))

    @property
    def within_3std(self) -> bool:
        """Whether the error is within 3 reported std on every axis."""
        return bool(np.all(np.abs(self.estimate - self.truth) <= 3.0 * self.std))


def _peg_leave_point(span: TautSpan, axis_point: FloatArray) -> FloatArray:
    """Where the straight span, extended, is tangent to the peg's circle [m].

    The circle is the one the cable's centre line keeps about the axis (its
    radius measured at the vertex where the cable leaves the peg), at the
    axis point's height.
    """
    u = span.middle - span.leave
    u[2] = 0.0
    un = float(np.linalg.norm(u))
    radial = span.leave - axis_point
    radial[2] = 0.0
    radius = float(np.linalg.norm(radial))
    if un < 1e-9 or radius < 1e-9:
        return axis_point.copy()
    u /= un
    n = radial - u * float(u @ radial)
    nn = float(np.linalg.norm(n))
    if nn < 1e-9:
        return axis_point.copy()
    out: FloatArray = axis_point + radius * n / nn
    return out


@dataclass
class FilterWatch:
    """Records the contact filter against the truth at each of its iterations.

    Args:
        truth: The simulator's truth.
        cable: The cable of the context's model.
        arm: Its sensing gripper.
    """

    truth: GroundTruth
    cable: str
    arm: Arm
    samples: list[FilterSample] = field(default_factory=list)
    _iterations: int = 0

    def ran(self, ctx: PrimitiveContext) -> bool:
        """Whether the contact filter ran since the last sample."""
        return ctx.estimator.iterations != self._iterations

    def tick(self, ctx: PrimitiveContext, time: float, span: TautSpan | None = None) -> None:
        """Sample if the filter ran since the last call, against ``span`` (default: sampled now)."""
        estimator = ctx.estimator
        if estimator.iterations == self._iterations:
            return
        self._iterations = estimator.iterations
        # the estimate as the model reports it (a change under test does not
        # count until accepted), with its reported covariance
        estimate = estimator.contact_estimate()
        if estimate is None:
            return
        if span is None:
            span = self.truth.span(self.cable, self.arm)
        if span is None or span.fixture is None or span.contact is None:
            return
        true_point = span.contact
        if self.truth.fixture_type(span.fixture) == "peg" and estimate.radius is None:
            true_point = _peg_leave_point(span, span.contact)
        std = np.sqrt(np.maximum(np.diag(estimate.covariance), 0.0))
        self.samples.append(
            FilterSample(
                time,
                estimator.iterations,
                span.fixture,
                estimate.radius is not None,
                estimate.position,
                np.asarray(true_point, dtype=float).copy(),
                std,
                estimate.trusted,
                estimate.covariance,
            )
        )


def coverage(samples: list[FilterSample]) -> tuple[int, float | None]:
    """(converged samples, the fraction of them within 3 std on every axis)."""
    converged = [s for s in samples if s.trusted]
    if not converged:
        return 0, None
    return len(converged), sum(1 for s in converged if s.within_3std) / len(converged)


class RunAudit:
    """The truth of a whole run: one :class:`StepWatch` per step, the filters' samples.

    ``run_scenario`` calls :meth:`start_step` before each step, :meth:`tick`
    every control period, :meth:`end_step` after the step and
    :meth:`finish` after the last. Each step is watched on its own cable and
    gripper; each sensing context's contact filter has its own
    :class:`FilterWatch`.

    Args:
        truth: The simulator's truth.
        cable: The cable a step works on when it does not say (the first).
        arm: The gripper a step watches when it does not say.
    """

    def __init__(self, truth: GroundTruth, cable: str, arm: Arm) -> None:
        self.truth = truth
        self.cable = cable
        self.arm: Arm = arm
        #: One filter watch per (cable, sensing arm).
        self.filters: dict[tuple[str, Arm], FilterWatch] = {}
        self.watches: list[StepWatch] = []
        self.checks: list[TruthCheck] = []
        self.successes: list[bool] = []
        #: The final models' contact and fixed points against the truth (all cables).
        self.contacts: list[ContactCheck] = []
        self._step: tuple[str, dict[str, Any], str] | None = None

    @property
    def filter(self) -> FilterWatch:
        """The filter watch of the default cable's sensing gripper."""
        return self._filter(self.cable, self.arm)

    def _filter(self, cable: str, arm: Arm) -> FilterWatch:
        key = (cable, arm)
        if key not in self.filters:
            self.filters[key] = FilterWatch(self.truth, cable, arm)
        return self.filters[key]

    def start_step(
        self,
        letter: str,
        params: dict[str, Any],
        cable: str | None = None,
        arm: Arm | None = None,
        primitive: str = "",
    ) -> StepWatch:
        """Start watching a step of primitive ``letter`` with ``params``.

        Args:
            letter: The primitive's letter ("" for a move).
            params: Its parameters.
            cable: The cable it works on (default the audit's).
            arm: The gripper that senses it, watched when the step names
                no arm (default the audit's).
            primitive: The primitive's name.
        """
        default: Arm = self.arm if arm is None else arm
        named = params.get("arm", default)
        axis = params.get("axis", (0.0, 0.0, 1.0)) if letter == "I" else None
        watched: Arm = named if named in ("left", "right") else default
        watch = StepWatch(
            self.truth,
            self.cable if cable is None else cable,
            watched,
            None if axis is None else np.asarray(axis, dtype=float),
        )
        self.watches.append(watch)
        self._step = (letter, dict(params), primitive)
        return watch

    def tick(self, ctx: PrimitiveContext) -> None:
        """Sample the truth after a control period (at the simulator's time)."""
        time = self.truth.time
        cable = self.watches[-1].cable if self.watches else self.cable
        watch_filter = self._filter(cable, ctx.arm)
        ran = watch_filter.ran(ctx)
        if self.watches:
            watch = self.watches[-1]
            watch.tick(time, resample=ran)  # the filter's sample shares the span just taken
            if ran:
                span = watch.span if watch.arm == ctx.arm else None
                watch_filter.tick(ctx, time, span)
                return
        watch_filter.tick(ctx, time)

    def end_step(self, success: bool, ctx: PrimitiveContext) -> TruthCheck:
        """Check the step that just ended (it reported ``success``) on its context ``ctx``."""
        assert self._step is not None, "end_step without start_step"
        letter, params, primitive = self._step
        watch = self.watches[-1]
        watch.finish()
        k_hat = ctx.estimator.elasticity.k_hat
        watch.k_hat = float(k_hat) if math.isfinite(k_hat) else None
        check = check_step(letter, params, success, watch, ctx, self.truth, primitive)
        self.checks.append(check)
        self.successes.append(success)
        self._step = None
        return check

    def finish(self, ctx: PrimitiveContext, graphs: dict[str, PathGraph] | None = None) -> None:
        """Check the final models: ``graphs`` by cable (default ``ctx``'s, the audit's cable)."""
        models = {self.cable: ctx.graph} if graphs is None else graphs
        trusted_std = ctx.estimator.trust_limit
        self.contacts = [
            c
            for cable, graph in models.items()
            for c in check_contacts(graph, self.truth, cable, trusted_std)
        ]

    @property
    def false_successes(self) -> int:
        """Steps that reported success while the simulator disagrees."""
        return sum(
            1 for s, c in zip(self.successes, self.checks, strict=True) if s and not c.agrees
        )

    @property
    def samples(self) -> list[FilterSample]:
        """The contact filters against the truth, one sample per iteration of each."""
        return [s for w in self.filters.values() for s in w.samples]

    def consistency(self) -> dict[str, Any]:
        """The NEES coverage of the run: converged samples and the fraction within 3 std."""
        n, within = coverage(self.samples)
        return {
            "samples": n,
            "within_3std": within,
            "definition": "contact filter iterations whose largest std is at most the "
            "estimator's trusted_std; error within 3 reported std on every axis",
        }


# ------------------------------------------------------------- model scores

#: Arc length [m] between two samples of a modelled cable (shape_error).
SHAPE_STEP = 0.005


@dataclass(frozen=True)
class PointDeviation:
    """One feature point of a model against the true point it stands for.

    Attributes:
        cable: The cable.
        label: The point's label (a fixture's name, an arm, ``estimated``).
        stands_for: What it stands for: a fixture's name or ``gripper <arm>``.
        horizontal: Horizontal (x-y) distance [m] from the true point.
        vertical: Vertical distance [m] from the true point.
    """

    cable: str
    label: str
    stands_for: str
    horizontal: float
    vertical: float


def point_deviations(
    graph: PathGraph, truth: GroundTruth, cable: str, trusted_std: float = 0.01
) -> list[PointDeviation]:
    """Each point of ``cable``'s model that stands for a fixture or a gripper, against it.

    A gripper's point against its true tool centre point; a contact or
    fixed point against the true point of the fixture it stands for, as the
    step's truth check has it (:func:`check_contacts`): an anchor, a peg's
    axis point within the band of heights it holds the cable over, for a
    clip the cable's point in its slot nearest the model's (the clipping
    primitives put it at the seat, the force's lines meet at the slot's end
    the cable leaves by: both stand for the clip; scored against the seat, a
    point at the slot's end read 15 mm off on random board 635178977). A
    made-up point stands for nothing and is left out (the step's truth
    counts it).
    """
    out: list[PointDeviation] = []
    for pt in graph.points:
        if pt.kind == "gripper" and pt.label in ("left", "right"):
            arm: Arm = "left" if pt.label == "left" else "right"
            d = pt.position - truth.gripper_position(arm)
            out.append(
                PointDeviation(
                    cable, pt.label, f"gripper {pt.label}", float(np.hypot(d[0], d[1])), abs(d[2])
                )
            )
    for c in check_contacts(graph, truth, cable, trusted_std):
        if c.made_up or c.truth is None or c.fixture is None:
            continue
        d = c.estimate - c.truth
        out.append(
            PointDeviation(cable, c.label, c.fixture, float(np.hypot(d[0], d[1])), abs(d[2]))
        )
    return out


def model_samples(graph: PathGraph, step: float = SHAPE_STEP) -> FloatArray:
    """The modelled cable sampled every ``step`` [m] of arc length, shape (K, 3).

    Each edge is its chord lowered by its sag in a parabola
    (equ:catenarySlack: 4 s t (1 - t) below the chord at fraction t of its
    length): a taut edge (sag 0) is straight, a slack edge sags, a free end
    hangs as the constraint map placed it.
    """
    samples: list[FloatArray] = [graph.points[0].position.copy()]
    for i, edge in enumerate(graph.edges):
        a, b = graph.points[i].position, graph.points[i + 1].position
        n = max(1, math.ceil(edge.length / step))
        for k in range(1, n + 1):
            t = k / n
            p = a + t * (b - a)
            p[2] -= 4.0 * edge.sag * t * (1.0 - t)
            samples.append(p)
    return np.array(samples)


def shape_deviations(graph: PathGraph, polyline: FloatArray) -> FloatArray:
    """Horizontal and vertical distance [m] of each model sample from the true cable, (K, 2).

    Each sample (:func:`model_samples`) against the nearest point of the
    true cable's centre line.
    """
    rows = []
    for p in model_samples(graph):
        d = p - closest_on_polyline(polyline, p)
        rows.append((float(np.hypot(d[0], d[1])), abs(float(d[2]))))
    return np.array(rows).reshape(-1, 2)


def deviation_summary(horizontal: list[float], vertical: list[float]) -> dict[str, float] | None:
    """Mean and max [m] of horizontal and vertical deviations (None without any)."""
    if not horizontal:
        return None
    return {
        "horizontal_mean": float(np.mean(horizontal)),
        "horizontal_max": float(np.max(horizontal)),
        "vertical_mean": float(np.mean(vertical)),
        "vertical_max": float(np.max(vertical)),
    }


def route_truth(truth: GroundTruth, cable: str, route: list[tuple[str, str | None]]) -> TruthCheck:
    """Whether ``cable`` truly follows its target ``route``: (fixture, side) in order.

    A clip holds the cable in its jaws (:meth:`GroundTruth.clipped`); the
    cable touches a peg, and the peg lies on the route's side of it (seen
    along the cable from its start, at the vertex nearest the peg's axis).
    Windings are not counted.
    """
    parts: list[str] = []
    agrees = True
    touching = true_contacts(truth, cable)
    pts = truth.polyline(cable)
    for fixture, side in route:
        kind = truth.fixture_type(fixture)
        if kind == "clip":
            ok = truth.clipped(fixture, cable)
            parts.append(f"{fixture}: {'in' if ok else 'not in'} its jaws")
        elif kind == "peg":
            axis = touching.get(fixture)
            if axis is None:
                ok = False
                parts.append(f"{fixture}: not touched")
            else:
                on = peg_side(pts, axis)
                ok = side is None or on == side
                parts.append(f"{fixture}: touched, on the cable's {on}")
        else:
            ok = fixture in touching
            parts.append(f"{fixture}: {'holds' if ok else 'does not hold'} the cable")
        agrees &= ok
    return TruthCheck(agrees, "; ".join(parts) if parts else "no route")
