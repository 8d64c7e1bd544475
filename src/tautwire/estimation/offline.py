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
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from tautwire.estimation.contact_point_filter import DEFAULT_PROCESS_NOISE, ContactPointFilter
from tautwire.estimation.elasticity_estimator import ElasticityEstimator
from tautwire.estimation.force_log import ForceLog
from tautwire.estimation.weight_compensation import compensate_weight

FloatArray = NDArray[np.float64]

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


class OfflineEstimate(NamedTuple):
    """Result of :func:`estimate_force_log`.

    Attributes:
        contact: Final contact estimate [m], or None if there never was one.  # (3,)
        covariance: Its covariance [m^2], or None.  # (3, 3)
        history: One entry per data row, in order.
        changes: Data-row indices (0-based) where a new contact was declared.
        stiffness: k [N/m] of the last sufficiently excited contact interval,
            or None.
        stiffness_std: Its std [N/m], or None.
    """

    contact: FloatArray | None
    covariance: FloatArray | None
    history: list[HistoryEntry]
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
    history: list[HistoryEntry] = []
    torques = log.torque if log.torque is not None else [None] * len(log)
    for t, p, f, tau in zip(log.t, log.p_gripper, log.f_sens, torques, strict=True):
        r = flt.update(p, f, torque=tau)
        history.append(HistoryEntry(float(t), r.estimate, r.std))
    window = flt.detector.window
    starts = [0] + [max(c - window + 1, 0) for c in flt.changes]
    ends = [*starts[1:], len(log)]
    stiffness: float | None = None
    stiffness_std: float | None = None
    for start, end in zip(starts, ends, strict=True):
        final = history[end - 1].contact
        if final is None or end - start < 3:
            continue
        est = ElasticityEstimator(force_noise=force_noise)
        for p, f in zip(log.p_gripper[start:end], log.f_sens[start:end], strict=True):
            length = float(np.linalg.norm(p - final))
            f_chord = compensate_weight(f, length, mass_per_length)
            est.update(float(np.linalg.norm(f_chord)), length)
        if est.is_ready(STIFFNESS_RELATIVE_STD):
            stiffness, stiffness_std = est.k_hat, est.std
    final_contact = flt.estimate
    covariance = flt.P.copy() if flt.running else None
    return OfflineEstimate(
        final_contact, covariance, history, list(flt.changes), stiffness, stiffness_std
    )
