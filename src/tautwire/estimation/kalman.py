"""Textbook Kalman predict and update (equ:kalmanUpdate), pure functions.

Notation of filterpy / Labbe, "Kalman and Bayesian Filters in Python": state x,
covariance P, transition F, process noise Q, observation H, measurement noise
R. These are the reference that :class:`~tautwire.estimation.ContactPointFilter`
(an inlined, allocation-light form of the same equations) is tested against.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


class KalmanUpdate(NamedTuple):
    """Result of :func:`kalman_update`.

    Attributes:
        x: Posterior state.  # (n,)
        P: Posterior covariance.  # (n, n)
        y: Innovation z - H x^-.  # (m,)
        S: Innovation covariance H P^- H' + R.  # (m, m)
        K: Kalman gain.  # (n, m)
        nis: Normalised innovation squared y' S^-1 y.
    """

    x: FloatArray
    P: FloatArray
    y: FloatArray
    S: FloatArray
    K: FloatArray
    nis: float


def kalman_predict(
    x: ArrayLike, P: ArrayLike, F: ArrayLike, Q: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    """Predict step; returns (x^-, P^-)."""
    x_ = np.asarray(x, dtype=float)
    F_ = np.asarray(F, dtype=float)
    x_prior = F_ @ x_  # x = F x
    P_prior = F_ @ np.asarray(P, dtype=float) @ F_.T + np.asarray(Q, dtype=float)  # P = F P F' + Q
    return x_prior, P_prior


def kalman_update(
    x: ArrayLike, P: ArrayLike, z: ArrayLike, H: ArrayLike, R: ArrayLike
) -> KalmanUpdate:
    """Update step with the Joseph-form covariance (as filterpy's ``update``)."""
    x_ = np.asarray(x, dtype=float)
    P_ = np.asarray(P, dtype=float)
    H_ = np.asarray(H, dtype=float)
    R_ = np.asarray(R, dtype=float)
    y = np.asarray(z, dtype=float) - H_ @ x_  # y = z - H x
    S = H_ @ P_ @ H_.T + R_  # S = H P H' + R
    SI = np.linalg.inv(S)
    K = P_ @ H_.T @ SI  # K = P H' S^-1
    x_post = x_ + K @ y  # x = x + K y
    I_KH = np.eye(x_.shape[0]) - K @ H_
    P_post = I_KH @ P_ @ I_KH.T + K @ R_ @ K.T  # P = (I - K H) P (I - K H)' + K R K'
    nis = float(y @ SI @ y)  # NIS = y' S^-1 y
    return KalmanUpdate(x_post, P_post, y, S, K, nis)
