"""Offline estimation of a recorded force log (``tautwire estimate``).

The contact filter (:class:`~tautwire.estimation.ContactPointFilter`) runs
over the log row by row, exactly as it would online; its estimate and std
after each row form the history. Stiffness: the rows are split into contact
intervals at the declared changes (an interval starts at the first gated
sample of a change); within each interval the span length is the distance
from the gripper to that interval's *final* contact estimate (offline, the
best one available), and an :class:`~tautwire.estimation.ElasticityEstimator`
fits k from the (weight-compensated) tension and that length. Its excitation
guard skips rows where the length hardly changes, so a pure circle around the
contact yields no stiffness (None) rather than a fit to noise. The reported
stiffness is that of the last interval whose estimate is known to 10 %.

The history is kept as arrays (:class:`ContactHistory`: t, estimate and std
per row, 57 bytes a row) and its per-row entries are made only when read: a
list of one ``HistoryEntry`` per row took about 376 bytes a row, 376 MB for
a 1e6-row log (bench/force_log.py).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import NamedTuple, overload

import numpy as np
from numpy.typing import NDArray

from tautwire.estimation.contact_point_filter import DEFAULT_PROCESS_NOISE, ContactPointFilter
from tautwire.estimation.elasticity_estimator import ElasticityEstimator
from tautwire.estimation.force_log import ForceLog
from tautwire.model.tension import GRAVITY

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]

#: Relative std of k below which an interval's stiffness is reported.
STIFFNESS_RELATIVE_STD = 0.1


class HistoryEntry(NamedTuple):
    """The filter's state after one data row.

    Attributes:
        t: Time [s] of the row.
        contact: Contact estimate [m], or None before the first one.  # (3,)
        std: sqrt(diag(P)) [m], or None.  # (3,)
    """

    t: float
    contact: FloatArray | None
    std: FloatArray | None


class ContactHistory(Sequence[HistoryEntry]):
    """The filter's state after each data row, as arrays; a sequence of :class:`HistoryEntry`.

    ``history[i]`` makes row i's entry (with copies of its rows), as the list
    of entries did before.

    Args:
        t: Time [s] of each row.  # (N,)
        contact: Contact estimate [m] after each row (ignored where not
            ``known``).  # (N, 3)
        std: sqrt(diag(P)) [m] after each row.  # (N, 3)
        known: Whether there was an estimate after the row.  # (N,)
    """

    def __init__(self, t: FloatArray, contact: FloatArray, std: FloatArray, known: BoolArray):
        n = t.shape[0]
        if contact.shape != (n, 3) or std.shape != (n, 3) or known.shape != (n,):
            raise ValueError(
                f"history arrays disagree: t {t.shape}, contact {contact.shape}, "
                f"std {std.shape}, known {known.shape}"
            )
        self.t = t
        self.contact = contact
        self.std = std
        self.known = known

    def __len__(self) -> int:
        return int(self.t.shape[0])

    def _entry(self, i: int) -> HistoryEntry:
        if not self.known[i]:
            return HistoryEntry(float(self.t[i]), None, None)
        return HistoryEntry(float(self.t[i]), self.contact[i].copy(), self.std[i].copy())

    @overload
    def __getitem__(self, index: int) -> HistoryEntry: ...

    @overload
    def __getitem__(self, index: slice) -> list[HistoryEntry]: ...

    def __getitem__(self, index: int | slice) -> HistoryEntry | list[HistoryEntry]:
        if isinstance(index, slice):
            return [self._entry(i) for i in range(*index.indices(len(self)))]
        i = int(index)
        if not -len(self) <= i < len(self):
            raise IndexError(f"history index {i} out of range for {len(self)} rows")
        return self._entry(i + len(self) if i < 0 else i)

    def __iter__(self) -> Iterator[HistoryEntry]:
        return (self._entry(i) for i in range(len(self)))


class OfflineEstimate(NamedTuple):
    """Result of :func:`estimate_force_log`.

    Attributes:
        contact: Final contact estimate [m], or None if there never was one.  # (3,)
        covariance: Its covariance [m^2], or None.  # (3, 3)
        history: One entry per data row, in order (a sequence).
        changes: Data-row indices (0-based) where a new contact was declared.
        stiffness: k [N/m] of the last sufficiently excited contact interval,
            or None.
        stiffness_std: Its std [N/m], or None.
    """

    contact: FloatArray | None
    covariance: FloatArray | None
    history: ContactHistory
    changes: list[int]
    stiffness: float | None
    stiffness_std: float | None


def estimate_force_log(
    log: ForceLog,
    force_noise: float = 0.05,
    process_noise: float = DEFAULT_PROCESS_NOISE,
    mass_per_length: float = 0.0,
    edge_length: float | None = None,
    torque_noise: float = 0.002,
) -> OfflineEstimate:
    """Estimate the contact point(s) and the stiffness of a force log.

    When the log has torques (``tx,ty,tz``, about the logged gripper
    position), each sample's line runs through the whole wrench's line of
    action (:mod:`~tautwire.estimation.force_line`): where the cable left
    the fingers does not bias the contact.

    Args:
        log: A validated force log.
        force_noise: sigma_f [N], force sensor noise, std per axis.
        torque_noise: sigma_tau [N m], torque sensor noise, std per axis
            (used when the log has torques).
        process_noise: q [m^2 per step], the filter's process noise.
        mass_per_length: rho [kg/m] for weight compensation (0 = off).
        edge_length: Known gripper-contact length [m], or None.

    Returns:
        The final contact, its covariance, the per-row history, the change
        indices and the stiffness.
    """
    flt = ContactPointFilter(
        force_noise=force_noise,
        process_noise=process_noise,
        mass_per_length=mass_per_length,
        edge_length=edge_length,
        torque_noise=torque_noise,
    )
    n = len(log)
    contact = np.full((n, 3), np.nan)
    std = np.full((n, 3), np.nan)
    known = np.zeros(n, dtype=bool)
    update = flt.update
    if log.torque is None:
        for i, (p, f) in enumerate(zip(log.p_gripper, log.f_sens, strict=True)):
            r = update(p, f)
            if r.estimate is not None:
                contact[i], std[i], known[i] = r.estimate, r.std, True
    else:
        rows = zip(log.p_gripper, log.f_sens, log.torque, strict=True)
        for i, (p, f, tau) in enumerate(rows):
            r = update(p, f, torque=tau)
            if r.estimate is not None:
                contact[i], std[i], known[i] = r.estimate, r.std, True
    history = ContactHistory(np.array(log.t, dtype=float), contact, std, known)
    window = flt.detector.window
    starts = [0] + [max(c - window + 1, 0) for c in flt.changes]
    ends = [*starts[1:], n]
    stiffness: float | None = None
    stiffness_std: float | None = None
    for start, end in zip(starts, ends, strict=True):
        if end - start < 3 or not known[end - 1]:
            continue
        final = contact[end - 1]
        lengths = np.linalg.norm(log.p_gripper[start:end] - final, axis=1)
        f_chord = log.f_sens[start:end]
        if mass_per_length > 0.0:
            # compensate_weight: f - m_g g with m_g = rho d / 2 (eq:mass), per row
            m_g = (0.5 * mass_per_length) * np.maximum(lengths, 0.0)
            f_chord = f_chord - m_g[:, None] * GRAVITY
        est = ElasticityEstimator(force_noise=force_noise)
        for tension, length in zip(
            np.linalg.norm(f_chord, axis=1).tolist(), lengths.tolist(), strict=True
        ):
            est.update(tension, length)
        if est.is_ready(STIFFNESS_RELATIVE_STD):
            stiffness, stiffness_std = est.k_hat, est.std
    final_contact = flt.estimate
    covariance = flt.P.copy() if flt.running else None
    return OfflineEstimate(
        final_contact, covariance, history, list(flt.changes), stiffness, stiffness_std
    )
