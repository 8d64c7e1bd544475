"""A Rerun recording (``.rrd``) of a simulated run: the model over the truth, in time.

Needs the optional extra ``rerun`` (``pip install tautwire[rerun]``). Feed a
:class:`RerunRecorder` from a runner's hooks: :meth:`~RerunRecorder.attach`
(``on_world``: the board, once), :meth:`~RerunRecorder.keep_truth`
(``on_truth``), :meth:`~RerunRecorder.tick` (``on_tick``) and
:meth:`~RerunRecorder.step` (``on_step``); then :meth:`~RerunRecorder.close`.
Every entry is on the timeline ``sim_time`` (the run's simulated time [s]).
Open the file with ``rerun FILE.rrd``.

Entities (lengths in metres, forces in newtons, world frame):

- ``board/fixtures``: the fixtures, coloured and labelled by type (static);
- ``wrench/force/{x,y,z,norm}``, ``wrench/torque/{x,y,z}``: the measured
  wrench, every control period;
- ``tension/{model,set_point,truth}``: the tension the model estimates, its
  set point and the simulator's;
- ``grippers/{left,right}``: the grippers' poses (``Transform3D``);
- ``model/points``, ``model/edges``, ``model/uncertainty``: the path graph
  (points coloured by what holds them, edges as a line strip, each
  estimated point's 3-sigma ellipsoid), every ``model_every`` s;
- ``truth/cable``: the simulated cable's polyline (ground truth), as often;
- ``contact/estimate`` (``Ellipsoids3D``, 3 sigma), ``contact/truth``,
  ``contact/error`` [m], ``tension/truth``: as often, once there is an
  estimate;
- ``steps``: a ``TextLog`` line when each step starts and ends, and the
  scalar ``steps/index`` (the step's number, -1 after the last).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from tautwire.errors import TautwireError
from tautwire.robot import ARMS
from tautwire.sim.ground_truth import GroundTruth
from tautwire.sim.model_overlay import (
    FIXTURE_COLOURS,
    SIGMAS,
    covariance_ellipsoid,
    fixture_type,
    model_shapes,
)
from tautwire.sim.world import SimWorld
from tautwire.tasks import StepReport, TickRecord

#: The timeline every entry is logged on.
TIMELINE = "sim_time"
#: The recording's application id.
APPLICATION_ID = "tautwire"


class RerunUnavailableError(TautwireError):
    """The optional ``rerun-sdk`` package is not installed."""


def _rgba(colour: tuple[float, ...]) -> list[int]:
    return [round(255 * c) for c in colour]


def _xyzw(q_wxyz: Any) -> list[float]:
    w, x, y, z = (float(v) for v in q_wxyz)
    return [x, y, z, w]


class RerunRecorder:
    """Writes a run to a ``.rrd`` file as it happens.

    Args:
        path: The recording file (overwritten).
        cable: The cable whose truth is recorded (default: the world's first).
        model_every: Simulated time [s] between snapshots of the model
            graph and the true cable (the wrench is logged every period).
        name: The recording's name, shown by the viewer.

    Raises:
        RerunUnavailableError: without ``rerun-sdk``.
    """

    def __init__(
        self,
        path: str | Path,
        cable: str | None = None,
        model_every: float = 0.04,
        name: str = "",
    ) -> None:
        try:
            import rerun as rr
        except ImportError as exc:
            raise RerunUnavailableError(
                "recording to Rerun needs rerun-sdk: pip install 'tautwire[rerun]'"
            ) from exc
        self._rr = rr
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.cable = cable
        self.model_every = float(model_every)
        self._stream: Any = rr.RecordingStream(APPLICATION_ID)
        self._stream.save(str(self.path))
        if name:
            self._stream.send_recording_name(name)
        self._truth: GroundTruth | None = None
        self._types: dict[str, str] = {}
        self._next_model = 0.0
        self._step = 0
        self._step_open = False
        self.ticks = 0
        self.snapshots = 0
        self.estimates = 0
        self.closed = False

    # ----------------------------------------------------------------- hooks
    def attach(self, world: SimWorld) -> None:
        """The runner's ``on_world`` hook: log the board (static)."""
        rr, s = self._rr, self._stream
        fixtures = world.spec.fixtures
        self._types = {f.name: fixture_type(f) for f in fixtures}
        if self.cable is None and world.spec.cables:
            self.cable = world.spec.cables[0].name
        if fixtures:
            s.log(
                "board/fixtures",
                rr.Points3D(
                    [np.asarray(f.position, dtype=float) for f in fixtures],
                    radii=0.008,
                    colors=[_rgba(FIXTURE_COLOURS[self._types[f.name]]) for f in fixtures],
                    labels=[f"{f.name} ({self._types[f.name]})" for f in fixtures],
                    show_labels=True,
                ),
                static=True,
            )
        s.log("world", rr.ViewCoordinates.RIGHT_HAND_Z_UP, static=True)
        for arm in ARMS:  # the tool frame's axes, 5 cm long
            s.log(f"grippers/{arm}", rr.TransformAxes3D(axis_length=0.05), static=True)

    def keep_truth(self, truth: GroundTruth) -> None:
        """The runner's ``on_truth`` hook (the truth is recorded, never fed back)."""
        self._truth = truth

    def tick(self, rec: TickRecord) -> None:
        """The runner's ``on_tick`` hook: log one control period."""
        rr, s = self._rr, self._stream
        obs = rec.observation
        t = float(obs.time)
        s.set_time(TIMELINE, duration=t)
        if not self._step_open:
            self._step_open = True
            s.log("steps", rr.TextLog(f"step {self._step + 1}: {rec.primitive.letter} starts"))
            s.log("steps/index", rr.Scalars(float(self._step + 1)))
        for w in obs.wrenches:
            prefix = "wrench" if len(obs.wrenches) == 1 else f"wrench/{w.arm}"
            for axis, value in zip("xyz", w.force, strict=True):
                s.log(f"{prefix}/force/{axis}", rr.Scalars(float(value)))
            s.log(f"{prefix}/force/norm", rr.Scalars(float(np.linalg.norm(w.force))))
            for axis, value in zip("xyz", w.torque, strict=True):
                s.log(f"{prefix}/torque/{axis}", rr.Scalars(float(value)))
        est = rec.context.estimator
        if est.state is not None:
            s.log("tension/model", rr.Scalars(float(est.state.tension)))
        if rec.context.tension is not None:
            s.log("tension/set_point", rr.Scalars(float(rec.context.tension)))
        for arm in ARMS:
            g = obs.gripper(arm)
            s.log(
                f"grippers/{arm}",
                rr.Transform3D(
                    translation=np.asarray(g.position, dtype=float),
                    quaternion=rr.Quaternion(xyzw=_xyzw(g.orientation)),
                ),
            )
        self.ticks += 1
        if t >= self._next_model - 1e-9:  # on the grid of model_every, as time rounds
            while self._next_model <= t + 1e-9:
                self._next_model += self.model_every
            self._snapshot(rec)

    def _contact(self, rec: TickRecord) -> None:
        rr, s = self._rr, self._stream
        ce = rec.context.estimator.contact_estimate()
        if ce is None:
            return
        e = covariance_ellipsoid(ce.position, ce.covariance, (0.95, 0.15, 0.15, 1.0), "estimate")
        s.log(
            "contact/estimate",
            rr.Ellipsoids3D(
                centers=[e.centre],
                half_sizes=[np.maximum(e.half_sizes, 1e-5)],
                quaternions=[rr.Quaternion(xyzw=_rotation_xyzw(e.rotation))],
                colors=[_rgba(e.colour)],
                labels=[f"contact estimate ({SIGMAS:g} sigma)"],
            ),
        )
        self.estimates += 1
        span = None
        if self._truth is not None and self.cable is not None:
            span = self._truth.span(self.cable, rec.context.arm)
        if span is None or span.contact is None:
            return
        truth = np.asarray(span.contact, dtype=float)
        s.log(
            "contact/truth",
            rr.Points3D([truth], radii=0.003, colors=[[255, 255, 255]], labels=[str(span.fixture)]),
        )
        s.log("contact/error", rr.Scalars(float(np.linalg.norm(ce.position - truth))))
        s.log("tension/truth", rr.Scalars(float(span.tension)))

    def _snapshot(self, rec: TickRecord) -> None:
        rr, s = self._rr, self._stream
        self._contact(rec)
        shapes = model_shapes(rec.context.graph, self._types)
        s.log(
            "model/points",
            rr.Points3D(
                shapes.points,
                radii=0.005,
                colors=[_rgba(c) for c in shapes.colours],
                labels=list(shapes.labels),
            ),
        )
        s.log(
            "model/edges", rr.LineStrips3D([shapes.points], colors=[[255, 255, 255]], radii=0.0015)
        )
        if shapes.ellipsoids:
            s.log(
                "model/uncertainty",
                rr.Ellipsoids3D(
                    centers=[e.centre for e in shapes.ellipsoids],
                    half_sizes=[np.maximum(e.half_sizes, 1e-5) for e in shapes.ellipsoids],
                    quaternions=[
                        rr.Quaternion(xyzw=_rotation_xyzw(e.rotation)) for e in shapes.ellipsoids
                    ],
                    colors=[_rgba(e.colour) for e in shapes.ellipsoids],
                    labels=[e.label for e in shapes.ellipsoids],
                ),
            )
        else:
            s.log("model/uncertainty", rr.Clear(recursive=False))
        if self._truth is not None and self.cable is not None:
            s.log(
                "truth/cable",
                rr.LineStrips3D(
                    [self._truth.polyline(self.cable)], colors=[[242, 140, 25]], radii=0.0025
                ),
            )
        self.snapshots += 1

    def step(self, index: int, report: StepReport) -> None:
        """The runner's ``on_step`` hook: log the step's end."""
        rr, s = self._rr, self._stream
        text = f"step {index + 1}: {report.letter} {report.outcome}"
        if report.cause:
            text += f" ({report.cause}: {report.detail})"
        level = "INFO" if report.success else "WARN"
        s.log("steps", rr.TextLog(text, level=level))
        self._step = index + 1
        self._step_open = False
        s.log("steps/index", rr.Scalars(-1.0))

    def close(self) -> Path:
        """Flush and close the file (idempotent); return its path."""
        if not self.closed:
            self._stream.flush()
            self._stream.disconnect()
            self.closed = True
        return self.path


def _rotation_xyzw(rotation: Any) -> list[float]:
    """The unit quaternion [x, y, z, w] of a rotation matrix."""
    from scipy.spatial.transform import Rotation

    q: list[float] = Rotation.from_matrix(np.asarray(rotation, dtype=float)).as_quat().tolist()
    return q
