"""Batch least squares of a contact point (equ:ls_observation_model, equ:genneral_leastSquares).

Stacking G_j p_g_j = G_j p_c over samples j gives the standard observation
model y = A phi + e with phi = p_c. tautwire normalises the force direction
(see :mod:`tautwire.estimation.contact_observation`) and weights sample j by
1 / r_j^2, the inverse variance of its line's offset, so the normal
equations are

    A = sum_j (I - f_hat_j f_hat_j^T) / r_j^2,      # (3, 3) [1/m^2]
    b = sum_j (I - f_hat_j f_hat_j^T) p_g_j / r_j^2,  # (3,)  [1/m]
    p_c = A^-1 b,   Cov(p_c) = A^-1  [m^2].

With sigma_p = 0 the weight of sample j is |f_j|^2 / (d_j sigma_f)^2, so
A = sum_j G_j / (d_j sigma_f)^2: the paper's unnormalised G_j with the noise
scaled consistently. An optional Gaussian prior N(m0, P0) adds P0^-1 to A and
P0^-1 m0 to b (a Kalman filter with process noise 0 started from that prior
gives the same answer). With only parallel forces A has rank 2: the contact is
only known to lie on a line, and without a prior this raises
:class:`~tautwire.errors.InvalidArgumentError` instead of returning NaN.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from tautwire.errors import InvalidArgumentError
from tautwire.estimation.contact_observation import MIN_DISTANCE
from tautwire.estimation.force_line import line_offset, line_offset_variance

FloatArray = NDArray[np.float64]

#: Eigenvalues of A below this fraction of the largest count as zero (rank).
RANK_TOLERANCE = 1e-9
#: Default smallest RMS spread [m] of the gripper positions of a batch without a prior.
MIN_BASELINE = 1e-3


class NormalEquations(NamedTuple):
    """The weighted normal equations A p_c = b of the stacked observations.

    Attributes:
        A: Information matrix [1/m^2].  # (3, 3)
        b: Information vector [1/m].  # (3,)
    """

    A: FloatArray
    b: FloatArray


class ContactPointLeastSquares(NamedTuple):
    """Result of :func:`contact_point_least_squares`.

    Attributes:
        estimate: Contact position p_c [m], world frame.  # (3,)
        covariance: Cov(p_c) = A^-1 [m^2] from the force noise.  # (3, 3)
        rank: Rank of the data's information matrix (3 when the lines fix
            a point, 2 when all forces are parallel).
        condition: Condition number of A (largest / smallest eigenvalue).
        spread: Angular spread [rad] of the force directions, 2 asin(sqrt(
            lambda_min(mean_j (I - f_hat_j f_hat_j^T)))); for two samples it
            is the angle between their lines.
        chi2: Weighted residual sum of squares, sum_j |H_j (p_g_j - p_c)|^2
            / r_j^2 (about 2 N - 3 when the noise model is right).
        residual_rms: Root mean square distance [m] of p_c from the lines.
        distances: d_j [m] used in the weights (before the floor).  # (N,)
        ahead: Median distance [m] of p_c in front of the grippers along the
            forces, median_j f_hat_j . (p_c - p_j): a contact the cable pulls
            towards lies well ahead (> 0); lines that meet at or behind the
            gripper do not describe a contact.
    """

    estimate: FloatArray
    covariance: FloatArray
    rank: int
    condition: float
    spread: float
    chi2: float
    residual_rms: float
    distances: FloatArray
    ahead: float = math.inf


def _as_samples(p_grippers: ArrayLike, forces: ArrayLike) -> tuple[FloatArray, FloatArray]:
    p = np.asarray(p_grippers, dtype=float)
    f = np.asarray(forces, dtype=float)
    if p.ndim != 2 or p.shape[1] != 3 or f.shape != p.shape:
        raise InvalidArgumentError(
            f"p_grippers and forces must both have shape (N, 3), got {p.shape} and {f.shape}"
        )
    if p.shape[0] == 0:
        raise InvalidArgumentError("at least one sample is needed, got 0")
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(f))):
        raise InvalidArgumentError("p_grippers and forces must be finite (no NaN or inf)")
    return p, f


def _unit_directions(forces: FloatArray) -> tuple[FloatArray, FloatArray]:
    norms = np.linalg.norm(forces, axis=1)
    if np.any(norms <= 1e-12):
        raise InvalidArgumentError("every force must be non-zero to define a direction")
    return forces / norms[:, None], norms


def line_variances(
    force_norms: FloatArray,
    distances: FloatArray,
    force_noise: float,
    position_noise: float = 0.0,
    min_distance: float = MIN_DISTANCE,
) -> FloatArray:
    """Vectorised :func:`~tautwire.estimation.contact_observation.line_noise_variance`.

    Args:
        force_norms: |f_j| [N].  # (N,)
        distances: d_j [m].  # (N,)
        force_noise: sigma_f [N].
        position_noise: sigma_p [m].
        min_distance: Floor [m] of d_j.

    Returns:
        r_j^2 [m^2].  # (N,)
    """
    r = np.maximum(distances, min_distance) * force_noise / force_norms
    return np.asarray(r * r + position_noise * position_noise, dtype=float)


def contact_normal_equations(
    p_grippers: ArrayLike, directions: ArrayLike, variances: ArrayLike
) -> NormalEquations:
    """Build the weighted normal equations of the stacked observations.

    Args:
        p_grippers: Gripper positions p_g_j [m].  # (N, 3)
        directions: Unit force directions f_hat_j.  # (N, 3)
        variances: r_j^2 [m^2], noise of line j per normal axis.  # (N,)

    Returns:
        A = sum_j (I - f_hat_j f_hat_j^T) / r_j^2 and
        b = sum_j (I - f_hat_j f_hat_j^T) p_g_j / r_j^2.
    """
    p = np.asarray(p_grippers, dtype=float)
    u = np.asarray(directions, dtype=float)
    w = 1.0 / np.asarray(variances, dtype=float)  # (N,)
    wu = u * w[:, None]  # (N, 3)
    A = float(w.sum()) * np.eye(3) - u.T @ wu  # (3, 3)
    b = w @ p - wu.T @ np.einsum("ij,ij->i", u, p)  # (3,)
    return NormalEquations(A, b)


def direction_spread(directions: ArrayLike) -> float:
    """Angular spread [rad] of a set of unit directions (see ``spread`` above)."""
    u = np.asarray(directions, dtype=float)
    mean_projector = np.eye(3) - (u.T @ u) / u.shape[0]  # (3, 3)
    lam = float(np.linalg.eigvalsh(mean_projector)[0])
    return 2.0 * math.asin(math.sqrt(min(max(lam, 0.0), 1.0)))


def _solve(
    eq: NormalEquations, prior_mean: FloatArray | None, prior_information: FloatArray | None
) -> tuple[FloatArray, FloatArray, int, float]:
    lam = np.linalg.eigvalsh(eq.A)
    lam_max = float(lam[-1])
    rank = int(np.sum(lam > RANK_TOLERANCE * lam_max)) if lam_max > 0.0 else 0
    A, b = eq.A, eq.b
    if prior_information is not None and prior_mean is not None:
        A = A + prior_information
        b = b + prior_information @ prior_mean
    elif rank < 3:
        raise InvalidArgumentError(
            f"the forces are parallel (information rank {rank} of 3): the contact is only "
            "known to lie on a line; move the gripper so that the cable direction changes, "
            "or pass prior_mean and prior_covariance"
        )
    lam_all = np.linalg.eigvalsh(A)
    condition = float(lam_all[-1] / lam_all[0]) if lam_all[0] > 0.0 else math.inf
    covariance = np.linalg.inv(A)
    covariance = 0.5 * (covariance + covariance.T)
    estimate = covariance @ b
    return estimate, covariance, rank, condition


def contact_point_least_squares(
    p_grippers: ArrayLike,
    forces: ArrayLike,
    force_noise: float = 0.05,
    distances: ArrayLike | None = None,
    prior_mean: ArrayLike | None = None,
    prior_covariance: ArrayLike | None = None,
    position_noise: float = 0.0,
    min_distance: float = MIN_DISTANCE,
    iterations: int = 2,
    torques: ArrayLike | None = None,
    torque_noise: float = 0.0,
    offset_variances: ArrayLike | None = None,
    min_baseline: float = MIN_BASELINE,
) -> ContactPointLeastSquares:
    """Estimate the contact point from a batch of samples (equ:ls_observation_model).

    With ``torques``, each line passes through the point of the whole
    wrench's line of action nearest the gripper
    (:mod:`~tautwire.estimation.force_line`), not through the gripper: where
    the cable leaves the fingers no longer biases the estimate.

    Args:
        p_grippers: Gripper positions p_g_j [m], world frame.  # (N, 3)
        forces: Forces f_j [N] the cable exerts on the gripper (weight
            compensated if wanted), world frame.  # (N, 3)
        force_noise: sigma_f [N], std per axis of the force sensor.
        distances: d_j [m] (a scalar, e.g. a known edge length, or one per
            sample) for the noise r_j; None estimates them: a first solve
            with equal d_j, then ``iterations - 1`` re-solves with d_j the
            distance from each gripper position to the previous estimate.
        prior_mean: Mean [m] of an optional Gaussian prior on p_c.  # (3,)
        prior_covariance: Its covariance [m^2].  # (3, 3)
        position_noise: sigma_p [m], gripper position noise per axis.
        min_distance: Floor [m] of d_j.
        iterations: Number of solves when ``distances`` is None (>= 1).
        torques: Torques tau_j [N m] about the gripper, world frame, measured
            with ``forces`` (raw: the line of action is the raw force's);
            None assumes lines through the gripper.  # (N, 3)
        torque_noise: sigma_tau [N m], std per axis of the torque sensor.
        offset_variances: Further variance [m^2] of each line's position per
            normal axis (e.g. of line offsets computed by the caller).  # (N,)
        min_baseline: Without a prior, the gripper positions (or line points)
            must spread at least this far [m] (RMS about their mean): lines
            through one point meet at that point whatever the contact is.

    Returns:
        The estimate with its covariance, rank, conditioning and residuals.

    Raises:
        InvalidArgumentError: Bad shapes or values, parallel forces (rank 2)
            or a gripper that did not move (baseline below ``min_baseline``)
            without a prior.
    """
    p, f = _as_samples(p_grippers, forces)
    n = p.shape[0]
    extra = np.zeros(n)
    if offset_variances is not None:
        extra = np.broadcast_to(np.asarray(offset_variances, dtype=float), (n,)).copy()
        if np.any(~np.isfinite(extra)) or np.any(extra < 0.0):
            raise InvalidArgumentError("offset_variances must be finite and >= 0 m^2")
    if torques is not None:
        tau = np.asarray(torques, dtype=float)
        if tau.shape != p.shape or not np.all(np.isfinite(tau)):
            raise InvalidArgumentError(
                f"torques must be finite with shape {p.shape}, got shape {tau.shape}"
            )
        if torque_noise < 0.0 or not math.isfinite(torque_noise):
            raise InvalidArgumentError(f"torque_noise must be >= 0 N m, got {torque_noise}")
        offsets = np.array([line_offset(fj, tj) for fj, tj in zip(f, tau, strict=True)])
        p = p + offsets
        extra = extra + np.array(
            [
                line_offset_variance(
                    float(np.linalg.norm(fj)), float(np.linalg.norm(oj)), force_noise, torque_noise
                )
                for fj, oj in zip(f, offsets, strict=True)
            ]
        )
    if not (force_noise > 0.0 and math.isfinite(force_noise)):
        raise InvalidArgumentError(f"force_noise must be > 0 N, got {force_noise}")
    if position_noise < 0.0 or not math.isfinite(position_noise):
        raise InvalidArgumentError(f"position_noise must be >= 0 m, got {position_noise}")
    if iterations < 1:
        raise InvalidArgumentError(f"iterations must be >= 1, got {iterations}")
    if (prior_mean is None) != (prior_covariance is None):
        raise InvalidArgumentError("give both prior_mean and prior_covariance, or neither")
    m0: FloatArray | None = None
    info0: FloatArray | None = None
    if prior_mean is not None and prior_covariance is not None:
        m0 = np.asarray(prior_mean, dtype=float).reshape(3)
        P0 = np.asarray(prior_covariance, dtype=float).reshape(3, 3)
        try:
            info0 = np.linalg.inv(P0)
        except np.linalg.LinAlgError as exc:
            raise InvalidArgumentError("prior_covariance must be invertible") from exc
    u, norms = _unit_directions(f)
    if m0 is None:
        baseline = float(np.sqrt(np.mean(np.sum((p - p.mean(axis=0)) ** 2, axis=1))))
        if baseline < min_baseline:
            raise InvalidArgumentError(
                f"the gripper hardly moved ({baseline * 1e3:.2f} mm RMS, at least "
                f"{min_baseline * 1e3:g} mm needed): lines through one point meet there whatever "
                "the contact is; move the gripper across the cable, or pass prior_mean and "
                "prior_covariance"
            )
    if distances is None:
        d = np.ones(n)
        passes = iterations
    else:
        d = np.broadcast_to(np.asarray(distances, dtype=float), (n,)).copy()
        if np.any(~np.isfinite(d)) or np.any(d < 0.0):
            raise InvalidArgumentError("distances must be finite and >= 0 m")
        passes = 1
    for k in range(passes):
        variances = line_variances(norms, d, force_noise, position_noise, min_distance) + extra
        eq = contact_normal_equations(p, u, variances)
        estimate, covariance, rank, condition = _solve(eq, m0, info0)
        if distances is None and k + 1 < passes:
            d = np.linalg.norm(p - estimate, axis=1)
    offsets = p - estimate  # (N, 3)
    perp = offsets - u * np.einsum("ij,ij->i", u, offsets)[:, None]  # (N, 3)
    perp_sq = np.einsum("ij,ij->i", perp, perp)  # (N,)
    return ContactPointLeastSquares(
        estimate=estimate,
        covariance=covariance,
        rank=rank,
        condition=condition,
        spread=direction_spread(u),
        chi2=float(np.sum(perp_sq / variances)),
        residual_rms=float(math.sqrt(np.mean(perp_sq))),
        distances=d,
        ahead=float(np.median(np.einsum("ij,ij->i", u, -offsets))),
    )
